// The background's posture under generated speech (render/PostureTransfer): the speech subspace
// and the inner lips' opening are left as generated, the rest takes the background's level; on
// the demo, a model's trajectory drawn into a clip moves its lower face less with the clip's own
// posture kept, and opens the lips exactly as much; the slow posture is a Gaussian over time.
#include "render/PostureTransfer.h"

#include "aam/AamSynthesizer.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "project/Project.h"
#include "render/BilabialClosure.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

const std::string kDemo = std::string(LIPSYNC_SOURCE_DIR) + "/resources/demo";
const std::string kHeldOut = "bbaf2n";

} // namespace

class TestPostureTransfer : public QObject
{
    Q_OBJECT

private slots:
    // Phone targets spread along one whitened direction and an opening along another: those two
    // are kept as generated, the other two take the posture's offset from the targets' mean.
    void keepsSpeechAndOpeningAsGenerated()
    {
        const Eigen::Vector4d variances(4.0, 1.0, 9.0, 2.25);
        const Eigen::Vector4d root = variances.cwiseSqrt();
        Eigen::MatrixXd targets(3, 4);
        for (int p = 0; p < 3; ++p)
            targets.row(p) = (Eigen::Vector4d(1.0, 0.0, 0.0, 0.0) * (p - 1.0) * root[0]
                              + Eigen::Vector4d(0.5, 0.0, 2.0, -1.0))
                                 .transpose();
        const Eigen::Vector4d opening(0.0, 3.0, 0.0, 0.0);
        const PostureTransfer transfer(targets, variances, opening);
        QCOMPARE(transfer.speechDimension(), 2);
        const Eigen::Vector4d c(1.0, -2.0, 3.0, 0.25);
        const Eigen::Vector4d posture(7.0, 5.0, 4.0, 1.5);
        const Eigen::VectorXd drawn = transfer.apply(c, posture);
        QVERIFY(std::abs(drawn[0] - c[0]) < 1e-12);
        QVERIFY(std::abs(drawn[1] - c[1]) < 1e-12);
        QVERIFY(std::abs(drawn[2] - (c[2] + posture[2] - 2.0)) < 1e-12);
        QVERIFY(std::abs(drawn[3] - (c[3] + posture[3] + 1.0)) < 1e-12);
        // A posture at the targets' own level changes nothing; no posture (the neutral frame,
        // or no face near) leaves the parameters as generated.
        QVERIFY((transfer.apply(c, targets.colwise().mean().transpose()) - c).norm() < 1e-12);
        QCOMPARE(transfer.apply(c, Eigen::VectorXd()), Eigen::VectorXd(c));
        QCOMPARE(transfer.apply(c, Eigen::Vector4d::Constant(std::nan(""))), Eigen::VectorXd(c));
        // Without an opening only the targets' direction is kept.
        QCOMPARE(PostureTransfer(targets, variances, Eigen::VectorXd()).speechDimension(), 1);
        QVERIFY_THROWS_EXCEPTION(Error, PostureTransfer(targets.leftCols(3), variances, opening));
        QVERIFY_THROWS_EXCEPTION(Error, PostureTransfer(targets, Eigen::Vector4d(1, 1, 0, 1), opening));
    }

