// MouthExemplars on a real clip (resources/demo, GRID s1) with shapes of known openings: the
// closed frames are kept one per closure, the most closed; open mouths a few per band of
// opening, those moving as the video's open mouths typically do first; a mouth is never taken
// from within half a second of the frame drawn into, and an open one comes from the band of the
// opening asked for or the nearest that has one; drawn onto its own shape an exemplar gives back the recording's pixels, moved with its
// shape it moves with it, and a degenerate map draws nothing.
#include "render/MouthExemplars.h"

#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"
#include "render/LowerFaceWarp.h"

#include <opencv2/imgproc.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace lipsync;

namespace {

const std::string kClip = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";

// The template face in the middle of a 360x288 frame, its inner lips `gap` pixels apart.
Eigen::VectorXd face(double gap)
{
    const Eigen::VectorXd t = templateShape();
    double top = 1e9, bottom = -1e9;
    for (Eigen::Index i = 1; i < t.size(); i += 2) {
        top = std::min(top, t[i]);
        bottom = std::max(bottom, t[i]);
    }
    const double scale = 0.45 * 288 / (bottom - top);
    Eigen::VectorXd s(t.size());
    for (Eigen::Index i = 0; i < t.size(); i += 2) {
        s[i] = 180.0 + scale * t[i];
        s[i + 1] = 130.0 + scale * t[i + 1];
    }
    const double mid = 0.5 * (s[2 * 16 + 1] + s[2 * 17 + 1]);
    s[2 * 16 + 1] = mid - 0.5 * gap;
    s[2 * 17 + 1] = mid + 0.5 * gap;
    return s;
}

double meanAbsDifference(const cv::Mat &a, const cv::Mat &b)
{
    cv::Mat d;
    cv::absdiff(a, b, d);
    const cv::Scalar m = cv::mean(d);
    return (m[0] + m[1] + m[2]) / 3.0;
}

} // namespace

class TestMouthExemplars : public QObject
{
    Q_OBJECT

    // Frames 5, 30, 31 and 60 closed (30 and 31 one closure: 40 ms apart; 31 the more closed),
    // frame 45 closed but not usable, the rest open.
    Eigen::MatrixXd m_shapes;
    std::vector<bool> m_usable;

private slots:
    void initTestCase()
    {
        VideoReader video(kClip);
        QVERIFY(video.frameCount() >= 70);
        m_shapes.resize(video.frameCount(), 2 * scheme23::kPointCount);
        m_usable.assign(size_t(video.frameCount()), true);
        for (int t = 0; t < video.frameCount(); ++t)
            m_shapes.row(t) = face(t == 31 ? 0.0 : (t == 5 || t == 30 || t == 45 || t == 60) ? 0.5 : 12.0).transpose();
        m_usable[45] = false;
        QVERIFY(MouthExemplars::openingShare(face(0.5)) < MouthExemplars::kClosedShare);
        QVERIFY(MouthExemplars::openingShare(face(12.0)) > MouthExemplars::kClosedShare);
    }

    void keepsOneFramePerClosure()
    {
        VideoReader video(kClip);
        const MouthExemplars exemplars(video, m_shapes, m_usable);
        QCOMPARE(exemplars.closedFrames(), (std::vector<int>{5, 31, 60}));
        // No usable frame at all: nothing kept.
        std::vector<bool> none(m_usable.size(), false);
        QVERIFY(MouthExemplars(video, m_shapes, none).empty());
    }

    void neverFromBesideTheFrameDrawnInto()
    {
        VideoReader video(kClip);
        const MouthExemplars exemplars(video, m_shapes, m_usable);
        const std::vector<int> frames = exemplars.closedFrames();
        for (int t = 0; t < video.frameCount(); ++t) {
            const int which = exemplars.chooseClosed(video.timestamp(t));
            QVERIFY(which >= 0);
            const double away = std::abs(video.timestamp(exemplars.frame(which)) - video.timestamp(t));
            QVERIFY2(away >= MouthExemplars::kAwaySeconds, qPrintable(QString("frame %1").arg(t)));
            // ... and the nearest such.
            for (int f : frames) {
                const double d = std::abs(video.timestamp(f) - video.timestamp(t));
                QVERIFY(d < MouthExemplars::kAwaySeconds || d >= away);
            }
        }
        QCOMPARE(exemplars.frame(exemplars.chooseClosed(video.timestamp(28))), 5); // 31 is beside it, 5 nearer than 60
    }

