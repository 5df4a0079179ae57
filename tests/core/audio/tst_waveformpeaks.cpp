// The peak pyramid must give exactly the brute-force min/max at every level and for any range,
// including ranges that start and end inside blocks and the short last block of each level.
#include "audio/WaveformPeaks.h"

#include <QRandomGenerator>
#include <QTest>

#include <algorithm>
#include <cmath>

using lipsync::Peak;
using lipsync::WaveformPeaks;

namespace {

std::vector<float> randomSignal(int n, quint32 seed)
{
    QRandomGenerator rng(seed);
    std::vector<float> s(std::size_t(n), 0.0f);
    for (int i = 0; i < n; ++i)
        s[std::size_t(i)] = float(std::sin(i * 0.01) * 0.5 + (rng.generateDouble() - 0.5) * 0.8);
    return s;
}

Peak bruteForce(const std::vector<float> &s, std::int64_t first, std::int64_t last)
{
    first = std::max<std::int64_t>(first, 0);
    last = std::min<std::int64_t>(last, std::int64_t(s.size()));
    if (first >= last)
        return {};
    const auto [lo, hi] = std::minmax_element(s.begin() + first, s.begin() + last);
    return {*lo, *hi};
}

} // namespace

class TestWaveformPeaks : public QObject
{
    Q_OBJECT
private slots:
    void levelsEqualBruteForce_data()
    {
        QTest::addColumn<int>("sampleCount");
        QTest::addColumn<int>("baseBlock");
        QTest::newRow("one second, base 16") << 16000 << 16;
        QTest::newRow("odd length, base 7") << 12345 << 7;
        QTest::newRow("shorter than a block") << 5 << 16;
        QTest::newRow("base 1") << 1000 << 1;
    }
    void levelsEqualBruteForce()
    {
        QFETCH(int, sampleCount);
        QFETCH(int, baseBlock);
        const std::vector<float> s = randomSignal(sampleCount, 7);
        const WaveformPeaks peaks(s, 16000, baseBlock);
        QVERIFY(peaks.levelCount() >= 1);
        QCOMPARE(peaks.level(peaks.levelCount() - 1).size(), std::size_t(1));
        for (int l = 0; l < peaks.levelCount(); ++l) {
            const std::int64_t size = peaks.blockSize(l);
            const std::vector<Peak> &level = peaks.level(l);
            QCOMPARE(std::int64_t(level.size()), (std::int64_t(s.size()) + size - 1) / size);
            for (std::size_t i = 0; i < level.size(); ++i) {
                const Peak expected = bruteForce(s, std::int64_t(i) * size, std::int64_t(i + 1) * size);
                if (!(level[i] == expected))
                    QFAIL(qPrintable(QStringLiteral("level %1 entry %2 differs").arg(l).arg(i)));
            }
        }
    }

    void rangesEqualBruteForce()
    {
        const std::vector<float> s = randomSignal(48000, 11);
        const WaveformPeaks peaks(s, 16000, 16);
        QRandomGenerator rng(3);
        for (int k = 0; k < 2000; ++k) {
            std::int64_t a = rng.bounded(int(s.size()) + 40) - 20;
            std::int64_t b = a + rng.bounded(k % 2 ? 40 : 30000);
            const Peak got = peaks.peak(a, b);
            const Peak expected = bruteForce(s, a, b);
            if (!(got == expected))
                QFAIL(qPrintable(QStringLiteral("range [%1, %2) differs").arg(a).arg(b)));
        }
        QVERIFY(peaks.peak(0, 0) == Peak{});
        QVERIFY(peaks.peak(0, peaks.sampleCount()) == bruteForce(s, 0, std::int64_t(s.size())));
    }

    void timeRangesAndEmpty()
    {
        const WaveformPeaks empty;
        QVERIFY(empty.isEmpty());
        QVERIFY(empty.peakInTime(0.0, 1.0) == Peak{});
        std::vector<float> s(1600, 0.0f);
        s[800] = 0.9f; // at 0.05 s
        s[900] = -0.4f; // at 0.05625 s
        const WaveformPeaks peaks(s, 16000);
        QCOMPARE(peaks.duration(), 0.1);
        QCOMPARE(peaks.peakInTime(0.04, 0.06).max, 0.9f);
        QCOMPARE(peaks.peakInTime(0.04, 0.06).min, -0.4f);
        QCOMPARE(peaks.peakInTime(0.0, 0.04).max, 0.0f);
    }
};

QTEST_GUILESS_MAIN(TestWaveformPeaks)
#include "tst_waveformpeaks.moc"
