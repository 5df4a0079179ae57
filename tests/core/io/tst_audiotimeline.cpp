// AudioTimeline and AudioDecoder: decoded audio placed by its timestamps. A late start and gaps
// become silence at the right samples, overlaps are dropped, a frame without a timestamp follows
// on, a broken timestamp past the container's end is not filled. On a real file (a stream
// starting 0.5 s late, tests/data/media/timing) the decoded speech lies 0.5 s after the clean
// original's.
#include "io/AudioDecoder.h"
#include "io/AudioTimeline.h"

#include <QTest>

#include <cmath>

using lipsync::AudioBuffer;
using lipsync::AudioDecoder;
using lipsync::AudioTimeline;

namespace {
const std::string kTiming = LIPSYNC_SOURCE_DIR "/tests/data/media/timing/";
} // namespace

class TestAudioTimeline : public QObject
{
    Q_OBJECT
private slots:
    void placesFramesByTheirTimestamps()
    {
        AudioTimeline t(10.0);
        // The first frame at 0.5 s: silence before it, not counted as a gap.
        AudioTimeline::Placement p = t.place(0.5, 1000, 1000);
        QVERIFY(p.silenceBefore);
        QCOMPARE(p.start, 0.5);
        QCOMPARE(t.firstTime(), 0.5);
        QCOMPARE(t.gapCount(), 0);
        // Contiguous, within the tolerance of timestamp rounding.
        p = t.place(1.5004, 1000, 1000);
        QVERIFY(!p.silenceBefore);
        QCOMPARE(p.start, 1.5);
        // A 48 ms gap.
        p = t.place(2.548, 452, 1000);
        QVERIFY(p.silenceBefore);
        QCOMPARE(t.gapCount(), 1);
        QVERIFY(std::abs(t.gapSeconds() - 0.048) < 1e-12);
        QVERIFY(std::abs(t.gaps().front().at - 2.5) < 1e-12);
        // An overlap of 100 samples: dropped.
        p = t.place(2.9, 200, 1000);
        QCOMPARE(p.skip, 100LL);
        QCOMPARE(t.overlapCount(), 1);
        QVERIFY(std::abs(t.endTime() - 3.1) < 1e-12);
        // No timestamp: follows on.
        p = t.place(NAN, 100, 1000);
        QVERIFY(std::abs(p.start - 3.1) < 1e-12);
        // A jump far past the container's end is a discontinuity: not filled.
        p = t.place(3600.0, 100, 1000);
        QVERIFY(!p.silenceBefore);
        QCOMPARE(t.discontinuities(), 1);
        QVERIFY(std::abs(t.endTime() - 3.3) < 1e-12);
    }

    void samplesBeforeTheStartAreDropped()
    {
        AudioTimeline t;
        const AudioTimeline::Placement p = t.place(-0.01, 100, 1000); // priming before the file's start
        QCOMPARE(p.skip, 10LL);
        QCOMPARE(t.firstTime(), 0.0);
        QCOMPARE(t.overlapCount(), 0);
    }

    // The late stream's sound, decoded, is the clean original's 0.5 s later (the energy envelope
    // correlates best at that lag, within 5 ms), with silence before it.
    void decodedSoundSitsOnTheTimeline()
    {
        const AudioBuffer clean = AudioDecoder::decode(kTiming + "clean.mp4", 16000);
        const AudioBuffer late = AudioDecoder::decode(kTiming + "audio_late_0.5s.mp4", 16000);
        QCOMPARE(late.startTime, 0.0);
        for (size_t i = 0; i < 7000; ++i)
            QCOMPARE(late.samples[i], 0.0f);
        auto envelope = [](const AudioBuffer &a) {
            std::vector<double> e(a.samples.size() / 16, 0.0); // 1 ms
            for (size_t i = 0; i < e.size(); ++i)
                for (size_t k = 0; k < 16; ++k)
                    e[i] += std::abs(a.samples[16 * i + k]);
            return e;
        };
        const std::vector<double> a = envelope(clean), b = envelope(late);
        int best = -1;
        double bestScore = -1;
        for (int lag = 400; lag <= 600; ++lag) {
            double score = 0;
            for (size_t i = 0; i < a.size() && i + size_t(lag) < b.size(); ++i)
                score += a[i] * b[i + size_t(lag)];
            if (score > bestScore) {
                bestScore = score;
                best = lag;
            }
        }
        QVERIFY2(std::abs(best - 500) <= 5, qPrintable(QString::number(best)));
        // The joined clips: 48 ms of silence at each join, the sound ending at 8.952 s.
        const AudioBuffer joined = AudioDecoder::decode(kTiming + "joined_gaps_48ms.mkv", 16000);
        QVERIFY(std::abs(joined.duration() - 8.952) < 0.002);
        for (size_t i = size_t(2.955 * 16000); i < size_t(2.997 * 16000); ++i)
            QCOMPARE(joined.samples[i], 0.0f);
    }
};

QTEST_GUILESS_MAIN(TestAudioTimeline)
#include "tst_audiotimeline.moc"
