// MP4 export read back as a player reads it: h264 + aac streams, frame count, durations, picture
// fidelity, sound/picture synchronisation measured on decoded content, and the atomic-write
// guarantees (cancel, errors, unwritable paths).
#include "render/VideoExporter.h"

#include "MediaProbe.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A moving pattern: a gradient background and a square that moves one step per frame, so every
// frame differs. Frames from `flashFrom` on carry a large white patch (the visual sync event).
cv::Mat patternFrame(int i, int width = 360, int height = 288, int flashFrom = -1)
{
    cv::Mat frame(height, width, CV_8UC3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            frame.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(x * 255 / width), uchar(y * 255 / height), 60);
    const int s = 40;
    const int x0 = (i * 6) % (width - s);
    cv::rectangle(frame, cv::Rect(x0, height / 3, s, s), cv::Scalar(20, 20, 230), cv::FILLED);
    if (flashFrom >= 0 && i >= flashFrom)
        cv::rectangle(frame, cv::Rect(0, 0, width, height / 2), cv::Scalar(255, 255, 255), cv::FILLED);
    return frame;
}

// A quiet 220 Hz tone; from `burstAt` seconds on a loud 1 kHz tone (the audible sync event).
AudioBuffer tone(double seconds, int rate = 16000, double burstAt = -1)
{
    AudioBuffer audio;
    audio.sampleRate = rate;
    audio.samples.resize(size_t(std::lround(seconds * rate)));
    for (size_t n = 0; n < audio.samples.size(); ++n) {
        const double t = double(n) / rate;
        audio.samples[n] = float(burstAt >= 0 && t >= burstAt ? 0.6 * std::sin(2 * kPi * 1000 * t)
                                                              : 0.02 * std::sin(2 * kPi * 220 * t));
    }
    return audio;
}

double psnr(const cv::Mat &a, const cv::Mat &b)
{
    return cv::PSNR(a, b);
}

} // namespace

class TestVideoExporter : public QObject
{
    Q_OBJECT

private slots:
    void exportsH264AndAacAndReadsBack()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("clip.mp4").toStdString();
        const AudioBuffer audio = tone(2.0);
        Feedback feedback;
        double lastProgress = 0;
        feedback.onProgress = [&](double p) { lastProgress = p; };
        exportVideo(path, 50, [](int i) { return patternFrame(i); }, &audio, feedback);
        QCOMPARE(lastProgress, 1.0);

