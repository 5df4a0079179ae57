// FrameClock: frame <-> time both ways for evenly spaced frames (25 fps, the exact 30000/1001,
// a late first frame) and for a variable frame rate; the cut points a long recording is split at.
#include "annotation/FrameClock.h"

#include <QTest>

#include <cmath>

using lipsync::FrameClock;

class TestFrameClock : public QObject
{
    Q_OBJECT
private slots:
    void evenFrames()
    {
        const FrameClock c = FrameClock::uniform(25.0, 75, 0.5);
        QVERIFY(!c.isVariable());
        QCOMPARE(c.time(0), 0.5);
        QVERIFY(std::abs(c.time(10) - 0.9) < 1e-12);
        QVERIFY(std::abs(c.endTime() - 3.5) < 1e-12);
        QVERIFY(std::abs(c.duration() - 3.0) < 1e-12);
        QCOMPARE(c.frameAt(0.0), 0);      // before the first frame: the first
        QCOMPARE(c.frameAt(0.539), 0);
        QCOMPARE(c.frameAt(0.54), 1);     // a frame starts exactly at its time
        QCOMPARE(c.frameAt(99.0), 74);    // after the last: the last
        QCOMPARE(c.nearestFrame(0.559), 1);
        QCOMPARE(c.nearestFrame(0.561), 2);
        // NTSC: 30000/1001 exactly, no drift over an hour of frames.
        const FrameClock ntsc = FrameClock::uniform(30000.0 / 1001.0, 107892);
        QVERIFY(std::abs(ntsc.time(107891) - 107891 * 1001.0 / 30000.0) < 1e-9);
        QCOMPARE(ntsc.frameAt(107891 * 1001.0 / 30000.0), 107891);
    }

    void timesThatAreEvenBecomeUniform()
    {
        std::vector<double> t;
        for (int i = 0; i < 90; ++i)
            t.push_back(i * 1001.0 / 30000.0 + (i % 2 ? 3e-5 : 0.0)); // a 1/90000 time base's rounding
        const FrameClock c = FrameClock::fromTimes(t, 30000.0 / 1001.0);
        QVERIFY(!c.isVariable());
        QCOMPARE(c, FrameClock::uniform(30000.0 / 1001.0, 90));
    }

    void variableFrames()
    {
        const std::vector<double> t{0.0, 0.04, 0.12, 0.16, 0.5, 0.54};
        const FrameClock c = FrameClock::fromTimes(t, 0.0); // rate from the median step
        QVERIFY(c.isVariable());
        QVERIFY(std::abs(c.rate() - 25.0) < 1e-9);
        QCOMPARE(c.time(2), 0.12);
        QCOMPARE(c.endTime(3), 0.5);      // frame 3 stays on screen until frame 4
        QVERIFY(std::abs(c.endTime(5) - 0.58) < 1e-12); // the last lasts one nominal period
        QVERIFY(std::abs(c.centre(3) - 0.33) < 1e-12);
        QCOMPARE(c.frameAt(0.3), 3);
        QCOMPARE(c.frameAt(0.5), 4);
        QCOMPARE(c.times(), t);
        // A slice keeps its times; shifted, it starts where asked.
        const FrameClock s = c.slice(2, 3).shifted(-0.12);
        QVERIFY(s.isVariable());
        QCOMPARE(s.count(), 3);
        QCOMPARE(s.time(0), 0.0);
        QVERIFY(std::abs(s.time(2) - 0.38) < 1e-12);
        QVERIFY(std::abs(s.endTime() - 0.42) < 1e-12);
        // Repeated timestamps are kept increasing.
        const FrameClock r = FrameClock::fromTimes({0.0, 0.04, 0.04, 0.2}, 25.0);
        QVERIFY(r.time(2) > r.time(1));
    }

    void cutPointsFallOnFrameBoundaries()
    {
        const FrameClock c = FrameClock::fromTimes({0.0, 0.04, 0.12, 0.16, 0.5, 0.54}, 25.0);
        QCOMPARE(c.boundaryAtOrBefore(0.3), 0.16);
        QCOMPARE(c.boundaryAtOrAfter(0.3), 0.5);
        QCOMPARE(c.boundaryAtOrAfter(0.12), 0.12);
        QCOMPARE(c.boundaryAtOrBefore(0.12), 0.12);
        QVERIFY(std::abs(c.boundaryAtOrAfter(0.56) - 0.58) < 1e-12); // the end of the last frame
        QCOMPARE(c.frameAtBoundary(0.16), 3);
        QCOMPARE(c.frameAtBoundary(c.endTime()), 6);
    }
};

QTEST_GUILESS_MAIN(TestFrameClock)
#include "tst_frameclock.moc"
