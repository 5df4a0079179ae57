// Video frames and audio PCM (libav) (libav) from a GRID demo clip and the small files in
// tests/data/media; every damaged file must give a lipsync::Error naming it.
#include "io/AudioDecoder.h"
#include "io/VideoReader.h"
#include "util/Error.h"

#include <QDir>
#include <QTest>

#include <algorithm>
#include <cmath>
#include <numeric>

using namespace lipsync;

namespace {

std::string gridClip()
{
    return LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
}

std::string media(const char *name)
{
    return std::string(LIPSYNC_TEST_DATA "/media/") + name;
}

double rms(const std::vector<float> &x)
{
    double sum = 0;
    for (float v : x)
        sum += double(v) * v;
    return x.empty() ? 0.0 : std::sqrt(sum / double(x.size()));
}

bool withinUnit(const std::vector<float> &x)
{
    return std::all_of(x.begin(), x.end(), [](float v) { return std::isfinite(v) && std::abs(v) <= 1.0f; });
}

} // namespace

class TestMediaDecode : public QObject
{
    Q_OBJECT

private slots:
    void gridVideoProperties()
    {
        VideoReader reader(gridClip());
        QCOMPARE(reader.frameCount(), 75);
        QCOMPARE(reader.frameRate(), 25.0);
        QCOMPARE(reader.width(), 360);
        QCOMPARE(reader.height(), 288);
        QCOMPARE(reader.path(), gridClip());
        QCOMPARE(int(reader.timestamps().size()), 75);
        // Real presentation times: 40 ms apart from 0.
        for (int i = 0; i < 75; ++i)
            QVERIFY2(std::abs(reader.timestamp(i) - i * 0.04) < 1e-6, qPrintable(QString::number(i)));
        QVERIFY(std::abs(reader.timestamp(75) - 3.0) < 1e-6); // extrapolated
    }

    void gridSequentialAndRandomAccess()
    {
        VideoReader reader(gridClip());
        std::vector<cv::Mat> sequential;
        for (int i = 0; i < reader.frameCount(); ++i) {
            cv::Mat image = reader.frame(i);
            QCOMPARE(image.type(), CV_8UC3);
            QCOMPARE(image.cols, 360);
            QCOMPARE(image.rows, 288);
            sequential.push_back(image);
        }
        // Frames are independent copies and differ (a person talking).
        QVERIFY(cv::norm(sequential[0], sequential[40], cv::NORM_L1) > 0);
        QVERIFY(cv::mean(sequential[37])[0] > 10.0);

        // Backwards, far forward, near start (where OpenCV's own seek lands off by frames on
        // GRID), and the very last frame: all equal to the sequential decode.
        for (int index : {74, 3, 60, 0, 50, 49, 12, 13, 1, 70, 20, 21, 72}) {
            const cv::Mat image = reader.frame(index);
            QVERIFY2(cv::norm(image, sequential[size_t(index)], cv::NORM_INF) == 0,
                     qPrintable(QStringLiteral("frame %1 differs after random access").arg(index)));
        }
        // A second reader seeking straight to a far frame agrees too.
        VideoReader other(gridClip());
        QVERIFY(cv::norm(other.frame(66), sequential[66], cv::NORM_INF) == 0);
    }

