// Automatic landmarks on a GRID demo frame: YuNet, the Haar fallback, dlib's 68 points mapped to
// 23 (when libdlib-data is installed), and no face on a blank frame.
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"

#include <QTest>


using namespace lipsync;

namespace {

cv::Mat demoFrame(int index)
{
    VideoReader video(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
    return video.frame(index);
}

} // namespace

class TestFaceDetector : public QObject
{
    Q_OBJECT
private slots:
    void yunetFindsTheGridFace()
    {
        const cv::Mat frame = demoFrame(10);
        QCOMPARE(frame.cols, 360);
        FaceDetector detector;
        QVERIFY2(detector.hasYunet(), "the YuNet model in resources/models was not found");
        const auto faces = detector.detect(frame);
        QVERIFY(!faces.empty());
        const FaceDetection &f = faces.front();
        QCOMPARE(f.source, std::string("yunet"));
        QVERIFY(f.score > 0.8);
        QVERIFY(f.hasKeypoints);
        // The speaker sits in the middle of the frame; keypoints are ordered by image side.
        QVERIFY(f.box.x > 60 && f.box.x + f.box.width < 300);
        QVERIFY(f.keypoints[0].x() < f.keypoints[1].x());
        QVERIFY(f.keypoints[3].x() < f.keypoints[4].x());
        QVERIFY(f.keypoints[3].y() > f.keypoints[0].y()); // mouth below the eyes
        // The template placed on the keypoints puts the eyes where YuNet saw them.
        const Eigen::VectorXd s = initialShapeFromDetection(templateShape(), f);
        Eigen::Vector2d leftEye = Eigen::Vector2d::Zero();
        for (int i = 0; i < 4; ++i)
            leftEye += s.segment<2>(2 * i) / 4.0;
        QVERIFY((leftEye - f.keypoints[0]).norm() < 6.0);
    }

    void haarFallbackFindsTheFace()
    {
        FaceDetectorPaths paths = FaceDetectorPaths::boxesOnly();
        paths.yunetModel = "/nonexistent/yunet.onnx";
        FaceDetector detector(paths);
        QVERIFY(!detector.hasYunet());
        if (!detector.hasHaar())
            QSKIP("opencv-data's Haar cascades are not installed");
        const auto faces = detector.detect(demoFrame(10));
        QVERIFY(!faces.empty());
        QCOMPARE(faces.front().source, std::string("haar"));
        QVERIFY(!faces.front().hasKeypoints);
        const Eigen::VectorXd s = initialShapeFromDetection(templateShape(), faces.front());
        QVERIFY(s.allFinite());
    }

    void dlibGives68PointsMappedTo23()
    {
        FaceDetector detector;
        if (!detector.hasDlib())
            QSKIP("dlib's shape predictor is not installed (libdlib-data)");
        const cv::Mat frame = demoFrame(10);
        const auto faces = detector.detect(frame);
        QVERIFY(!faces.empty());
        const Eigen::VectorXd ibug = detector.dlibLandmarks(frame, faces.front());
        QCOMPARE(ibug.size(), Eigen::Index(136));
        const Eigen::VectorXd s = mapIbug68To23(ibug);
        // dlib and the keypoint-placed template agree roughly (both find the same face).
        const Eigen::VectorXd t = initialShapeFromDetection(templateShape(), faces.front());
        const double nme = normalisedMeanError(t, s);
        QVERIFY2(nme < 0.2, qPrintable(QString::number(nme)));
        // Anatomy: mouth corners below the eyes, chin lowest.
        QVERIFY(s[2 * scheme23::kMouthLeft + 1] > s[2 * scheme23::kLeftEyeOuter + 1]);
        QVERIFY(s[2 * 20 + 1] > s[2 * scheme23::kMouthLeft + 1]);
    }

    void noFaceInABlankFrame()
    {
        FaceDetector detector;
        QVERIFY(detector.detect(cv::Mat(288, 360, CV_8UC3, cv::Scalar(128, 128, 128))).empty());
        QVERIFY(detector.detect(cv::Mat()).empty());
    }
};

QTEST_GUILESS_MAIN(TestFaceDetector)
#include "tst_facedetector.moc"