        const MediaProbe probe = MediaProbe::read(path, true);
        QCOMPARE(probe.videoStreams, 1);
        QCOMPARE(probe.audioStreams, 1);
        QCOMPARE(probe.videoStreamIndex, 0); // video first, as players and editors expect
        QCOMPARE(probe.videoCodec, AV_CODEC_ID_H264);
        QCOMPARE(probe.audioCodec, AV_CODEC_ID_AAC);
        QCOMPARE(probe.width, 360);
        QCOMPARE(probe.height, 288);
        QCOMPARE(probe.sampleRate, 16000);
        QCOMPARE(probe.videoPackets, 50);
        QCOMPARE(int(probe.frameTimes.size()), 50);
        const double frame = 1.0 / 25;
        // Frames are presented at i/25 exactly, starting at 0.
        for (int i = 0; i < 50; ++i)
            QVERIFY2(std::abs(probe.frameTimes[size_t(i)] - i * frame) < 1e-3,
                     qPrintable(QString("frame %1 at %2 s").arg(i).arg(probe.frameTimes[size_t(i)])));
        QVERIFY(std::abs(probe.videoStart) < 1e-3);
        QVERIFY(std::abs(probe.audioStart - probe.videoStart) < frame);
        QVERIFY(std::abs(probe.firstAudioTime) < 1e-3);
        QVERIFY2(std::abs(probe.videoDuration - 2.0) < frame, qPrintable(QString::number(probe.videoDuration)));
        QVERIFY2(std::abs(probe.audioDuration - 2.0) < frame, qPrintable(QString::number(probe.audioDuration)));
        QVERIFY2(std::abs(probe.containerDuration - 2.0) < frame,
                 qPrintable(QString::number(probe.containerDuration)));
        // All the sound is there. The stream's duration (edit list) is exact; a plain decoder
        // also returns the padding of the last AAC frame (< 1024 samples).
        QVERIFY2(probe.audio.size() >= 32000 && probe.audio.size() < 32000 + 1024,
                 qPrintable(QString("%1 samples").arg(probe.audio.size())));
        // Picture fidelity at crf 20.
        for (int i : {0, 17, 49})
            QVERIFY2(psnr(probe.frames[size_t(i)], patternFrame(i)) > 30.0,
                     qPrintable(QString("frame %1: PSNR %2").arg(i).arg(psnr(probe.frames[size_t(i)], patternFrame(i)))));
        // Nothing but the file itself is left in the folder.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1);
    }

    // A real GRID clip with its own sound (44.1 kHz MP2, 2.98 s against 3 s of video): the export
    // keeps the audio's rate, every frame, and the clip's duration (the sound continued with
    // silence to the last frame's end).
    void gridClipWithItsOwnSound()
    {
        const std::string clip = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
        VideoReader reader(clip);
        const AudioBuffer audio = AudioDecoder::decode(clip, 0);
        QTemporaryDir dir;
        const std::string path = dir.filePath("bbaf2n.mp4").toStdString();
        Feedback feedback;
        exportVideo(path, reader.frameCount(), [&](int i) { return reader.frame(i); }, &audio, feedback);

        const MediaProbe probe = MediaProbe::read(path, true);
        QCOMPARE(probe.videoCodec, AV_CODEC_ID_H264);
        QCOMPARE(probe.audioCodec, AV_CODEC_ID_AAC);
        QCOMPARE(probe.sampleRate, audio.sampleRate);
        const double frame = 1.0 / 25, aacFrame = 1024.0 / audio.sampleRate;
        QCOMPARE(probe.videoPackets, reader.frameCount());
        QVERIFY2(std::abs(probe.containerDuration - 3.0) < aacFrame,
                 qPrintable(QString("%1 vs 3.0").arg(probe.containerDuration)));
        QVERIFY(std::abs(probe.videoDuration - 3.0) < 1e-6);
        QVERIFY2(std::abs(probe.audioDuration - 3.0) < aacFrame, qPrintable(QString::number(probe.audioDuration)));
        QVERIFY(std::abs(probe.audioStart - probe.videoStart) < frame);
        const double quality = psnr(probe.frames[40], reader.frame(40));
        QVERIFY2(quality > 30.0, qPrintable(QString::number(quality)));
    }

    // Colours survive export and decoding: a GRID clip exported losslessly reads back at the same
    // colours, and exported again (an export of an export) they do not drift. swscale's fast
    // paths, on one side or the other, darkened every pass by about 1.7 levels.
    void coloursSurviveTheRoundTrip_data()
    {
        QTest::addColumn<int>("crf");
        QTest::addColumn<double>("drift");
        QTest::newRow("lossless") << 0 << 0.25;
        QTest::newRow("crf 20") << 20 << 1.0;
    }

    void coloursSurviveTheRoundTrip()
    {
        QFETCH(int, crf);
        QFETCH(double, drift);
        std::string source = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
        const cv::Scalar original = cv::mean(VideoReader(source).frame(40));
        QTemporaryDir dir;
        VideoExportOptions options;
        options.crf = crf;
        Feedback feedback;
        for (int pass = 1; pass <= 2; ++pass) {
            VideoReader reader(source);
            const std::string out = dir.filePath(QStringLiteral("pass%1.mp4").arg(pass)).toStdString();
            exportVideo(out, reader.frameCount(), [&](int i) { return reader.frame(i); }, nullptr, feedback, options);
            const cv::Mat decoded = VideoReader(out).frame(40);
            const cv::Scalar mean = cv::mean(decoded);
            for (int c = 0; c < 3; ++c)
                QVERIFY2(std::abs(mean[c] - original[c]) < drift,
                         qPrintable(QStringLiteral("pass %1, channel %2: %3 against %4")
                                        .arg(pass).arg(c).arg(mean[c]).arg(original[c])));
            if (crf == 0) {
                const double quality = psnr(decoded, reader.frame(40));
                QVERIFY2(quality > 40.0, qPrintable(QString::number(quality)));
            }
            source = out;
        }
    }

    // Lossless with colour at full resolution (what the realism report's observer encodes): the
    // first pass differs from the source only by the rounding of RGB to YUV and back, and a second
    // pass of what the first gave back changes almost nothing (a level, in few values), so a
    // recording and its own re-encode are, to the observer, the same frames.
    void fullChromaLosslessIsIdempotent()
    {
        const std::string source = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
        QTemporaryDir dir;
        VideoExportOptions options;
        options.crf = 0;
        options.fullChroma = true;
        Feedback feedback;
        std::vector<cv::Mat> passes{VideoReader(source).frame(40)};
        std::string in = source;
        for (int pass = 1; pass <= 2; ++pass) {
            VideoReader reader(in);
            const std::string out = dir.filePath(QStringLiteral("pass%1.mp4").arg(pass)).toStdString();
            exportVideo(out, reader.frameCount(), [&](int i) { return reader.frame(i); }, nullptr, feedback, options);
            passes.push_back(VideoReader(out).frame(40));
            in = out;
        }
        double largest = 0;
        cv::minMaxLoc(cv::abs(passes[1] - passes[0]) + cv::abs(passes[0] - passes[1]), nullptr, &largest);
        // Rounding only: video-range YUV has 220 levels of luma and 225 of colour for RGB's 256.
        QVERIFY2(largest <= 5, qPrintable(QString::number(largest)));
        QVERIFY(cv::norm(passes[1], passes[0], cv::NORM_L1) / double(passes[0].total() * 3) < 1.0);
        QVERIFY2(cv::norm(passes[2], passes[1], cv::NORM_INF) <= 1, qPrintable(QString::number(cv::norm(passes[2], passes[1], cv::NORM_INF))));
        cv::Mat changed;
        cv::compare(passes[2], passes[1], changed, cv::CMP_NE);
        const double share = double(cv::countNonZero(changed.reshape(1))) / double(changed.total() * 3);
        QVERIFY2(share < 0.01, qPrintable(QString::number(share)));
        // 4:2:0 at crf 0 is not lossless: its colour is halved on every pass.
        options.fullChroma = false;
        VideoReader reader(dir.filePath(QStringLiteral("pass1.mp4")).toStdString());
        const std::string subsampled = dir.filePath(QStringLiteral("subsampled.mp4")).toStdString();
        exportVideo(subsampled, reader.frameCount(), [&](int i) { return reader.frame(i); }, nullptr, feedback, options);
        QVERIFY(cv::norm(VideoReader(subsampled).frame(40), passes[1], cv::NORM_INF) > 5);
    }

    // Sync measured on decoded content: the white flash starts on frame 30 (t = 1.2 s) and the
    // loud tone starts at 1.2 s; after encoding, muxing and decoding they must coincide within
    // one frame.
    void soundAndPictureStayInSync()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("sync.mp4").toStdString();
        const AudioBuffer audio = tone(2.4, 16000, 1.2);
        Feedback feedback;
        exportVideo(path, 60, [](int i) { return patternFrame(i, 360, 288, 30); }, &audio, feedback);
        const MediaProbe probe = MediaProbe::read(path);

        double flash = -1;
        for (size_t i = 0; i < probe.frameBrightness.size(); ++i)
            if (probe.frameBrightness[i] > 170) {
                flash = probe.frameTimes[i];
                break;
            }
        double burst = -1;
        for (size_t n = 0; n < probe.audio.size(); ++n)
            if (std::abs(probe.audio[n]) > 0.3) {
                burst = probe.firstAudioTime + double(n) / probe.sampleRate;
                break;
            }
        QVERIFY(flash > 0);
        QVERIFY(burst > 0);
        QVERIFY2(std::abs(flash - 1.2) < 1e-3, qPrintable(QString::number(flash)));
        QVERIFY2(std::abs(burst - flash) < 1.0 / 25,
                 qPrintable(QString("flash %1 s, sound %2 s").arg(flash).arg(burst)));
    }

    // Every frame given is written; the sound (2 s) is cut at the last frame's end or continued
    // with silence up to it: the file lasts exactly as long as its frames.
    void soundIsFittedToTheFrames_data()
    {
        QTest::addColumn<int>("given");
        QTest::newRow("short video") << 30;
        QTest::newRow("long video") << 80;
    }
    void soundIsFittedToTheFrames()
    {
        QFETCH(int, given);
        QTemporaryDir dir;
        const std::string path = dir.filePath("fit.mp4").toStdString();
        const AudioBuffer audio = tone(2.0);
        Feedback feedback;
        int rendered = 0;
        QCOMPARE(exportVideo(path, given, [&](int i) { ++rendered; return patternFrame(i); }, &audio, feedback), given);
        QCOMPARE(rendered, given);
        const MediaProbe probe = MediaProbe::read(path);
        QCOMPARE(probe.videoPackets, given);
        const double seconds = given / 25.0, aacFrame = 1024.0 / audio.sampleRate;
        QVERIFY(std::abs(probe.videoDuration - seconds) < 1e-6);
        QVERIFY2(std::abs(probe.audioDuration - seconds) < aacFrame, qPrintable(QString::number(probe.audioDuration)));
    }

    // Frames at their own times: a variable frame rate keeps every frame's timestamp, and
    // 30000/1001 is written as that fraction.
    void frameTimesAreKept()
    {
        QTemporaryDir dir;
        const std::vector<double> times{0.0, 0.04, 0.12, 0.16, 0.5, 0.54, 0.58, 0.9};
        VideoExportOptions variable;
        variable.setFrames(FrameClock::fromTimes(times, 25.0));
        QVERIFY(variable.frames.isVariable());
        const AudioBuffer audio = tone(1.0);
        Feedback feedback;
        const std::string vfr = dir.filePath("vfr.mp4").toStdString();
        QCOMPARE(exportVideo(vfr, int(times.size()), [](int i) { return patternFrame(i); }, &audio, feedback, variable),
                 int(times.size()));
        const MediaProbe probe = MediaProbe::read(vfr);
        QCOMPARE(probe.frameTimes.size(), times.size());
        for (size_t i = 0; i < times.size(); ++i)
            QVERIFY2(std::abs(probe.frameTimes[i] - times[i]) < 1e-4,
                     qPrintable(QString("frame %1 at %2 s, not %3").arg(i).arg(probe.frameTimes[i]).arg(times[i])));
        QVERIFY2(std::abs(probe.audioDuration - 0.94) < 1024.0 / audio.sampleRate, qPrintable(QString::number(probe.audioDuration)));

        VideoExportOptions ntsc;
        ntsc.setFrames(FrameClock::uniform(30000.0 / 1001.0, 30));
        QCOMPARE(ntsc.frameRateNumerator, 30000);
        QCOMPARE(ntsc.frameRateDenominator, 1001);
        const std::string path = dir.filePath("ntsc.mp4").toStdString();
        exportVideo(path, 30, [](int i) { return patternFrame(i); }, &audio, feedback, ntsc);
        const MediaInfo info = MediaInfo::probe(path);
        QCOMPARE(info.frameCount, 30);
        QCOMPARE(info.frameRateNum, 30000);
        QCOMPARE(info.frameRateDen, 1001);
        QVERIFY(!info.variableFrameRate);
        QVERIFY(std::abs(info.frames.time(29) - 29 * 1001.0 / 30000.0) < 1e-6);
    }

    void silentVideoAndOddSizes()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("odd.mp4").toStdString();
        Feedback feedback;
        exportVideo(path, 12, [](int i) { return patternFrame(i, 361, 287); }, nullptr, feedback);
        const MediaProbe probe = MediaProbe::read(path);
        QCOMPARE(probe.audioStreams, 0);
        QCOMPARE(probe.videoPackets, 12);
        QCOMPARE(probe.width, 362); // padded to even sizes
        QCOMPARE(probe.height, 288);
    }

    // 22 kHz is not an AAC rate: the sound is resampled to 48 kHz and keeps its duration.
    void unusualSampleRateIsResampled()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("rate.mp4").toStdString();
        const AudioBuffer audio = tone(1.0, 22000);
        Feedback feedback;
        exportVideo(path, 25, [](int i) { return patternFrame(i); }, &audio, feedback);
        const MediaProbe probe = MediaProbe::read(path);
        QCOMPARE(probe.sampleRate, 48000);
        QVERIFY2(std::abs(probe.audioDuration - 1.0) < 1.0 / 25, qPrintable(QString::number(probe.audioDuration)));
    }

    // Cancel half way: no file under the final name, no temporary left, an older file there kept.
    void cancelLeavesNothingBehind()
    {
        QTemporaryDir dir;
        const QString target = dir.filePath("clip.mp4");
        {
            QFile old(target);
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write("previous export");
        }
        const AudioBuffer audio = tone(2.0);
        Feedback feedback;
        feedback.onProgress = [&](double p) {
            if (p > 0.5)
                feedback.cancel();
        };
        int rendered = 0;
        QVERIFY_THROWS_EXCEPTION(Canceled, exportVideo(target.toStdString(), 50, [&](int i) {
            ++rendered;
            return patternFrame(i);
        }, &audio, feedback));
        QVERIFY(rendered > 10 && rendered < 50);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"clip.mp4"});
        QFile old(target);
        QVERIFY(old.open(QIODevice::ReadOnly));
        QCOMPARE(old.readAll(), QByteArray("previous export"));
    }

    void canceledBeforeTheFirstFrame()
    {
        QTemporaryDir dir;
        Feedback feedback;
        feedback.cancel();
        QVERIFY_THROWS_EXCEPTION(Canceled, exportVideo(dir.filePath("x.mp4").toStdString(), 5,
                                                       [](int i) { return patternFrame(i); },
                                                       nullptr, feedback));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }

    // A failure in the frame source (or the encoder) also cleans up.
    void errorMidExportLeavesNothingBehind()
    {
        QTemporaryDir dir;
        Feedback feedback;
        const std::string path = dir.filePath("bad.mp4").toStdString();
        try {
            exportVideo(path, 20, [](int i) {
                return i < 5 ? patternFrame(i) : patternFrame(i, 200, 100); // size changes
            }, nullptr, feedback);
            QFAIL("a frame of another size must be rejected");
        } catch (const Error &e) {
            QCOMPARE(e.file(), path);
            QVERIFY2(QString(e.what()).contains("frame 5 is 200x100"), e.what());
        }
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }

    void unwritablePathIsAClearError_data()
    {
        QTest::addColumn<QString>("relative");
        QTest::addColumn<QString>("reason");
        QTest::newRow("missing folder") << "no/such/folder/out.mp4" << "does not exist";
        QTest::newRow("parent is a file") << "file.txt/out.mp4" << "is not a folder";
        QTest::newRow("target is a folder") << "folder" << "is a directory";
    }
    void unwritablePathIsAClearError()
    {
        QFETCH(QString, relative);
        QFETCH(QString, reason);
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("folder"));
        QFile file(dir.filePath("file.txt"));
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.close();
        const std::string path = dir.filePath(relative).toStdString();
        Feedback feedback;
        try {
            exportVideo(path, 5, [](int i) { return patternFrame(i); }, nullptr, feedback);
            QFAIL("expected lipsync::Error");
        } catch (const Error &e) {
            QCOMPARE(e.file(), path);
            QVERIFY2(QString(e.what()).contains(QString::fromStdString(path)), e.what());
            QVERIFY2(QString(e.what()).contains(reason), e.what());
        }
    }

    void audioIsAlignedToTheFirstFrame()
    {
        AudioBuffer audio;
        audio.sampleRate = 1000;
        audio.samples = {1, 2, 3, 4, 5};
        audio.startTime = 0.5;
        AudioBuffer later = alignAudioToVideo(audio, 0.497); // sound starts 3 samples after the frame
        QCOMPARE(later.samples, (std::vector<float>{0, 0, 0, 1, 2, 3, 4, 5}));
        QCOMPARE(later.startTime, 0.497);
        AudioBuffer earlier = alignAudioToVideo(audio, 0.502); // sound started 2 samples before
        QCOMPARE(earlier.samples, (std::vector<float>{3, 4, 5}));
        QVERIFY(alignAudioToVideo(audio, 1.0).samples.empty());
    }

    void emptyAudioIsRejected()
    {
        QTemporaryDir dir;
        AudioBuffer empty;
        empty.sampleRate = 16000;
        QVERIFY_THROWS_EXCEPTION(Error, VideoExporter(dir.filePath("a.mp4").toStdString(), {}, &empty));
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }

    // A streaming exporter dropped without finish() removes its temporary file.
    void destroyedExporterCleansUp()
    {
        QTemporaryDir dir;
        {
            VideoExporter exporter(dir.filePath("s.mp4").toStdString());
            exporter.addFrame(patternFrame(0));
            exporter.addFrame(patternFrame(1));
            QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 1); // the .part
        }
        QVERIFY(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestVideoExporter)
#include "tst_videoexporter.moc"
