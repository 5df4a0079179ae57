// ExemplarSelection (render/ExemplarSelection): recorded frames in place of generated ones.
//  - a generated trajectory that is a recording plus a little noise gets that recording's own
//    frames back, in order (parameter recovery);
//  - every chosen frame is a recorded one, and frames that followed each other in a recording
//    are preferred to jumps between recordings of the same distance;
//  - without join and cut costs each frame takes its nearest recorded frame;
//  - bad input is refused.
#include "render/ExemplarSelection.h"
#include "util/Error.h"

#include <QTest>

#include <cmath>
#include <random>

using namespace lipsync;

namespace {

// A smooth 3-d trajectory: sinusoids of the given phase.
Eigen::MatrixXd wave(int frames, double phase, double speed = 0.2)
{
    Eigen::MatrixXd m(frames, 3);
    for (int t = 0; t < frames; ++t)
        m.row(t) << std::sin(speed * t + phase), std::cos(0.7 * speed * t + 2 * phase), 0.5 * std::sin(1.3 * speed * t);
    return m;
}

} // namespace

class TestExemplarSelection : public QObject
{
    Q_OBJECT
private slots:
    void recoversARecording()
    {
        const std::vector<Eigen::MatrixXd> recordings{wave(60, 0.0), wave(60, 1.0), wave(60, 2.0)};
        const ExemplarSelection selection(recordings, {});
        std::mt19937 random(7);
        std::normal_distribution<double> noise(0.0, 0.01);
        Eigen::MatrixXd generated = recordings[1];
        for (Eigen::Index i = 0; i < generated.size(); ++i)
            generated.data()[i] += noise(random);
        const std::vector<int> chosen = selection.choose(generated);
        QCOMPARE(int(chosen.size()), 60);
        for (int t = 0; t < 60; ++t)
            QCOMPARE(chosen[size_t(t)], 60 + t);
        QVERIFY((selection.select(generated) - recordings[1]).cwiseAbs().maxCoeff() < 1e-12);
    }

    void choosesRecordedFramesAndRuns()
    {
        const std::vector<Eigen::MatrixXd> recordings{wave(80, 0.0), wave(80, 0.5), wave(80, 3.0)};
        Eigen::MatrixXd all(240, 3);
        all << recordings[0], recordings[1], recordings[2];
        // Halfway between two recordings: no recorded frame is exactly it.
        const Eigen::MatrixXd generated = 0.5 * (recordings[0] + recordings[1]).topRows(50);
        const ExemplarSelection selection(recordings, {});
        const Eigen::MatrixXd chosen = selection.select(generated);
        int runs = 1;
        const std::vector<int> index = selection.choose(generated);
        for (size_t t = 0; t < index.size(); ++t) {
            QVERIFY((all.row(index[t]) - chosen.row(Eigen::Index(t))).norm() < 1e-12);
            if (t > 0 && index[t] != index[t - 1] + 1)
                ++runs;
        }
        QVERIFY2(runs <= 5, qPrintable(QString::number(runs))); // recordings play on, not frame-by-frame jumps
        // Near the generated trajectory all along.
        QVERIFY((chosen - generated).rowwise().norm().maxCoeff() < 0.5);
    }

    void withoutJoinCostsEachFrameIsItsNearest()
    {
        // Recordings of still poses from -1 to 1: a moving generated trajectory must jump between
        // them; without the join and cut costs each frame takes its nearest pose.
        std::vector<Eigen::MatrixXd> stills;
        for (int k = 0; k <= 20; ++k)
            stills.push_back(Eigen::MatrixXd::Constant(3, 3, -1.0 + 0.1 * k));
        const Eigen::MatrixXd generated = wave(30, 0.0, 0.05).col(0).replicate(1, 3);
        ExemplarSelection::Options free;
        free.join = 0.0;
        free.cut = 0.0;
        const Eigen::MatrixXd nearest = ExemplarSelection(stills, free).select(generated);
        for (Eigen::Index t = 0; t < generated.rows(); ++t)
            QVERIFY(std::abs(nearest(t, 0) - generated(t, 0)) <= 0.05 + 1e-9);
        QVERIFY_THROWS_EXCEPTION(Error, ExemplarSelection({}, {}));
        QVERIFY_THROWS_EXCEPTION(Error, ExemplarSelection(stills, {}).select(Eigen::MatrixXd::Zero(4, 2)));
        QVERIFY_THROWS_EXCEPTION(Error, ExemplarSelection({Eigen::MatrixXd::Zero(2, 3), Eigen::MatrixXd::Zero(2, 4)}, {}));
    }
};

QTEST_GUILESS_MAIN(TestExemplarSelection)
#include "tst_exemplarselection.moc"
