// Long recordings aligned a window at a time (align/LongAlignment.h), on the ten GRID demo clips' sound back to back (29.6 s, 60 words)
// with 10 s windows, so that the windowing runs as it does on an hour:
//  - the windows' alignment places every word where one Viterbi pass over the whole recording
//    does (within 20 ms for at least 95 % of the word boundaries) and within 40 ms of GRID's
//    reference timings as often; tiers tile the recording;
//  - with subtitle cues (late by 0.7 s, as subtitles often are) the same; cues whose words do
//    not add up to the transcript are ignored;
//  - a stretch of 25 s of noise without words in the middle changes nothing around it;
//  - a transcript with words the recording does not speak is an Error naming where they stop
//    fitting; cancel throws Canceled.
#include "align/AcousticModel.h"
#include "align/ForcedAligner.h"
#include "align/Lexicon.h"
#include "align/LongAlignment.h"
#include "io/AudioDecoder.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo/media/";
const char *const kClips[] = {"bbaf2n", "bgin3a", "bwbg8n", "lbwy6n", "lrik4p",
                              "pbav2n", "pgwe6n", "pwbk1s", "sbwo1s", "srbu6n"};

struct Recording
{
    std::vector<float> samples;
    std::vector<std::string> words;
    std::vector<Interval> reference; // GRID's word timings, shifted into the recording
    std::vector<Interval> cues;      // one per clip
    double noiseStart = -1.0;        // seconds, where the noise begins
};

// The demo clips back to back; `noiseAfter` >= 0 puts 25 s of faint noise after that clip.
Recording demoRecording(int noiseAfter = -1)
{
    Recording r;
    std::mt19937 random(7);
    std::normal_distribution<float> noise(0.0f, 3e-4f);
    for (int c = 0; c < 10; ++c) {
        const AudioBuffer audio = AudioDecoder::decode(kDemo + kClips[c] + ".mpg", 16000);
        const double offset = double(r.samples.size()) / 16000.0;
        const Transcript t = readTranscript(kDemo + kClips[c] + ".align");
        std::string cueText;
        for (const Interval &i : t.timing.intervals)
            if (!PhoneSet::isSilence(i.label)) {
                r.words.push_back(i.label);
                r.reference.push_back(Interval{i.start + offset, i.end + offset, i.label, false});
                cueText += (cueText.empty() ? "" : " ") + i.label;
            }
        r.cues.push_back(Interval{offset + 0.7, offset + audio.duration() + 0.7, cueText, false});
        r.samples.insert(r.samples.end(), audio.samples.begin(), audio.samples.end());
        if (c == noiseAfter) {
            r.noiseStart = double(r.samples.size()) / 16000.0;
            for (int k = 0; k < 25 * 16000; ++k)
                r.samples.push_back(noise(random));
        }
    }
    return r;
}

std::vector<Interval> spoken(const Tier &words)
{
    std::vector<Interval> out;
    for (const Interval &i : words.intervals)
        if (!PhoneSet::isSilence(i.label))
            out.push_back(i);
    return out;
}

// Share of the word boundaries (starts and ends) of `a` within `tolerance` of those of `b`.
double agreement(const std::vector<Interval> &a, const std::vector<Interval> &b, double tolerance)
{
    if (a.size() != b.size() || a.empty())
        return 0.0;
    int ok = 0;
    for (size_t i = 0; i < a.size(); ++i)
        ok += (std::abs(a[i].start - b[i].start) <= tolerance) + (std::abs(a[i].end - b[i].end) <= tolerance);
    return ok / (2.0 * double(a.size()));
}

void checkTiles(const Tier &tier, double end)
{
    QVERIFY(!tier.intervals.empty());
    QCOMPARE(tier.intervals.front().start, 0.0);
    for (size_t i = 1; i < tier.intervals.size(); ++i) {
        QCOMPARE(tier.intervals[i].start, tier.intervals[i - 1].end);
        QVERIFY(tier.intervals[i].end > tier.intervals[i].start);
    }
    QVERIFY(std::abs(tier.intervals.back().end - end) < 1e-6);
}

LongAlignmentOptions tenSecondWindows()
{
    LongAlignmentOptions o;
    o.windowSeconds = 10.0;
    o.guardSeconds = 3.0;
    return o;
}

const AcousticModel &model()
{
    static const AcousticModel m = AcousticModel::load(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner");
    return m;
}

} // namespace

class TestLongAlignment : public QObject
{
    Q_OBJECT
private slots:
    void windowsAgreeWithOnePass_data()
    {
        QTest::addColumn<bool>("cues");
        QTest::newRow("speaking rate") << false;
        QTest::newRow("subtitle cues") << true;
    }

