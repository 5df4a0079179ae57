// Rare phones (docs/models.md §0): a phone seen in fewer than kMinimumVarianceFrames training
// frames takes the global variance instead of its own, so its later frames are not improbable
// beyond measure — what a phone seen in a single frame did to a fold of the 400-clip GRID
// evaluation (log-likelihoods of -37 000 nats per frame).
//  - HMM-mean: the rare phone's variance is the global one, its mean its own; a common phone's
//    variance is still its exact ML estimate.
//  - Every model (HMM-mean, Brand, SLDS, DPDS) trained with a phone seen once scores held-out
//    frames of that phone within a few nats of the others, not thousands below.
#include "dynamics/BrandModel.h"
#include "dynamics/DpdsModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/LabelledSequence.h"
#include "dynamics/SldsModel.h"
#include "tasks/Feedback.h"

#include <QTest>

#include <memory>
#include <random>

using namespace lipsync;

namespace {

constexpr int kCommon = 0, kOther = 1, kRare = 2;

// Sequences of phones 0 and 1 (runs of 6 frames), the rare phone 2 in exactly `rareFrames`
// frames of the first; features a random walk in 3 dimensions.
std::vector<LabelledSequence> data(int sequences, int rareFrames, unsigned seed)
{
    std::mt19937 random(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    std::vector<LabelledSequence> out;
    for (int s = 0; s < sequences; ++s) {
        LabelledSequence seq;
        seq.name = "s" + std::to_string(s);
        const int frames = 60;
        seq.features.resize(frames, 3);
        Eigen::RowVector3d y(0, 0, 0);
        for (int t = 0; t < frames; ++t) {
            int label = (t / 6) % 2 == 0 ? kCommon : kOther;
            if (s == 0 && t >= 20 && t < 20 + rareFrames)
                label = kRare;
            y = 0.8 * y + Eigen::RowVector3d(noise(random), noise(random), noise(random))
                + (label == kOther ? Eigen::RowVector3d(1, -1, 0.5) : Eigen::RowVector3d::Zero());
            seq.labels.push_back(label);
            seq.features.row(t) = y;
        }
        out.push_back(std::move(seq));
    }
    return out;
}

// The held-out sequence's frames of the rare phone, scored by the model per frame, against its
// frames of the common phone.
double perFrame(const DynamicModel &model, const LabelledSequence &s)
{
    return model.trajectoryLogLikelihood(s.labels, s.features) / double(s.frameCount());
}

} // namespace

class TestRarePhones : public QObject
{
    Q_OBJECT

private slots:
    void hmmMeanBacksOffOnlyForRarePhones()
    {
        const std::vector<LabelledSequence> training = data(20, 1, 1);
        HmmMeanModel model;
        Feedback feedback;
        model.train(training, feedback);
        const FrameStatistics st = computeFrameStatistics(training);
        QCOMPARE(st.count[kRare], 1);
        QVERIFY((model.variances().row(kRare).transpose() - st.globalVariance).norm() < 1e-12);
        // The rare phone's mean is still its own frame.
        QVERIFY((model.means().row(kRare) - training[0].features.row(20)).norm() < 1e-12);
        // A common phone: the exact ML variance.
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero(), sumSq = Eigen::RowVector3d::Zero();
        int n = 0;
        for (const LabelledSequence &s : training)
            for (int t = 0; t < s.frameCount(); ++t)
                if (s.labels[size_t(t)] == kCommon) {
                    sum += s.features.row(t);
                    sumSq += s.features.row(t).cwiseProduct(s.features.row(t));
                    ++n;
                }
        const Eigen::RowVector3d mean = sum / n, variance = sumSq / n - mean.cwiseProduct(mean);
        QVERIFY((model.variances().row(kCommon) - variance).cwiseAbs().maxCoeff() < 1e-9);
        QVERIFY(n >= kMinimumVarianceFrames);
    }

    void aPhoneSeenOnceDoesNotCollapseTheLikelihood_data()
    {
        QTest::addColumn<QString>("kind");
        for (const char *kind : {"hmm", "brand", "slds", "dpds"})
            QTest::newRow(kind) << QString::fromLatin1(kind);
    }

    void aPhoneSeenOnceDoesNotCollapseTheLikelihood()
    {
        QFETCH(QString, kind);
        const std::vector<LabelledSequence> training = data(20, 1, 2);
        // Held out: the rare phone for 12 frames in the middle of common and other phones.
        LabelledSequence test = data(1, 0, 99).front();
        for (int t = 24; t < 36; ++t)
            test.labels[size_t(t)] = kRare;
        LabelledSequence plain = data(1, 0, 99).front();
        std::unique_ptr<DynamicModel> model;
        if (kind == "hmm")
            model = std::make_unique<HmmMeanModel>();
        else if (kind == "brand")
            model = std::make_unique<BrandModel>();
        else if (kind == "slds")
            model = std::make_unique<SldsModel>();
        else
            model = std::make_unique<DpdsModel>();
        Feedback feedback;
        model->train(training, feedback);
        const double withRare = perFrame(*model, test), without = perFrame(*model, plain);
        qInfo("%s: %.2f nats per frame with the rare phone, %.2f without", qPrintable(kind), withRare, without);
        QVERIFY2(std::isfinite(withRare) && withRare > without - 3.0,
                 qPrintable(QString("%1 against %2").arg(withRare).arg(without)));
    }
};

QTEST_GUILESS_MAIN(TestRarePhones)
#include "tst_rarephones.moc"
