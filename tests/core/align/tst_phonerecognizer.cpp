// Phone recognition as the sound comes in (align/StreamingPhoneRecognizer.h) and its bigram
// (align/PhoneBigram.h), on the GRID demo clips with the shipped aligner model:
//  - the streamed features are the offline ones (AcousticModel::features) when the mean is the
//    same, whatever the block sizes; decisions do not depend on the block sizes either;
//  - a short lag agrees with the full Viterbi path (an unbounded lag) on most frames, and the
//    latency it reports is the lag plus the features' look-ahead;
//  - recognised phones match the forced alignment on most frames of a clip whose bigram comes
//    from the other clips;
//  - the bigram counts transitions, smooths them, and its file round-trips; malformed files are
//    Errors naming the file and line.
#include "align/AcousticModel.h"
#include "align/PhoneBigram.h"
#include "align/StreamingPhoneRecognizer.h"
#include "audio/Mfcc.h"
#include "io/AudioDecoder.h"
#include "align/ForcedAligner.h"
#include "align/Lexicon.h"
#include "io/Transcript.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <random>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";
const char *const kClips[] = {"bbaf2n", "bgin3a", "bwbg8n", "lbwy6n", "lrik4p",
                              "pbav2n", "pgwe6n", "pwbk1s", "sbwo1s", "srbu6n"};

const AcousticModel &model()
{
    static const AcousticModel m = AcousticModel::load(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner");
    return m;
}

std::vector<float> sound(const std::string &clip)
{
    return AudioDecoder::decode(kDemo + "/media/" + clip + ".mpg", 16000).samples;
}

// Decisions for `samples` fed in blocks of random sizes up to `largest`.
std::vector<int> recognise(StreamingPhoneRecognizer &r, const std::vector<float> &samples, size_t largest,
                           unsigned seed = 1)
{
    std::mt19937 random(seed);
    std::vector<int> out;
    for (size_t at = 0; at < samples.size();) {
        const size_t n = std::min(samples.size() - at, size_t(1 + random() % largest));
        r.push(samples.data() + at, n);
        at += n;
        for (int p : r.takeDecided())
            out.push_back(p);
    }
    r.finish();
    for (int p : r.takeDecided())
        out.push_back(p);
    return out;
}

// The forced alignment's phone at each 100 Hz frame centre.
std::vector<int> alignedFrames(const Tier &phones, int frames, const MfccOptions &o)
{
    std::vector<int> out;
    for (int j = 0; j < frames; ++j) {
        const double c = j * o.shiftSeconds + o.windowSeconds / 2;
        int label = PhoneSet::kSilence;
        for (const Interval &i : phones.intervals)
            if (c >= i.start && c < i.end)
                label = PhoneSet::index(i.label);
        out.push_back(label);
    }
    return out;
}

double agreement(const std::vector<int> &a, const std::vector<int> &b)
{
    const size_t n = std::min(a.size(), b.size());
    int same = 0;
    for (size_t i = 0; i < n; ++i)
        same += a[i] == b[i];
    return n ? double(same) / double(n) : 0.0;
}

} // namespace

class TestPhoneRecognizer : public QObject
{
    Q_OBJECT
private slots:
    void featuresAreTheOfflineOnes()
    {
        const std::vector<float> samples = sound("bbaf2n");
        const Mfcc mfcc(model().featureOptions());
        const Eigen::VectorXf mean = mfcc.computeStatic(samples).colwise().mean().transpose();
        const Eigen::MatrixXf offline = model().features(samples); // its own mean: the same
        for (size_t largest : {size_t(1), size_t(160), size_t(5000)}) {
            StreamingPhoneRecognizer r(model(), PhoneBigram());
            r.keepFeatureHistory(true);
            r.useFixedMean(mean);
            recognise(r, samples, largest);
            QCOMPARE(Eigen::Index(r.featureHistory().size()), offline.rows());
            float worst = 0;
            for (size_t t = 0; t < r.featureHistory().size(); ++t)
                worst = std::max(worst, (r.featureHistory()[t] - offline.row(Eigen::Index(t)).transpose()).cwiseAbs().maxCoeff());
            QVERIFY2(worst < 1e-3f, qPrintable(QString::number(worst)));
        }
    }

    void decisionsDoNotDependOnBlocks()
    {
        const std::vector<float> samples = sound("lrik4p");
        StreamingPhoneRecognizer a(model(), PhoneBigram()), b(model(), PhoneBigram());
        const std::vector<int> x = recognise(a, samples, 160), y = recognise(b, samples, 20000, 7);
        QCOMPARE(x, y);
        QCOMPARE(int(x.size()), Mfcc(model().featureOptions()).frameCount(samples.size()));
        QCOMPARE(a.decidedFrames(), int(x.size()));
    }