    // Three runs of open mouths, each in its own band of opening, moving within it on every frame
    // (as a speaking mouth does) but 40-44, which hold still; 74 opened wider than the mouth.
    void keepsTypicallyMovingOpenMouthsOfEachBand()
    {
        VideoReader video(kClip);
        QVERIFY(video.frameCount() >= 75);
        const double width = LowerFaceWarp::mouthWidth(face(0.0));
        auto share = [](int band) { return MouthExemplars::kClosedShare + (band + 0.5) * MouthExemplars::kOpenStep; };
        Eigen::MatrixXd shapes(75, 2 * scheme23::kPointCount);
        for (int t = 0; t < 75; ++t) {
            const double wobble = (t < 40 || t >= 45) && t % 2 ? 0.2 * MouthExemplars::kOpenStep : 0.0;
            shapes.row(t) = face(width * (share(t < 25 ? 2 : t < 50 ? 6 : 10) + wobble)).transpose();
        }
        shapes.row(74) = face(1.5 * width).transpose(); // opened wider than the mouth: a misfit, never kept
        QCOMPARE(MouthExemplars::bandOf(share(6)), 6);
        QCOMPARE(MouthExemplars::bandOf(share(6) + 0.2 * MouthExemplars::kOpenStep), 6);
        QCOMPARE(MouthExemplars::bandOf(0.0), 0);
        const MouthExemplars exemplars(video, shapes, std::vector<bool>(75, true));
        QVERIFY(exemplars.closedFrames().empty());
        const std::vector<int> open = exemplars.openFrames();
        QCOMPARE(int(open.size()), 3 * MouthExemplars::kOpenPerBand);
        QVERIFY(std::find(open.begin(), open.end(), 74) == open.end());
        for (int band : {2, 6, 10}) {
            std::vector<double> times;
            for (int f : open)
                if (MouthExemplars::bandOf(MouthExemplars::openingShare(shapes.row(f).transpose())) == band)
                    times.push_back(video.timestamp(f));
            QCOMPARE(int(times.size()), MouthExemplars::kOpenPerBand);
            for (size_t i = 1; i < times.size(); ++i)
                QVERIFY(times[i] - times[i - 1] > MouthExemplars::kSpacingSeconds - 1e-6);
        }
        // The middle band's first choice is its first frame that moves as the others do, 26 (25
        // jumps from another band): not the still 41-43, crisper than every other mouth of the
        // video, nor 25.
        const int typical = exemplars.chooseOpen(video.timestamp(70), share(6));
        QCOMPARE(exemplars.frame(typical), 26);
        QCOMPARE(exemplars.band(typical), 6);
        for (int f : open)
            QVERIFY2(f != 25 && (f < 40 || f > 44), qPrintable(QString("frame %1 kept").arg(f)));
        // Drawn into frame 42, it is another of that band, half a second away at least.
        const int away = exemplars.chooseOpen(video.timestamp(42), share(6));
        QCOMPARE(exemplars.band(away), 6);
        QVERIFY(std::abs(video.timestamp(exemplars.frame(away)) - video.timestamp(42)) >= MouthExemplars::kAwaySeconds);
        // A band with none: the nearest that has one; below every band, the lowest.
        QCOMPARE(exemplars.band(exemplars.chooseOpen(video.timestamp(0), share(9))), 10);
        // ... and one beside the frame drawn into counts as none: at frame 0, band 2's are all within half a second.
        QCOMPARE(exemplars.band(exemplars.chooseOpen(video.timestamp(0), share(2))), 6);
        QCOMPARE(exemplars.band(exemplars.chooseOpen(video.timestamp(70), 0.0)), 2);
        // Never from beside the frame drawn into, whatever the opening.
        for (int t = 0; t < 75; ++t)
            for (double asked : {0.0, share(2), share(5), share(12)}) {
                const int which = exemplars.chooseOpen(video.timestamp(t), asked);
                QVERIFY(which >= 0);
                QVERIFY(std::abs(video.timestamp(exemplars.frame(which)) - video.timestamp(t)) >= MouthExemplars::kAwaySeconds);
            }
    }

