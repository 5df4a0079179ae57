// Microphone bytes to the live session's samples (live/SampleConverter): a device's own format,
// 16-bit stereo at 48 kHz, in blocks that cut frames in two, comes out as mono at 16 kHz (one
// third as many samples, at the tone's level); mono float at 16 kHz passes through unchanged.
#include "live/SampleConverter.h"

#include <QTest>

#include <cmath>
#include <cstring>

using namespace lipsync::studio;

class TestSampleConverter : public QObject
{
    Q_OBJECT
private slots:
    void deviceFormatToSessionSamples()
    {
        QAudioFormat format;
        format.setSampleRate(48000);
        format.setChannelCount(2);
        format.setSampleFormat(QAudioFormat::Int16);
        QByteArray bytes;
        for (int i = 0; i < 48000; ++i) {
            const qint16 s = qint16(std::lround(16384 * std::sin(2 * M_PI * 440 * i / 48000.0)));
            bytes.append(reinterpret_cast<const char *>(&s), 2).append(reinterpret_cast<const char *>(&s), 2);
        }
        SampleConverter converter(format, 16000);
        std::vector<float> out;
        for (qsizetype at = 0; at < bytes.size(); at += 1001) { // 1001 bytes: frames cut in two
            const std::vector<float> part = converter.convert(bytes.constData() + at, std::min<qsizetype>(1001, bytes.size() - at));
            out.insert(out.end(), part.begin(), part.end());
        }
        QVERIFY2(std::abs(int(out.size()) - 16000) <= 40, qPrintable(QString::number(out.size())));
        double sum = 0;
        for (size_t i = 1000; i < 15000; ++i)
            sum += double(out[i]) * out[i];
        QVERIFY(std::abs(std::sqrt(sum / 14000) - 0.5 / std::sqrt(2.0)) < 0.01);
    }

    void sessionFormatPassesThrough()
    {
        QAudioFormat format;
        format.setSampleRate(16000);
        format.setChannelCount(1);
        format.setSampleFormat(QAudioFormat::Float);
        const std::vector<float> in{0.25f, -0.5f, 0.75f, 1.0f};
        SampleConverter converter(format, 16000);
        QCOMPARE(converter.convert(reinterpret_cast<const char *>(in.data()), qsizetype(in.size() * 4)), in);
    }
};

QTEST_GUILESS_MAIN(TestSampleConverter)
#include "tst_sampleconverter.moc"
