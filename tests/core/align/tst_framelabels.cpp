// Frame voting (docs/models.md §0): majority of the 100 Hz frames whose centres fall in the video
// frame, ties to the phone with the audio-frame centre nearest the video-frame centre.
#include "align/FrameLabels.h"

#include <QTest>

using namespace lipsync;

class TestFrameLabels : public QObject
{
    Q_OBJECT
private slots:
    void majorityAt25fps()
    {
        // Video frame 0 = [0, 0.04) holds audio centres 0.0125, 0.0225, 0.0325;
        // frame 1 = [0.04, 0.08) holds 0.0425 ... 0.0725.
        const Tier phones{"phones", {{0, 0.03, "A", false}, {0.03, 0.05, "B", false}, {0.05, 1.0, "C", false}}};
        const auto labels = voteFrameLabels(phones, FrameClock::uniform(25.0, 3));
        QCOMPARE(labels[0], std::string("A")); // A A B
        QCOMPARE(labels[1], std::string("C")); // B C C C
        QCOMPARE(labels[2], std::string("C"));
    }

    void tieGoesToNearestCentre()
    {
        // Frame 1 holds centres 0.0425 0.0525 | 0.0625 0.0725: 2-2. The video-frame centre is
        // 0.06; B's 0.0625 is nearer than A's 0.0525.
        const Tier phones{"phones", {{0, 0.058, "A", false}, {0.058, 1.0, "B", false}}};
        QCOMPARE(voteFrameLabels(phones, FrameClock::uniform(25.0, 2))[1], std::string("B"));
        // Mirror: A's nearest 0.0625 (0.0025 away) beats B's 0.0725.
        const Tier later{"phones", {{0, 0.068, "A", false}, {0.068, 1.0, "B", false}}};
        QCOMPARE(voteFrameLabels(later, FrameClock::uniform(25.0, 2))[1], std::string("A")); // A A A B: majority anyway
        const Tier split{"phones", {{0, 0.048, "A", false}, {0.048, 0.068, "B", false}, {0.068, 1, "C", false}}};
        // Centres: A(0.0425) B(0.0525) B(0.0625) C(0.0725) -> B majority.
        QCOMPARE(voteFrameLabels(split, FrameClock::uniform(25.0, 2))[1], std::string("B"));
        // 1-1-1-1 with four phones: C holds 0.0625, nearest to 0.06.
        const Tier four{"phones", {{0, 0.048, "A", false}, {0.048, 0.058, "B", false}, {0.058, 0.068, "C", false}, {0.068, 1, "D", false}}};
        QCOMPARE(voteFrameLabels(four, FrameClock::uniform(25.0, 2))[1], std::string("C"));
    }

    void ntscAndHighRates()
    {
        const Tier phones{"phones", {{0, 0.5, "sil", false}, {0.5, 1.0, "AA", false}}};
        const auto ntsc = voteFrameLabels(phones, FrameClock::uniform(29.97, 30));
        QCOMPARE(ntsc.size(), size_t(30));
        // Frame 14 = [0.4671, 0.5005): centres 0.4725, 0.4825, 0.4925 (sil) -> sil;
        // frame 15 = [0.5005, 0.5339): 0.5025 ... 0.5325 -> AA.
        QCOMPARE(ntsc[14], std::string("sil"));
        QCOMPARE(ntsc[15], std::string("AA"));
        // 200 fps: some video frames hold no audio-frame centre and take the phone at their own centre.
        const auto fast = voteFrameLabels(phones, FrameClock::uniform(200.0, 200));
        QCOMPARE(fast[99], std::string("sil"));
        QCOMPARE(fast[100], std::string("AA"));
        // Past the end of the tier: silence.
        QCOMPARE(voteFrameLabels(phones, FrameClock::uniform(25.0, 40))[39], std::string("sil"));
    }
};

QTEST_GUILESS_MAIN(TestFrameLabels)
#include "tst_framelabels.moc"
