// Lip closure on /p b m/ (render/BilabialClosure): the weights of a phone tier's frames, closed
// lips in the AAM's own shape after apply(), the smallest change under the AAM's prior, and
// nothing changed off the bilabials — on the demo's AAM and tracked features.
#include "render/BilabialClosure.h"

#include "aam/AamModel.h"
#include "io/FeatureCsv.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <random>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";

// Inner-lip opening of the shape of c, computed from the shape itself (scheme23 points 16 and
// 17 along the mean face's vertical, in mean eye-corner distances).
double shapeOpening(const AamModel &aam, const Eigen::VectorXd &c)
{
    Eigen::VectorXd bs, bg;
    aam.partsFromCombined(c, bs, bg);
    const Eigen::VectorXd shape = aam.meanShape + aam.shapeBasis * bs;
    const Eigen::Vector2d eyes = aam.meanShape.segment<2>(12) - aam.meanShape.segment<2>(0);
    const Eigen::Vector2d down = Eigen::Vector2d(-eyes.y(), eyes.x()) / eyes.norm();
    return (shape.segment<2>(34) - shape.segment<2>(32)).dot(down) / eyes.norm();
}

} // namespace

class TestBilabialClosure : public QObject
{
    Q_OBJECT

    AamModel m_aam;
    Eigen::MatrixXd m_tracked;

private slots:
    void initTestCase()
    {
        m_aam = AamModel::load(kDemo + "/aam/demo.aam");
        m_tracked = readFeatureCsv(kDemo + "/features/bbaf2n.csv").values;
        QCOMPARE(int(m_tracked.cols()), m_aam.combinedModes());
    }

    void weightsAreTheFramesShareOfThePhone()
    {
        // B over [0.10, 0.18) s at 25 frames/s: half of frame 2, all of frame 3, half of frame 4.
        const Tier phones{"phones", {{0.0, 0.10, "sil"}, {0.10, 0.18, "B"}, {0.18, 0.30, "AY"},
                                     {0.30, 0.315, "M"}, {0.315, 0.40, "sil"}}};
        const std::vector<double> w = BilabialClosure::weights(phones, FrameClock::uniform(25.0, 10));
        QCOMPARE(int(w.size()), 10);
        QCOMPARE(w[1], 0.0);
        QVERIFY(std::abs(w[2] - 0.5) < 1e-9);
        QCOMPARE(w[3], 1.0);
        QVERIFY(std::abs(w[4] - 0.5) < 1e-9);
        QCOMPARE(w[5], 0.0);
        // An M of 15 ms inside frame 7 still closes the lips on that frame.
        QCOMPARE(w[7], 1.0);
        QCOMPARE(w[6], 0.0);
        QCOMPARE(w[8], 0.0);
        // Frames past the tier's end and lower-case or stressed labels.
        const Tier lower{"phones", {{0.0, 0.04, "p"}, {0.04, 0.08, "m1"}, {0.08, 0.12, "t"}}};
        QCOMPARE(BilabialClosure::weights(lower, FrameClock::uniform(25.0, 2)), (std::vector<double>{1.0, 1.0}));
        QCOMPARE(BilabialClosure::weights(phones, FrameClock::uniform(0.0, 3)), (std::vector<double>{0.0, 0.0, 0.0}));
        QCOMPARE(BilabialClosure::weights(std::vector<int>{PhoneSet::kP, PhoneSet::index("AA"), PhoneSet::kB,
                                                           PhoneSet::kM, PhoneSet::kSilence}),
                 (std::vector<double>{1.0, 0.0, 1.0, 1.0, 0.0}));
    }

    void openingIsTheShapes()
    {
        const BilabialClosure closure(m_aam);
        double widest = 0;
        for (Eigen::Index t = 0; t < m_tracked.rows(); ++t) {
            const Eigen::VectorXd c = m_tracked.row(t).transpose();
            QVERIFY(std::abs(closure.opening(c) - shapeOpening(m_aam, c)) < 1e-9);
            widest = std::max(widest, closure.opening(c));
        }
        // The clip's lips open by a tenth of the eye-corner distance or more.
        QVERIFY2(widest > 0.1, qPrintable(QString::number(widest)));
    }

