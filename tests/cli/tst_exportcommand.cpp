// `lipsync export video` on a demo clip, read back with ffprobe-like checks through the JSON
// report and the written files; bad input gives one clear line.
#include "CliRun.h"

#include "render/VideoExporter.h"
#include "tasks/Feedback.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;
using lipsync::testing::verifyOneLineError;

namespace {

const QString kClip = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
const QString kOther = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bgin3a.mpg");

} // namespace

class TestExportCommand : public QObject
{
    Q_OBJECT

private slots:
    void sideBySideMp4WithSound()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("compare.mp4");
        const Run r = runLipsync({"export", "video", "--media", kClip, "--beside", kOther, "--captions",
                           "real,other", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(r.err.isEmpty(), r.err.constData()); // FFmpeg's chatter stays quiet
        const QJsonObject json = parseJsonObject(r.out);
        QVERIFY(json.value("audio").toBool());
        const double audio = json.value("audioDuration").toDouble();
        QVERIFY(audio > 2.5);
        QVERIFY(std::abs(json.value("duration").toDouble() - audio) < 1.0 / 25);
        QVERIFY(QFileInfo(out).size() > 10000);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList{"compare.mp4"});
    }

    void pngSequence()
    {
        QTemporaryDir dir;
        const Run r = runLipsync({"export", "video", "--media", kClip, "--png-dir", dir.filePath("png"), "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out).value("frames").toInt(), 75);
        QCOMPARE(QDir(dir.filePath("png")).entryList({"*.png"}).size(), 75);
    }

    // Media without sound: a clear message that says how to go on.
    void mediaWithoutAudio()
    {
        QTemporaryDir dir;
        const QString silent = dir.filePath("silent.mp4");
        lipsync::Feedback feedback;
        lipsync::exportVideo(silent.toStdString(), 10, [](int i) {
            return cv::Mat(64, 64, CV_8UC3, cv::Scalar(i * 20, 100, 100));
        }, nullptr, feedback);
        verifyOneLineError(runLipsync({"export", "video", "--media", silent, "--out", dir.filePath("x.mp4")}), 1,
                           "--no-audio");
        QVERIFY(!QFileInfo::exists(dir.filePath("x.mp4")));
        const Run r = runLipsync({"export", "video", "--media", silent, "--no-audio", "--out", dir.filePath("x.mp4"), "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out).value("frames").toInt(), 10);
        QCOMPARE(parseJsonObject(r.out).value("audio").toBool(), false);
    }

    void badInput()
    {
        QTemporaryDir dir;
        verifyOneLineError(runLipsync({"export", "video", "--media", dir.filePath("none.mpg"), "--out",
                                dir.filePath("x.mp4")}), 1, "none.mpg");
        verifyOneLineError(runLipsync({"export", "video", "--media", kClip, "--out",
                                dir.filePath("missing/x.mp4")}), 1, "does not exist");
        verifyOneLineError(runLipsync({"export", "video", "--media", kClip}), 2, "usage");
        verifyOneLineError(runLipsync({"export", "video", "--media", kClip, "--out", "x.mp4", "--crf", "99"}), 2, "--crf");
        QVERIFY(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestExportCommand)
#include "tst_exportcommand.moc"
