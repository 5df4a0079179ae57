// The display spectrogram: HTK's frame count and grid, a pure tone peaks in its own bin in every
// frame (Hann leakage stays far below it), silence sits at the floor, and bad options are refused.
#include "audio/Spectrogram.h"
#include "util/Error.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

class TestSpectrogram : public QObject
{
    Q_OBJECT
private slots:
    void toneAndGrid()
    {
        const int rate = 16000;
        std::vector<float> samples(static_cast<size_t>(rate)); // 1 s of 1 kHz at half scale
        for (size_t i = 0; i < samples.size(); ++i)
            samples[i] = 0.5f * float(std::sin(2 * M_PI * 1000.0 * double(i) / rate));
        const Spectrogram s = Spectrogram::compute(samples, rate);
        QCOMPARE(s.frameCount(), (16000 - 400) / 160 + 1); // 98, as HTK counts frames
        QCOMPARE(s.binCount(), 257);                        // 512-point FFT
        QCOMPARE(s.binFrequency(32), 1000.0);
        QCOMPARE(s.frameCentre(0), 0.0125);
        for (int f = 0; f < s.frameCount(); ++f) {
            Eigen::Index peak = 0;
            const float top = s.powerDb().row(f).maxCoeff(&peak);
            QCOMPARE(int(peak), 32);
            QVERIFY(top - s.powerDb()(f, 100) > 60.0f); // far from the tone: leakage only
        }
        QVERIFY(std::abs(s.maxDb() - s.powerDb()(10, 32)) < 0.5f);
    }

    void silenceAtTheFloorAndShortInput()
    {
        const Spectrogram silent = Spectrogram::compute(std::vector<float>(1600, 0.0f), 16000);
        QCOMPARE(silent.frameCount(), 8);
        QVERIFY(std::abs(silent.maxDb() - (-120.0f)) < 1e-3f);
        QVERIFY(Spectrogram::compute(std::vector<float>(100, 0.1f), 16000).isEmpty());
        QVERIFY_THROWS_EXCEPTION(Error, Spectrogram::compute({0.0f}, 0));
    }
};

QTEST_GUILESS_MAIN(TestSpectrogram)
#include "tst_spectrogram.moc"