    void closesTheLipsWithTheSmallestChange()
    {
        const BilabialClosure closure(m_aam);
        Eigen::Index widest = 0;
        for (Eigen::Index t = 1; t < m_tracked.rows(); ++t)
            if (closure.opening(m_tracked.row(t).transpose()) > closure.opening(m_tracked.row(widest).transpose()))
                widest = t;
        const std::vector<double> w(size_t(m_tracked.rows()), 0.0);
        std::vector<double> close = w, half = w;
        close[size_t(widest)] = 1.0;
        half[size_t(widest)] = 0.5;
        const Eigen::VectorXd before = m_tracked.row(widest).transpose();
        const Eigen::MatrixXd closed = closure.apply(m_tracked, close);
        const Eigen::VectorXd after = closed.row(widest).transpose();
        QVERIFY(std::abs(shapeOpening(m_aam, after)) < 1e-9);
        QVERIFY(std::abs(shapeOpening(m_aam, closure.apply(m_tracked, half).row(widest).transpose())
                         - 0.5 * shapeOpening(m_aam, before)) < 1e-9);
        // Every other frame is untouched; zero weights change nothing.
        QCOMPARE(Eigen::MatrixXd(closed.topRows(widest)), Eigen::MatrixXd(m_tracked.topRows(widest)));
        QCOMPARE(closure.apply(m_tracked, w), m_tracked);
        // Closed lips stay as they are.
        QVERIFY((closure.apply(closed, close) - closed).norm() < 1e-12);
        // The change is the smallest in the AAM's Mahalanobis distance among the changes that
        // close the lips as much: no random change of the same opening is smaller.
        const Eigen::VectorXd delta = after - before;
        const Eigen::VectorXd lambda = m_aam.combinedVariances;
        auto mahalanobis = [&](const Eigen::VectorXd &d) { return d.cwiseProduct(lambda.cwiseInverse()).dot(d); };
        std::mt19937 rng(5);
        std::normal_distribution<double> normal;
        for (int trial = 0; trial < 200; ++trial) {
            Eigen::VectorXd other(delta.size());
            for (Eigen::Index i = 0; i < other.size(); ++i)
                other[i] = normal(rng) * std::sqrt(lambda[i]);
            const double needed = closure.opening(after) - closure.opening(before);
            const double moves = closure.opening(before + other) - closure.opening(before);
            if (std::abs(moves) < 1e-6)
                continue;
            other *= needed / moves;
            QVERIFY(mahalanobis(other) >= mahalanobis(delta) * (1 - 1e-9));
        }
    }

    // What renderers draw: the tier's weights applied, or the trajectory as it is for an AAM the
    // rule does not apply to.
    void closesOnAPhoneTier()
    {
        const Tier phones{"phones", {{0.0, 0.5, "sil"}, {0.5, 0.62, "B"}, {0.62, 3.0, "IH"}}};
        const Eigen::MatrixXd closed = BilabialClosure::closeOnPhones(m_aam, m_tracked, phones, FrameClock::uniform(25.0, int(m_tracked.rows())));
        QCOMPARE(closed, BilabialClosure(m_aam).apply(m_tracked, BilabialClosure::weights(phones, FrameClock::uniform(25.0, int(m_tracked.rows())))));
        QVERIFY(BilabialClosure(m_aam).opening(closed.row(13).transpose()) < 1e-9); // [0.52, 0.56) s
        QVERIFY(!BilabialClosure::forAam(AamModel{}));
        QVERIFY(BilabialClosure::forAam(m_aam));
        QCOMPARE(BilabialClosure::closeOnPhones(AamModel{}, m_tracked, phones, FrameClock::uniform(25.0, int(m_tracked.rows()))), m_tracked);
    }

    void refusesWhatItCannotClose()
    {
        const BilabialClosure closure(m_aam);
        QVERIFY_THROWS_EXCEPTION(Error, closure.apply(Eigen::MatrixXd::Zero(3, m_aam.combinedModes() + 1), {1, 1, 1}));
        AamModel empty;
        QVERIFY_THROWS_EXCEPTION(Error, BilabialClosure{empty});
        // Non-finite frames and frames past the weights pass through.
        Eigen::MatrixXd withNaN = m_tracked.topRows(3);
        withNaN(0, 0) = std::numeric_limits<double>::quiet_NaN();
        const Eigen::MatrixXd out = closure.apply(withNaN, {1.0});
        QVERIFY(std::isnan(out(0, 0)));
        QCOMPARE(Eigen::MatrixXd(out.bottomRows(2)), Eigen::MatrixXd(withNaN.bottomRows(2)));
    }
};

QTEST_GUILESS_MAIN(TestBilabialClosure)
#include "tst_bilabialclosure.moc"
