// BackgroundRetiming: new speech longer than the person's video is covered by runs of the video
// played forward, cut where the head's pose continues (each cut's step within the recording's own
// 99th-percentile step, each run at least the shortest run), and by playing back in reverse when
// no cut is small enough.
#include "render/BackgroundRetiming.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

// A head swaying slowly (a 4 s period) and turning a little, at 25 fps: every pose comes back.
std::vector<Similarity> swaying(int frames)
{
    std::vector<Similarity> poses;
    for (int i = 0; i < frames; ++i) {
        const double t = i / 25.0;
        const double angle = 0.05 * std::sin(2 * M_PI * t / 4.0), scale = 100.0 * (1.0 + 0.02 * std::sin(2 * M_PI * t / 6.0));
        poses.push_back({scale * std::cos(angle), scale * std::sin(angle), 180.0 + 10.0 * std::sin(2 * M_PI * t / 4.0), 140.0});
    }
    return poses;
}

} // namespace

class TestBackgroundRetiming : public QObject
{
    Q_OBJECT
private slots:
    void shortSpeechPlaysTheVideoAsItIs()
    {
        const BackgroundRetiming r = retimeBackground(swaying(300), 120);
        QCOMPARE(int(r.frames.size()), 120);
        for (int i = 0; i < 120; ++i)
            QCOMPARE(r.frames[size_t(i)], i);
        QVERIFY(r.cuts.empty());
    }

    void longSpeechCutsWhereThePoseContinues()
    {
        const std::vector<Similarity> poses = swaying(300);
        BackgroundRetimingOptions options;
        const BackgroundRetiming r = retimeBackground(poses, 2000, options);
        QCOMPARE(int(r.frames.size()), 2000);
        QVERIFY(r.cuts.size() >= 5);
        QCOMPARE(r.reversals, 0);
        QVERIFY(r.naturalStep99 > 0);
        for (double step : r.cutSteps)
            QVERIFY2(step <= r.naturalStep99, qPrintable(QString("%1 > %2").arg(step).arg(r.naturalStep99)));
        // Between cuts the video plays forward, frame by frame, for at least the shortest run.
        int runStart = 0;
        for (int k = 1; k < 2000; ++k) {
            const bool cut = std::find(r.cuts.begin(), r.cuts.end(), k) != r.cuts.end();
            QVERIFY(r.frames[size_t(k)] >= 0 && r.frames[size_t(k)] < 300);
            if (cut) {
                QVERIFY2(k - runStart >= options.shortestRun, qPrintable(QString("a run of %1 frames").arg(k - runStart)));
                runStart = k;
            } else {
                QCOMPARE(r.frames[size_t(k)], r.frames[size_t(k - 1)] + 1);
            }
        }
        // No step between output frames beyond the video's own largest.
        double largest = 0;
        for (size_t i = 0; i + 1 < poses.size(); ++i)
            largest = std::max(largest, poseStep(poses[i], poses[i + 1]));
        QVERIFY(r.largestStep <= largest + 1e-12);
    }

    void restlessVideoTurnsBack()
    {
        // A head that only moves one way: no earlier frame continues its motion.
        std::vector<Similarity> poses;
        for (int i = 0; i < 120; ++i)
            poses.push_back({100.0, 0.0, 100.0 + 2.0 * i, 140.0});
        const BackgroundRetiming r = retimeBackground(poses, 400);
        QCOMPARE(int(r.frames.size()), 400);
        QVERIFY(r.cuts.empty());
        QVERIFY(r.reversals >= 1);
        QCOMPARE(r.frames[119], 119);
        QCOMPARE(r.frames[120], 118); // back the way it came
        QVERIFY(retimeBackground({}, 10).frames.empty());
    }
};

QTEST_GUILESS_MAIN(TestBackgroundRetiming)
#include "tst_backgroundretiming.moc"