    // Every clip of the demo and the HD footage: frames reached by seeking, backwards and far
    // ahead, are the frames of the sequential decode (seeks land on key frames and are placed
    // by their timestamps).
    void randomAccessEqualsSequential_data()
    {
        QTest::addColumn<QString>("path");
        const QDir demo(QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media"));
        for (const QString &name : demo.entryList({QStringLiteral("*.mpg")}, QDir::Files, QDir::Name))
            QTest::newRow(qPrintable(name)) << demo.filePath(name);
        const QDir hd(QString::fromStdString(media("hd")));
        for (const QString &name : hd.entryList({QStringLiteral("*.mp4")}, QDir::Files, QDir::Name))
            QTest::newRow(qPrintable(name)) << hd.filePath(name);
    }

    void randomAccessEqualsSequential()
    {
        QFETCH(QString, path);
        VideoReader reader(path.toStdString());
        std::vector<cv::Mat> sequential;
        for (int i = 0; i < reader.frameCount(); ++i)
            sequential.push_back(reader.frame(i));
        const int n = reader.frameCount();
        for (int index : {n - 1, n / 2, 2, n - 30, 55, n / 3, n / 3 + 1, 0, n - 2}) {
            index = std::clamp(index, 0, n - 1);
            QVERIFY2(cv::norm(reader.frame(index), sequential[size_t(index)], cv::NORM_INF) == 0,
                     qPrintable(QStringLiteral("frame %1 of %2 differs after random access").arg(index).arg(n)));
        }
    }

    void frameOutOfRange()
    {
        VideoReader reader(gridClip());
        for (int index : {-1, 75, 1000}) {
            try {
                reader.frame(index);
                QFAIL("expected lipsync::Error");
            } catch (const Error &e) {
                QCOMPARE(e.file(), gridClip());
                QVERIFY(QString::fromStdString(e.reason()).contains(QLatin1String("out of range")));
            }
        }
        QVERIFY(!reader.frame(74).empty()); // the reader still works after the errors
    }

    void ntscFrameRate()
    {
        // 29.97 fps (30000/1001), H.264 in MP4, no audio.
        VideoReader reader(media("no_audio_29.97fps.mp4"));
        QCOMPARE(reader.frameCount(), 15);
        QVERIFY(std::abs(reader.frameRate() - 30000.0 / 1001.0) < 1e-9);
        for (int i = 0; i < reader.frameCount(); ++i)
            QVERIFY(std::abs(reader.timestamp(i) - i * 1001.0 / 30000.0) < 1e-3);
        const cv::Mat last = reader.frame(14);
        QCOMPARE(last.cols, 360);
        QCOMPARE(last.rows, 288);
        QVERIFY(cv::norm(reader.frame(2), reader.frame(2), cv::NORM_INF) == 0);
    }

    void gridAudioAtRequestedRate()
    {
        const AudioBuffer audio = AudioDecoder::decode(gridClip(), 16000);
        QCOMPARE(audio.sampleRate, 16000);
        // ~3.0 s: 114 MP2 frames of 1152 samples at 44.1 kHz = 2.978 s.
        QVERIFY2(std::abs(double(audio.samples.size()) - 48000.0) <= 480.0,
                 qPrintable(QString::number(audio.samples.size())));
        QVERIFY(std::abs(audio.duration() - 3.0) < 0.03);
        QCOMPARE(audio.startTime, 0.0);
        QVERIFY(withinUnit(audio.samples));
        QVERIFY(rms(audio.samples) > 0.01); // speech, not silence
    }

    // decodeRanges hands out exactly decode()'s samples of each range, in order, at the asked or
    // the stream's own rate; a range past the sound's end gets what there is; ranges out of
    // order are refused.
    void rangesAreSlicesOfTheWholeDecode_data()
    {
        QTest::addColumn<int>("rate");
        QTest::newRow("stream's own (44.1 kHz)") << 0;
        QTest::newRow("16 kHz") << 16000;
    }

    void rangesAreSlicesOfTheWholeDecode()
    {
        QFETCH(int, rate);
        const AudioBuffer whole = AudioDecoder::decode(gridClip(), rate);
        const std::vector<std::pair<double, double>> ranges{{0.0, 0.4}, {0.5, 1.25}, {1.25, 1.3}, {2.0, 2.9}, {2.95, 4.0}};
        std::vector<size_t> order;
        AudioDecoder::decodeRanges(gridClip(), rate, ranges, [&](size_t k, AudioBuffer piece) {
            order.push_back(k);
            QCOMPARE(piece.sampleRate, whole.sampleRate);
            const size_t from = size_t(std::llround(ranges[k].first * whole.sampleRate));
            const size_t to = std::min(whole.samples.size(), size_t(std::llround(ranges[k].second * whole.sampleRate)));
            QCOMPARE(piece.samples.size(), to - std::min(from, to));
            for (size_t i = 0; i < piece.samples.size(); ++i)
                if (piece.samples[i] != whole.samples[from + i])
                    QFAIL(qPrintable(QStringLiteral("range %1, sample %2").arg(k).arg(i)));
            QCOMPARE(piece.startTime, double(from) / whole.sampleRate);
        });
        QCOMPARE(order, (std::vector<size_t>{0, 1, 2, 3, 4}));
        QVERIFY_THROWS_EXCEPTION(Error, AudioDecoder::decodeRanges(gridClip(), rate, {{1.0, 2.0}, {0.5, 0.7}},
                                                                   [](size_t, AudioBuffer) {}));
    }

    void resamplingKeepsLengthAndShape()
    {
        const AudioBuffer native = AudioDecoder::decode(gridClip(), 0);
        QCOMPARE(native.sampleRate, 44100);
        QCOMPARE(int(native.samples.size()), 114 * 1152);
        for (int rate : {8000, 16000, 22050, 48000}) {
            const AudioBuffer resampled = AudioDecoder::decode(gridClip(), rate);
            QCOMPARE(resampled.sampleRate, rate);
            const double expected = double(native.samples.size()) * rate / 44100.0;
            QVERIFY2(std::abs(double(resampled.samples.size()) - expected) <= 2.0,
                     qPrintable(QStringLiteral("%1 Hz: %2 samples, expected %3")
                                    .arg(rate).arg(resampled.samples.size()).arg(expected)));
            // Same loudness (speech energy lies well below 4 kHz).
            QVERIFY(std::abs(rms(resampled.samples) / rms(native.samples) - 1.0) < 0.1);
        }
    }

    void upsamplingIsAligned()
    {
        // 8 kHz WAV doubled to 16 kHz: every second output sample is the input sample (no delay).
        const AudioBuffer low = AudioDecoder::decode(media("short_400ms_8k.wav"), 0);
        QCOMPARE(low.sampleRate, 8000);
        QCOMPARE(int(low.samples.size()), 3200);
        const AudioBuffer high = AudioDecoder::decode(media("short_400ms_8k.wav"), 16000);
        QCOMPARE(int(high.samples.size()), 6400);
        double dot = 0, a = 0, b = 0;
        for (size_t i = 0; i < low.samples.size(); ++i) {
            dot += double(low.samples[i]) * high.samples[2 * i];
            a += double(low.samples[i]) * low.samples[i];
            b += double(high.samples[2 * i]) * high.samples[2 * i];
        }
        QVERIFY(a > 0);
        QVERIFY2(dot / std::sqrt(a * b) > 0.95, qPrintable(QString::number(dot / std::sqrt(a * b))));
    }

    void flacStereoMixedToMono()
    {
        const AudioBuffer audio = AudioDecoder::decode(media("short_400ms_22k_stereo.flac"), 16000);
        QCOMPARE(audio.sampleRate, 16000);
        QCOMPARE(int(audio.samples.size()), 6400);
        QVERIFY(withinUnit(audio.samples));
        QVERIFY(rms(audio.samples) > 0.005);
    }

    void audioLessFile()
    {
        try {
            AudioDecoder::decode(media("no_audio_29.97fps.mp4"));
            QFAIL("expected lipsync::Error");
        } catch (const Error &e) {
            QCOMPARE(e.file(), media("no_audio_29.97fps.mp4"));
            QCOMPARE(QString::fromStdString(e.reason()), QStringLiteral("no audio stream"));
        }
    }

    void audioOnlyFileHasNoVideo()
    {
        try {
            VideoReader reader(media("short_400ms_8k.wav"));
            QFAIL("expected lipsync::Error");
        } catch (const Error &e) {
            QCOMPARE(QString::fromStdString(e.reason()), QStringLiteral("no video stream"));
            QVERIFY(QString::fromUtf8(e.what()).contains(QLatin1String("short_400ms_8k.wav")));
        }
    }

    void badFilesNameTheFile_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("reason");
        QTest::newRow("missing") << "does_not_exist.mpg" << "not found";
        QTest::newRow("empty") << "empty.mpg" << "empty";
        QTest::newRow("truncated mpg") << "truncated_30pct.mpg" << "truncated";
        QTest::newRow("text as mpg") << "text_renamed.mpg" << "unsupported";
        QTest::newRow("truncated wav") << "truncated_50pct.wav" << "truncated";
        QTest::newRow("truncated mp4") << "truncated_60pct.mp4" << "truncated";
        QTest::newRow("folder") << "" << "not a regular file";
    }

    void badFilesNameTheFile()
    {
        QFETCH(QString, name);
        QFETCH(QString, reason);
        const std::string path = media(name.toUtf8().constData());
        for (int reader = 0; reader < 2; ++reader) {
            try {
                if (reader == 0)
                    VideoReader video(path);
                else
                    AudioDecoder::decode(path, 16000);
                QFAIL("expected lipsync::Error");
            } catch (const Error &e) {
                QCOMPARE(e.file(), path);
                const QString what = QString::fromUtf8(e.what());
                QVERIFY2(what.startsWith(QString::fromStdString(path)), qPrintable(what));
                QVERIFY2(what.contains(reason), qPrintable(what));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestMediaDecode)
#include "tst_mediadecode.moc"