    void windowsAgreeWithOnePass()
    {
        QFETCH(bool, cues);
        const Recording r = demoRecording();
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const auto pronunciations = lexicon.pronounceAll(r.words);
        const double duration = double(r.samples.size()) / 16000.0;
        const AlignmentResult whole = ForcedAligner(model()).align(model().features(r.samples), r.words,
                                                                   pronunciations, duration);
        Feedback feedback;
        std::vector<double> progress;
        feedback.onProgress = [&](double p) { progress.push_back(p); };
        const AlignmentResult windowed = alignLongRecording(model(), r.samples, r.words, pronunciations,
                                                            cues ? r.cues : std::vector<Interval>{}, feedback,
                                                            tenSecondWindows());
        QVERIFY2(progress.size() >= 4, "one report per window at least");
        QCOMPARE(progress.back(), 1.0);
        checkTiles(windowed.words, duration);
        checkTiles(windowed.phones, duration);
        const std::vector<Interval> w = spoken(windowed.words);
        QCOMPARE(int(w.size()), int(r.words.size()));
        for (size_t i = 0; i < w.size(); ++i)
            QCOMPARE(w[i].label, r.words[i]);
        const double withWhole = agreement(w, spoken(whole.words), 0.02);
        QVERIFY2(withWhole >= 0.95, qPrintable(QString::number(withWhole)));
        const double wholeWithReference = agreement(spoken(whole.words), r.reference, 0.04);
        const double windowedWithReference = agreement(w, r.reference, 0.04);
        QVERIFY2(windowedWithReference >= wholeWithReference - 0.02,
                 qPrintable(QStringLiteral("%1 vs %2").arg(windowedWithReference).arg(wholeWithReference)));
        QVERIFY(windowedWithReference >= 0.8);
    }

    void cuesThatDoNotMatchAreIgnored()
    {
        const Recording r = demoRecording();
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const auto pronunciations = lexicon.pronounceAll(r.words);
        std::vector<Interval> wrong = r.cues;
        wrong.pop_back(); // six words short
        const AlignmentResult a = alignLongRecording(model(), r.samples, r.words, pronunciations, r.cues,
                                                     Feedback::none(),
                                                     tenSecondWindows());
        const AlignmentResult b = alignLongRecording(model(), r.samples, r.words, pronunciations, wrong,
                                                     Feedback::none(),
                                                     tenSecondWindows());
        const AlignmentResult c = alignLongRecording(model(), r.samples, r.words, pronunciations, {}, Feedback::none(),
                                                     tenSecondWindows());
        QCOMPARE(spoken(b.words).size(), r.words.size());
        QCOMPARE(b.words.intervals, c.words.intervals);
        QVERIFY(agreement(spoken(a.words), spoken(c.words), 0.02) >= 0.95);
    }

    void aStretchWithoutWords()
    {
        const Recording r = demoRecording(4);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const AlignmentResult a = alignLongRecording(model(), r.samples, r.words, lexicon.pronounceAll(r.words), {},
                                                     Feedback::none(), tenSecondWindows());
        const std::vector<Interval> w = spoken(a.words);
        QCOMPARE(w.size(), r.words.size());
        const double agree = agreement(w, r.reference, 0.04);
        QVERIFY2(agree >= 0.8, qPrintable(QString::number(agree)));
        for (const Interval &i : w)
            QVERIFY2(i.end <= r.noiseStart + 0.1 || i.start >= r.noiseStart + 25.0 - 0.1, i.label.c_str());
    }

    void wordsThatAreNotSpoken()
    {
        Recording r = demoRecording();
        for (int k = 0; k < 40; ++k)
            r.words.insert(r.words.end(), {"bin", "blue", "at", "f", "two", "now"});
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        try {
            alignLongRecording(model(), r.samples, r.words, lexicon.pronounceAll(r.words), {}, Feedback::none(),
                               tenSecondWindows());
            QFAIL("300 words fit 30 s");
        } catch (const Error &e) {
            QVERIFY2(e.reason().find(" from 0:00:") != std::string::npos, e.what());
            QVERIFY2(e.reason().find("(word ") != std::string::npos, e.what());
        }
    }

    void cancel()
    {
        const Recording r = demoRecording();
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        Feedback feedback;
        feedback.onProgress = [&](double p) {
            if (p > 0.3)
                feedback.cancel();
        };
        QVERIFY_THROWS_EXCEPTION(Canceled, alignLongRecording(model(), r.samples, r.words, lexicon.pronounceAll(r.words),
                                                               {}, feedback, tenSecondWindows()));
    }
};

QTEST_GUILESS_MAIN(TestLongAlignment)
#include "tst_longalignment.moc"
