// Sound in blocks to mono at another rate (io/SoundResampler.h), as a microphone delivers it: a
// 48 kHz stereo tone comes out at 16 kHz, one third as many samples, at its level; a 12 kHz tone,
// above the 8 kHz the output can hold, is filtered out instead of folding down to 4 kHz; the
// blocks' sizes change nothing.
#include "io/SoundResampler.h"
#include "util/Error.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

// `seconds` of a stereo tone at 48 kHz, both channels alike, amplitude 0.5.
std::vector<float> stereoTone(double hertz, double seconds)
{
    const int frames = int(seconds * 48000);
    std::vector<float> out(size_t(2 * frames));
    for (int i = 0; i < frames; ++i)
        out[size_t(2 * i)] = out[size_t(2 * i + 1)] = float(0.5 * std::sin(2 * M_PI * hertz * i / 48000.0));
    return out;
}

std::vector<float> resample(const std::vector<float> &stereo, size_t block)
{
    SoundResampler r(48000, 2, 16000);
    std::vector<float> out;
    for (size_t at = 0; at < stereo.size() / 2; at += block) {
        const std::vector<float> part = r.push(stereo.data() + 2 * at, std::min(block, stereo.size() / 2 - at));
        out.insert(out.end(), part.begin(), part.end());
    }
    const std::vector<float> rest = r.flush();
    out.insert(out.end(), rest.begin(), rest.end());
    return out;
}

double rms(const std::vector<float> &x, size_t from, size_t to)
{
    double sum = 0;
    for (size_t i = from; i < to; ++i)
        sum += double(x[i]) * x[i];
    return std::sqrt(sum / double(to - from));
}

} // namespace

class TestSoundResampler : public QObject
{
    Q_OBJECT
private slots:
    void toneKeepsItsLevel()
    {
        const std::vector<float> out = resample(stereoTone(440, 1.0), 480);
        QVERIFY2(std::abs(int(out.size()) - 16000) <= 2, qPrintable(QString::number(out.size())));
        const double level = rms(out, 1000, 15000);
        QVERIFY2(std::abs(level - 0.5 / std::sqrt(2.0)) < 0.01, qPrintable(QString::number(level)));
    }

    void aboveTheOutputsBandIsFilteredOut()
    {
        const std::vector<float> out = resample(stereoTone(12000, 1.0), 480);
        const double level = rms(out, 1000, 15000);
        QVERIFY2(level < 0.02, qPrintable(QString::number(level))); // 0.35 if it folded down to 4 kHz
    }

    void blocksChangeNothing()
    {
        const std::vector<float> tone = stereoTone(1000, 0.5);
        const std::vector<float> a = resample(tone, 37), b = resample(tone, 24000);
        QCOMPARE(a.size(), b.size());
        float worst = 0;
        for (size_t i = 0; i < a.size(); ++i)
            worst = std::max(worst, std::abs(a[i] - b[i]));
        QVERIFY2(worst < 1e-5f, qPrintable(QString::number(worst)));
    }

    void refusesNonsense()
    {
        QVERIFY_THROWS_EXCEPTION(Error, SoundResampler(0, 2, 16000));
        QVERIFY_THROWS_EXCEPTION(Error, SoundResampler(48000, 0, 16000));
    }
};

QTEST_GUILESS_MAIN(TestSoundResampler)
#include "tst_soundresampler.moc"