    // HMM-mean trained on the demo's other clips, its trajectory for the held-out clip drawn into
    // the clip's own frames: with the clip's slow posture kept, the 23 points move less from where
    // they were tracked, and the inner lips open exactly as generated.
    void movesTheRecordedFaceLess()
    {
        const AamModel aam = AamModel::load(kDemo + "/aam/demo.aam");
        const Project project = Project::load(kDemo);
        std::vector<LabelledSequence> training;
        const Sequence *heldOut = nullptr;
        for (const Sequence &s : project.sequences) {
            if (s.features.rows() == 0 || s.phones.isEmpty())
                continue;
            if (s.id == kHeldOut)
                heldOut = &s;
            else
                training.push_back({s.id, frameLabelsFromTier(s.phones, s.frameRate, int(s.features.rows())), s.features});
        }
        QVERIFY(heldOut);
        QVERIFY(training.size() >= 5);
        std::unique_ptr<DynamicModel> model = createDynamicModel("hmm");
        Feedback feedback;
        model->train(training, feedback);
        const std::shared_ptr<const PostureTransfer> transfer = PostureTransfer::forModel(*model, aam);
        QVERIFY(transfer);
        QVERIFY(transfer->speechDimension() > 1);
        QVERIFY(transfer->speechDimension() < aam.combinedModes());

        const Eigen::MatrixXd &tracked = heldOut->features;
        const Eigen::MatrixXd generated
            = model->generate(frameLabelsFromTier(heldOut->phones, heldOut->frameRate, int(tracked.rows())));
        const Eigen::MatrixXd posture = PostureTransfer::slowPosture(tracked, heldOut->clock().times());
        const AamSynthesizer synthesizer(aam);
        const BilabialClosure closure(aam);
        double asGenerated = 0, kept = 0;
        for (Eigen::Index t = 0; t < tracked.rows(); ++t) {
            const Eigen::VectorXd c = generated.row(t).transpose();
            const Eigen::VectorXd drawn = transfer->apply(c, posture.row(t).transpose());
            QVERIFY(std::abs(closure.opening(drawn) - closure.opening(c)) < 1e-9);
            const Eigen::VectorXd there = synthesizer.shape(tracked.row(t).transpose());
            asGenerated += (synthesizer.shape(c) - there).squaredNorm();
            kept += (synthesizer.shape(drawn) - there).squaredNorm();
        }
        qInfo("mean squared move of the 23 points: %.4f as generated, %.4f with the posture kept", asGenerated / double(tracked.rows()), kept / double(tracked.rows()));
        QVERIFY(kept < 0.8 * asGenerated);
    }

    // A Gaussian of kPostureSeconds over the frames' times: a constant stays, a step is halfway at
    // its time and settled three widths away, articulation at 5 Hz is gone, frames without a face
    // are filled from their neighbours, and a gap in the timestamps counts as time, not frames.
    void slowPostureIsAGaussianOverTime()
    {
        std::vector<double> times;
        Eigen::MatrixXd step(100, 2);
        for (int t = 0; t < 100; ++t) {
            times.push_back(t / 25.0);
            step(t, 0) = t / 25.0 >= 2.0 ? 1.0 : 0.0;
            step(t, 1) = 3.0 + std::sin(2.0 * M_PI * 5.0 * t / 25.0);
        }
        const Eigen::MatrixXd slow = PostureTransfer::slowPosture(step, times, 0.5);
        QVERIFY(std::abs(slow(50, 0) - 0.5) < 0.05);
        QVERIFY(slow(10, 0) < 0.01);
        QVERIFY(slow(90, 0) > 0.99);
        for (int t = 38; t < 62; ++t) // three widths from either end: the whole Gaussian
            QVERIFY(std::abs(slow(t, 1) - 3.0) < 0.01);
        Eigen::MatrixXd holes = step;
        holes.row(20).setConstant(std::nan(""));
        const Eigen::MatrixXd filled = PostureTransfer::slowPosture(holes, times, 0.5);
        QVERIFY(filled.allFinite());
        QVERIFY(std::abs(filled(20, 1) - slow(20, 1)) < 0.02);
        // Frames 50-99 shown 10 s later: frame 49 no longer sees the ones after the gap.
        std::vector<double> gap = times;
        for (size_t t = 50; t < gap.size(); ++t)
            gap[t] += 10.0;
        const Eigen::MatrixXd apart = PostureTransfer::slowPosture(step, gap, 0.5);
        QVERIFY(apart(49, 0) < 1e-9);
        QVERIFY(apart(50, 0) > 1.0 - 1e-9);
        // No face anywhere near: no posture.
        const Eigen::MatrixXd none = PostureTransfer::slowPosture(Eigen::MatrixXd::Constant(3, 2, std::nan("")), {0.0, 0.04, 0.08});
        QVERIFY(!none.row(1).allFinite());
    }
};

QTEST_GUILESS_MAIN(TestPostureTransfer)
#include "tst_posturetransfer.moc"
