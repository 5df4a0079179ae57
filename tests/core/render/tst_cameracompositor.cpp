// Generated faces over frames that come one at a time (render/CameraCompositor), on a demo clip's
// frames standing for a camera and the demo's AAM:
//  - every frame of the clip has its face found, at the pose FaceRenderer finds with the whole
//    video tracked beforehand (within a pixel or two and a few per cent of scale);
//  - the face is drawn where the frame's face is: the mouth changes with the parameters drawn,
//    the background far from the face stays as it was;
//  - when the face leaves the picture it stops being drawn within the detector's check and the
//    frame is left unchanged; a moved picture is followed; wrong frames and features are errors.
#include "aam/AamModel.h"
#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"
#include "render/CameraCompositor.h"
#include "render/FaceRenderer.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QTest>

#include <opencv2/core.hpp>

#include <cmath>

using namespace lipsync;

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";
const std::string kClip = kDemo + "/media/bgin3a.mpg";

double meanAbsDifference(const cv::Mat &a, const cv::Mat &b, const cv::Rect &box)
{
    cv::Mat d;
    cv::absdiff(a(box), b(box), d);
    const cv::Scalar m = cv::mean(d);
    return (m[0] + m[1] + m[2]) / 3.0;
}

} // namespace

class TestCameraCompositor : public QObject
{
    Q_OBJECT

    AamModel m_aam;

private slots:
    void initTestCase() { m_aam = AamModel::load(kDemo + "/aam/demo.aam"); }

    void followsTheFaceAsTheVideoTrackerDoes()
    {
        Feedback feedback;
        FaceRenderer tracked(m_aam, kClip, feedback);
        VideoReader camera(kClip);
        CameraCompositor compositor(m_aam);
        const Eigen::VectorXd mean = Eigen::VectorXd::Zero(m_aam.combinedModes());
        double worstShift = 0, worstScale = 0;
        for (int i = 0; i < camera.frameCount(); ++i) {
            cv::Mat frame = camera.frame(i).clone();
            QVERIFY2(compositor.compose(frame, mean), qPrintable(QString("frame %1").arg(i)));
            QVERIFY(compositor.pose());
            const Similarity &online = *compositor.pose(), &offline = tracked.pose(i);
            worstShift = std::max({worstShift, std::abs(online.tx - offline.tx), std::abs(online.ty - offline.ty)});
            worstScale = std::max(worstScale, std::abs(std::hypot(online.a, online.b) / std::hypot(offline.a, offline.b) - 1));
        }
        qInfo("online against offline pose over %d frames: %.2f px, %.3f of scale at worst", camera.frameCount(),
              worstShift, worstScale);
        QVERIFY2(worstShift < 3.0, qPrintable(QString::number(worstShift)));
        QVERIFY2(worstScale < 0.05, qPrintable(QString::number(worstScale)));
    }

    void drawsTheMouthAndKeepsTheRest()
    {
        VideoReader camera(kClip);
        CameraCompositor compositor(m_aam);
        const cv::Mat original = camera.frame(40).clone();
        // The widest-open and the most closed mouth the model's first mode draws.
        Eigen::VectorXd open = Eigen::VectorXd::Zero(m_aam.combinedModes()), shut = open;
        open[0] = 2.5 * std::sqrt(m_aam.combinedVariances[0]);
        shut[0] = -open[0];
        cv::Mat a = original.clone(), b = original.clone();
        QVERIFY(compositor.compose(a, open));
        QVERIFY(compositor.compose(b, shut));
        const Similarity pose = *compositor.pose();
        // The mouth: the model's mouth points under the pose.
        AamSynthesizer synth(m_aam);
        const Eigen::VectorXd points = pose.apply(synth.shape(open));
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (int k = scheme23::kMouthLeft; k < m_aam.pointCount(); ++k) {
            x0 = std::min(x0, points[2 * k]), x1 = std::max(x1, points[2 * k]);
            y0 = std::min(y0, points[2 * k + 1]), y1 = std::max(y1, points[2 * k + 1]);
        }
        const cv::Rect mouth(int(x0), int(y0), std::max(4, int(x1 - x0)), std::max(4, int(y1 - y0)));
        QVERIFY2(meanAbsDifference(a, b, mouth) > 4.0, qPrintable(QString::number(meanAbsDifference(a, b, mouth))));
        const cv::Rect corner(0, 0, 40, 40);
        QCOMPARE(meanAbsDifference(a, original, corner), 0.0);
    }

    void noFaceLeavesTheFrameAndAMovedPictureIsFollowed()
    {
        VideoReader camera(kClip);
        CameraCompositor compositor(m_aam);
        const Eigen::VectorXd mean = Eigen::VectorXd::Zero(m_aam.combinedModes());
        cv::Mat frame = camera.frame(10).clone();
        QVERIFY(compositor.compose(frame, mean));
        const Similarity before = *compositor.pose();
        // The person leaves: within the detector's check the face is no longer drawn, and then
        // the picture is left as it is.
        const cv::Mat grey(frame.size(), CV_8UC3, cv::Scalar(90, 90, 90));
        int drawn = 0;
        while (drawn <= CameraCompositor::kVerifyFrames) {
            cv::Mat picture = grey.clone();
            if (!compositor.compose(picture, mean))
                break;
            ++drawn;
        }
        QVERIFY2(drawn < CameraCompositor::kVerifyFrames, qPrintable(QString::number(drawn)));
        QVERIFY(!compositor.pose());
        cv::Mat picture = grey.clone();
        QVERIFY(!compositor.compose(picture, mean));
        QCOMPARE(cv::norm(picture, grey, cv::NORM_INF), 0.0);
        // The same picture moved 30 pixels right: found again there.
        cv::Mat moved(frame.size(), CV_8UC3, cv::Scalar(0, 0, 0));
        camera.frame(10)(cv::Rect(0, 0, frame.cols - 30, frame.rows)).copyTo(moved(cv::Rect(30, 0, frame.cols - 30, frame.rows)));
        QVERIFY(compositor.compose(moved, mean));
        QVERIFY2(std::abs(compositor.pose()->tx - before.tx - 30) < 3.0,
                 qPrintable(QString("%1 -> %2").arg(before.tx).arg(compositor.pose()->tx)));
    }

    void wrongInputIsAnError()
    {
        CameraCompositor compositor(m_aam);
        cv::Mat grey(100, 100, CV_8UC1, cv::Scalar(0));
        QVERIFY_THROWS_EXCEPTION(Error, compositor.compose(grey, Eigen::VectorXd::Zero(m_aam.combinedModes())));
        cv::Mat frame(100, 100, CV_8UC3, cv::Scalar(0));
        QVERIFY_THROWS_EXCEPTION(Error, compositor.compose(frame, Eigen::VectorXd::Zero(3)));
    }
};

QTEST_GUILESS_MAIN(TestCameraCompositor)
#include "tst_cameracompositor.moc"
