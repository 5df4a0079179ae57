// One recording's sound for every step of a job (io/RecordingSound.h): before its own rate is
// decoded, a rate asked for is decoded from the file exactly as AudioDecoder does; once own() has
// decoded it (kept, one decode), other rates are resampled from it: the same length and place on
// the timeline (a sound that starts 0.5 s late keeps its leading silence) and the same samples to
// within the resampler's filter (the GRID clip at 16 kHz correlates > 0.9999 with its direct
// decode).
#include "io/AudioDecoder.h"
#include "io/RecordingSound.h"
#include "util/Error.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

const std::string kClip = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
const std::string kLate = LIPSYNC_SOURCE_DIR "/tests/data/media/timing/audio_late_0.5s.mp4";

double correlation(const std::vector<float> &a, const std::vector<float> &b)
{
    const size_t n = std::min(a.size(), b.size());
    double ab = 0, aa = 0, bb = 0;
    for (size_t i = 0; i < n; ++i) {
        ab += double(a[i]) * b[i];
        aa += double(a[i]) * a[i];
        bb += double(b[i]) * b[i];
    }
    return ab / std::sqrt(aa * bb);
}

} // namespace

class TestRecordingSound : public QObject
{
    Q_OBJECT
private slots:
    void beforeItsOwnRateIsDecodedARateIsDecodedExactly()
    {
        const RecordingSound sound(kClip);
        QCOMPARE(sound.at(16000)->samples, AudioDecoder::decode(kClip, 16000).samples);
    }

    void ownIsDecodedOnceAndOtherRatesResampledFromIt()
    {
        const RecordingSound sound(kClip);
        const auto own = sound.own();
        QCOMPARE(own.get(), sound.own().get()); // kept: one decode
        QCOMPARE(own.get(), sound.at(0).get());
        QCOMPARE(own.get(), sound.at(own->sampleRate).get());
        QCOMPARE(own->samples, AudioDecoder::decode(kClip, 0).samples);
        QVERIFY(own->sampleRate > 16000);

        const auto resampled = sound.at(16000);
        const AudioBuffer direct = AudioDecoder::decode(kClip, 16000);
        QCOMPARE(resampled->sampleRate, 16000);
        QVERIFY2(std::abs(double(resampled->samples.size()) - double(direct.samples.size())) <= 2,
                 qPrintable(QStringLiteral("%1 vs %2").arg(resampled->samples.size()).arg(direct.samples.size())));
        const double r = correlation(resampled->samples, direct.samples);
        QVERIFY2(r > 0.9999, qPrintable(QString::number(r, 'g', 8)));
        QVERIFY(resampled.get() != sound.at(16000).get()); // not kept
    }

    void aLateSoundKeepsItsPlace()
    {
        const RecordingSound sound(kLate);
        sound.own();
        const auto resampled = sound.at(16000);
        const AudioBuffer direct = AudioDecoder::decode(kLate, 16000);
        QCOMPARE(resampled->startTime, direct.startTime);
        QVERIFY(std::abs(double(resampled->samples.size()) - double(direct.samples.size())) <= 2);
        // Silence for the first half second, as decoded directly.
        double early = 0;
        for (size_t i = 0; i < 7000; ++i)
            early = std::max(early, double(std::abs(resampled->samples[i])));
        QVERIFY2(early < 1e-3, qPrintable(QString::number(early)));
        QVERIFY(correlation(resampled->samples, direct.samples) > 0.999);
    }

    void aMissingFileIsNamed()
    {
        const RecordingSound sound("/nonexistent/clip.wav");
        try {
            sound.own();
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY(QString::fromStdString(e.what()).contains(QStringLiteral("/nonexistent/clip.wav")));
        }
    }
};

QTEST_MAIN(TestRecordingSound)
#include "tst_recordingsound.moc"
