// MediaInfo::probe: streams, rates and decoded counts; bad files give an Error naming them.
#include "io/MediaInfo.h"
#include "io/VideoReader.h"
#include "util/Error.h"

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

std::string media(const char *name)
{
    return std::string(LIPSYNC_TEST_DATA "/media/") + name;
}

} // namespace

class TestMediaInfo : public QObject
{
    Q_OBJECT

private slots:
    void gridClip()
    {
        const std::string path = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
        const MediaInfo info = MediaInfo::probe(path);
        QCOMPARE(info.path, path);
        QCOMPARE(info.format, std::string("mpeg"));
        QVERIFY(info.hasVideo);
        QCOMPARE(info.videoCodec, std::string("mpeg1video"));
        QCOMPARE(info.frameCount, 75);
        QCOMPARE(info.frameRate, 25.0);
        QCOMPARE(info.width, 360);
        QCOMPARE(info.height, 288);
        QVERIFY(std::abs(info.videoDuration - 3.0) < 1e-9);
        QVERIFY(info.hasAudio);
        QCOMPARE(info.audioCodec, std::string("mp2"));
        QCOMPARE(info.audioSampleRate, 44100);
        QCOMPARE(info.audioChannels, 2);
        QVERIFY(std::abs(info.audioDuration - 114 * 1152 / 44100.0) < 1e-9); // 2.978 s
        QCOMPARE(info.audioStartTime, 0.0);
        QCOMPARE(info.damagedFrames, 0);
        // The decoded count is what VideoReader delivers.
        QCOMPARE(VideoReader(path).frameCount(), info.frameCount);
    }

    void videoWithoutAudio()
    {
        const MediaInfo info = MediaInfo::probe(media("no_audio_29.97fps.mp4"));
        QVERIFY(info.hasVideo);
        QVERIFY(!info.hasAudio);
        QCOMPARE(info.audioSampleRate, 0);
        QCOMPARE(info.audioChannels, 0);
        QCOMPARE(info.audioDuration, 0.0);
        QCOMPARE(info.frameCount, 15);
        QVERIFY(std::abs(info.frameRate - 29.97) < 0.001);
        QVERIFY(std::abs(info.videoDuration - 15 / (30000.0 / 1001.0)) < 1e-9);
        QCOMPARE(info.videoCodec, std::string("h264"));
    }

    void audioOnly_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("rate");
        QTest::addColumn<int>("channels");
        QTest::newRow("wav") << "short_400ms_8k.wav" << 8000 << 1;
        QTest::newRow("flac") << "short_400ms_22k_stereo.flac" << 22050 << 2;
    }

    void audioOnly()
    {
        QFETCH(QString, name);
        QFETCH(int, rate);
        QFETCH(int, channels);
        const MediaInfo info = MediaInfo::probe(media(name.toUtf8().constData()));
        QVERIFY(!info.hasVideo);
        QCOMPARE(info.frameCount, 0);
        QVERIFY(info.hasAudio);
        QCOMPARE(info.audioSampleRate, rate);
        QCOMPARE(info.audioChannels, channels);
        QVERIFY(std::abs(info.audioDuration - 0.4) < 1e-3);
    }

    void badFiles_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("reason");
        QTest::newRow("missing") << "missing.mp4" << "file not found";
        QTest::newRow("empty") << "empty.mpg" << "empty file";
        QTest::newRow("truncated mpg") << "truncated_30pct.mpg" << "truncated";
        QTest::newRow("text as mpg") << "text_renamed.mpg" << "unsupported";
        QTest::newRow("truncated wav") << "truncated_50pct.wav" << "truncated";
        QTest::newRow("truncated mp4") << "truncated_60pct.mp4" << "truncated";
    }

    void badFiles()
    {
        QFETCH(QString, name);
        QFETCH(QString, reason);
        const std::string path = media(name.toUtf8().constData());
        // Twice: a failure is not cached as success.
        for (int attempt = 0; attempt < 2; ++attempt) {
            try {
                MediaInfo::probe(path);
                QFAIL("expected lipsync::Error");
            } catch (const Error &e) {
                QCOMPARE(e.file(), path);
                QVERIFY2(QString::fromStdString(e.reason()).contains(reason), e.what());
                QVERIFY(QString::fromUtf8(e.what()).contains(name));
            }
        }
    }

    void changedFileIsProbedAgain()
    {
        // The probe cache is keyed by size and modification time: replacing a file's contents
        // must not return the old answer.
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString path = dir.filePath(QStringLiteral("clip.wav"));
        QVERIFY(QFile::copy(QString::fromStdString(media("short_400ms_8k.wav")), path));
        QCOMPARE(MediaInfo::probe(path.toStdString()).audioSampleRate, 8000);
        QVERIFY(QFile::remove(path));
        QVERIFY(QFile::copy(QString::fromStdString(media("empty.mpg")), path));
        QVERIFY_THROWS_EXCEPTION(Error, MediaInfo::probe(path.toStdString()));
    }
};

QTEST_GUILESS_MAIN(TestMediaInfo)
#include "tst_mediainfo.moc"