    void lagAgainstTheWholePath()
    {
        const std::vector<float> samples = sound("pgwe6n");
        PhoneRecognizerOptions shortLag, whole;
        shortLag.lagFrames = 6;
        whole.lagFrames = 100000;
        StreamingPhoneRecognizer a(model(), PhoneBigram(), shortLag), b(model(), PhoneBigram(), whole);
        QVERIFY(std::abs(a.latencySeconds() - (0.06 + 0.04 + 0.0125)) < 1e-9);
        const std::vector<int> x = recognise(a, samples, 320), y = recognise(b, samples, 320);
        // Nothing is decided before the end with an unbounded lag.
        QCOMPARE(x.size(), y.size());
        const double agree = agreement(x, y);
        QVERIFY2(agree >= 0.9, qPrintable(QString::number(agree)));
    }

    void recognisesTheAlignedPhones()
    {
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        std::vector<Tier> aligned;
        for (const char *clip : kClips) {
            const std::vector<float> samples = sound(clip);
            aligned.push_back(ForcedAligner(model())
                                  .align(model().features(samples),
                                         readTranscript(kDemo + "/media/" + clip + ".align").text(), lexicon)
                                  .phones);
        }
        double total = 0;
        for (size_t held = 0; held < aligned.size(); ++held) {
            std::vector<Tier> others = aligned;
            others.erase(others.begin() + long(held));
            StreamingPhoneRecognizer r(model(), PhoneBigram::fromTiers(others));
            const std::vector<int> decided = recognise(r, sound(kClips[held]), 160);
            total += agreement(decided, alignedFrames(aligned[held], int(decided.size()), model().featureOptions()));
        }
        const int clips = int(aligned.size());
        const double mean = total / clips;
        qInfo("frames labelled as the forced alignment does: %.1f %% (mean of %d clips)", 100 * mean, clips);
        QVERIFY2(mean >= 0.85, qPrintable(QString::number(mean)));
    }

    void bigram()
    {
        Tier a{"phones", {{0, 1, "sil", false}, {1, 2, "B", false}, {2, 3, "IH", false}, {3, 4, "N", false}}};
        Tier b{"phones", {{0, 1, "B", false}, {1, 2, "IH", false}}};
        const PhoneBigram g = PhoneBigram::fromTiers({a, b});
        const int B = PhoneSet::index("B"), IH = PhoneSet::index("IH"), N = PhoneSet::index("N");
        QCOMPARE(g.counts()(B, IH), 2.0);
        QCOMPARE(g.counts()(PhoneSet::kSilence, B), 2.0); // sil -> B in a, start -> B in b
        QCOMPARE(g.transitions(), 6.0); // a starts with sil -> sil
        QVERIFY(std::abs(g.logProbability(B, IH) - std::log(3.0 / 43.0)) < 1e-12);
        QVERIFY(std::abs(g.logProbability(N, B) - std::log(1.0 / 41.0)) < 1e-12);
        double sum = 0;
        for (int q = 0; q < PhoneSet::kCount; ++q)
            sum += std::exp(g.logProbability(IH, q));
        QVERIFY(std::abs(sum - 1.0) < 1e-12);

        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("g.bigram")).toStdString();
        g.save(path);
        QCOMPARE(PhoneBigram::load(path).counts(), g.counts());
        auto errorOf = [](const std::string &text) {
            try {
                PhoneBigram::parse(text, "x.bigram");
            } catch (const Error &e) {
                return std::string(e.what());
            }
            return std::string();
        };
        std::string text = g.text();
        QVERIFY(errorOf("nonsense").find("x.bigram") != std::string::npos);
        QVERIFY(errorOf("lipsync-phone-bigram 2\n").find("version 2") != std::string::npos);
        QVERIFY(errorOf(text.substr(0, text.size() / 2)).find("line") != std::string::npos);
        std::string negative = text; // the second row's first count made negative
        const size_t row2 = negative.find('\n', negative.find('\n') + 1) + 1;
        negative.replace(row2, negative.find(' ', row2) - row2, "-1");
        QVERIFY(errorOf(negative).find("line 3") != std::string::npos);
        QVERIFY_THROWS_EXCEPTION(Error, PhoneBigram::fromTiers({Tier{"phones", {{0, 1, "XX", false}}}}));
    }
};

QTEST_GUILESS_MAIN(TestPhoneRecognizer)
#include "tst_phonerecognizer.moc"