    void drawsTheRecordingsLipsWhereTheShapePutsThem()
    {
        VideoReader video(kClip);
        const MouthExemplars exemplars(video, m_shapes, m_usable);
        const int which = exemplars.chooseClosed(video.timestamp(40)); // frame 60
        QCOMPARE(exemplars.frame(which), 60);
        const cv::Mat recorded = video.frame(60);
        const Eigen::VectorXd shape = m_shapes.row(60).transpose();
        const cv::Rect box = cv::boundingRect(LowerFaceWarp::outerLips(shape, 5.0));
        cv::Mat patch(box.size(), CV_8UC3, cv::Scalar(0, 0, 0));
        // Onto its own shape: the recording's pixels.
        QVERIFY(exemplars.draw(which, shape, box, patch));
        QVERIFY2(meanAbsDifference(patch, recorded(box)) < 0.5, qPrintable(QString::number(meanAbsDifference(patch, recorded(box)))));
        // Onto its shape moved 4 px right and 3 down: the recording's pixels moved so.
        Eigen::VectorXd moved = shape;
        for (Eigen::Index i = 0; i < moved.size(); i += 2) {
            moved[i] += 4.0;
            moved[i + 1] += 3.0;
        }
        const cv::Rect movedBox = box + cv::Point(4, 3);
        QVERIFY(exemplars.draw(which, moved, movedBox, patch));
        QVERIFY(meanAbsDifference(patch, recorded(box)) < 0.5);
        // ... not left where it was.
        cv::Mat unmoved(box.size(), CV_8UC3);
        QVERIFY(exemplars.draw(which, moved, box, unmoved));
        QVERIFY(meanAbsDifference(unmoved, recorded(box)) > 2.0);
        // A mouth shrunk to a point: a degenerate map, nothing drawn.
        Eigen::VectorXd point = shape;
        for (Eigen::Index i = 0; i < point.size(); i += 2) {
            point[i] = 180.0 + 0.01 * (shape[i] - 180.0);
            point[i + 1] = 200.0 + 0.01 * (shape[i + 1] - 200.0);
        }
        patch.setTo(cv::Scalar(1, 2, 3));
        QVERIFY(!exemplars.draw(which, point, box, patch));
        QCOMPARE(cv::mean(patch)[2], 3.0);
        QVERIFY(!exemplars.draw(-1, shape, box, patch));
        QVERIFY(!exemplars.draw(which, shape, box + cv::Size(1, 0), patch)); // the patch not the box's size
    }

    void aSubPixelMoveKeepsTheLipsDetail()
    {
        // Moved half a pixel right and down, the lips keep their fine detail: the drawn patch's
        // Laplacian energy stays near the recording's (a bilinear lookup, which averages four
        // pixels there, keeps under half of it: 0.46 on this clip, Lanczos 0.89).
        VideoReader video(kClip);
        const MouthExemplars exemplars(video, m_shapes, m_usable);
        const int which = exemplars.chooseClosed(video.timestamp(40)); // frame 60
        const Eigen::VectorXd shape = m_shapes.row(60).transpose();
        Eigen::VectorXd moved = shape;
        for (Eigen::Index i = 0; i < moved.size(); ++i)
            moved[i] += 0.5;
        const cv::Rect box = cv::boundingRect(LowerFaceWarp::outerLips(shape, 5.0));
        cv::Mat patch(box.size(), CV_8UC3);
        QVERIFY(exemplars.draw(which, moved, box, patch));
        auto energy = [](const cv::Mat &bgr) {
            cv::Mat grey, laplacian;
            cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
            cv::Laplacian(grey, laplacian, CV_64F);
            const cv::Rect inner(2, 2, laplacian.cols - 4, laplacian.rows - 4);
            return cv::mean(laplacian(inner).mul(laplacian(inner)))[0];
        };
        const double ratio = energy(patch) / energy(video.frame(60)(box));
        QVERIFY2(ratio > 0.75, qPrintable(QString::number(ratio)));
    }
};

QTEST_GUILESS_MAIN(TestMouthExemplars)
#include "tst_mouthexemplars.moc"
