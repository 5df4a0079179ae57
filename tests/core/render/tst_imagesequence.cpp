// PNG sequence export: lossless round trip, names, and all-or-nothing on cancel and errors.
#include "render/ImageSequenceExporter.h"

#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgcodecs.hpp>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;

namespace {

cv::Mat noiseFrame(int i)
{
    cv::Mat frame(60, 80, CV_8UC3);
    cv::randu(frame, cv::Scalar::all(0), cv::Scalar::all(256));
    frame.at<cv::Vec3b>(0, 0) = cv::Vec3b(uchar(i), 0, 0);
    return frame;
}

} // namespace

class TestImageSequence : public QObject
{
    Q_OBJECT

private slots:
    void roundTripIsLossless()
    {
        QTemporaryDir dir;
        const QString folder = dir.filePath("frames");
        std::vector<cv::Mat> frames;
        for (int i = 0; i < 5; ++i)
            frames.push_back(noiseFrame(i));
        Feedback feedback;
        const std::vector<std::string> paths = exportImageSequence(
            folder.toStdString(), 5, [&](int i) { return frames[size_t(i)]; }, feedback, "bbaf2n_");
        QCOMPARE(int(paths.size()), 5);
        QCOMPARE(QDir(folder).entryList(QDir::Files),
                 (QStringList{"bbaf2n_00000.png", "bbaf2n_00001.png", "bbaf2n_00002.png",
                              "bbaf2n_00003.png", "bbaf2n_00004.png"}));
        for (int i = 0; i < 5; ++i) {
            const cv::Mat back = cv::imread(paths[size_t(i)], cv::IMREAD_UNCHANGED);
            QCOMPARE(back.type(), CV_8UC3);
            QCOMPARE(cv::norm(back, frames[size_t(i)], cv::NORM_INF), 0.0);
        }
        QCOMPARE(feedback.progress(), 1.0);
        // Only the target folder remains beside it (no temporary folder).
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList{"frames"});
    }

    void cancelLeavesTheFolderAsItWas()
    {
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkdir("frames"));
        QFile keep(dir.filePath("frames/frame_00000.png"));
        QVERIFY(keep.open(QIODevice::WriteOnly));
        keep.write("older export");
        keep.close();
        Feedback feedback;
        int rendered = 0;
        QVERIFY_THROWS_EXCEPTION(Canceled, exportImageSequence(dir.filePath("frames").toStdString(), 10, [&](int i) {
            if (++rendered == 4)
                feedback.cancel();
            return noiseFrame(i);
        }, feedback));
        QCOMPARE(QDir(dir.filePath("frames")).entryList(QDir::Files), QStringList{"frame_00000.png"});
        QVERIFY(keep.open(QIODevice::ReadOnly));
        QCOMPARE(keep.readAll(), QByteArray("older export"));
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot),
                 QStringList{"frames"});
    }

    void errorsNameTheFolder()
    {
        QTemporaryDir dir;
        Feedback feedback;
        const std::string missing = dir.filePath("no/such/frames").toStdString();
        try {
            exportImageSequence(missing, 3, noiseFrame, feedback);
            QFAIL("expected lipsync::Error");
        } catch (const Error &e) {
            QCOMPARE(e.file(), missing);
            QVERIFY2(QString(e.what()).contains("does not exist"), e.what());
        }
        const std::string folder = dir.filePath("frames").toStdString();
        QVERIFY_THROWS_EXCEPTION(Error, exportImageSequence(folder, 3, [](int i) {
            return i == 1 ? cv::Mat() : noiseFrame(i);
        }, feedback));
        QVERIFY(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestImageSequence)
#include "tst_imagesequence.moc"
