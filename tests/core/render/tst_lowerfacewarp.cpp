// ThinPlateWarp and LowerFaceWarp: the spline interpolates its control points' displacements,
// fades to nothing at its region's border, and leaves an image unchanged when nothing moves; the
// lower-face warp moves the pixels at the mouth to where the generated shape puts the mouth,
// keeps the eyes and everything outside the face, and the mouth's inside is the lens between the
// inner-lip points; the shape it moves to takes the lips' opening and width from a generated one.
#include "render/LowerFaceWarp.h"
#include "render/ThinPlateWarp.h"

#include "aam/LandmarkScheme.h"

#include <opencv2/imgproc.hpp>

#include <QTest>

#include <cmath>

using namespace lipsync;

namespace {

// A textured test image: a smooth gradient plus a grid of dots, so any move shows.
cv::Mat pattern(int w, int h)
{
    cv::Mat image(h, w, CV_8UC3);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            image.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(x * 255 / w), uchar(y * 255 / h), uchar((x * 7 + y * 13) % 256));
    return image;
}

// The 23-point template shape scaled into a w x h frame (the face in its middle).
Eigen::VectorXd face(int w, int h)
{
    const Eigen::VectorXd t = templateShape();
    double top = 1e9, bottom = -1e9;
    for (Eigen::Index i = 1; i < t.size(); i += 2) {
        top = std::min(top, t[i]);
        bottom = std::max(bottom, t[i]);
    }
    const double scale = 0.45 * h / std::max(1e-9, bottom - top);
    Eigen::VectorXd s(t.size());
    for (Eigen::Index i = 0; i < t.size(); i += 2) {
        s[i] = 0.5 * w + scale * t[i];
        s[i + 1] = 0.45 * h + scale * t[i + 1];
    }
    return s;
}

} // namespace

class TestLowerFaceWarp : public QObject
{
    Q_OBJECT
private slots:
    void splineInterpolatesItsPoints()
    {
        Eigen::VectorXd from(10), to(10);
        from << 10, 10, 90, 10, 90, 90, 10, 90, 50, 50;
        to = from;
        to[8] = 56; // the centre moves 6 px right and 3 down
        to[9] = 53;
        const ThinPlateWarp warp(from, to);
        QVERIFY(warp.valid());
        for (int i = 0; i < 5; ++i) {
            const Eigen::Vector2d d = warp.displacement(to.segment<2>(2 * i));
            QVERIFY2((d - (to - from).segment<2>(2 * i)).norm() < 1e-9, qPrintable(QString::number(i)));
        }
        // Many pixels at once give what each gives alone, on the control points too (r = 0).
        Eigen::ArrayXd x(7), y(7), dx, dy;
        x << 10, 56, 0, 33.5, 120, -7, 90;
        y << 10, 53, 0, 71.25, 40, 200, 90;
        warp.displacements(x, y, dx, dy);
        for (int k = 0; k < 7; ++k) {
            const Eigen::Vector2d d = warp.displacement({x[k], y[k]});
            QVERIFY2(std::abs(dx[k] - d.x()) < 1e-9 && std::abs(dy[k] - d.y()) < 1e-9, qPrintable(QString::number(k)));
        }
        QVERIFY(std::abs(dx[1] - 6.0) < 1e-9 && std::abs(dy[1] - 3.0) < 1e-9);
        // Coincident points cannot be fitted.
        Eigen::VectorXd same(6);
        same << 1, 1, 1, 1, 1, 1;
        QVERIFY(!ThinPlateWarp(same, same).valid());
    }

    void imageMovesInsideItsRegionOnly()
    {
        const cv::Mat image = pattern(100, 100);
        Eigen::VectorXd from(10), to(10);
        from << 20, 20, 80, 20, 80, 80, 20, 80, 50, 50;
        to = from;
        cv::Mat same = image.clone();
        QVERIFY(ThinPlateWarp(from, to).apply(same, cv::Rect(10, 10, 80, 80), 8.0));
        QVERIFY(cv::norm(same, image, cv::NORM_INF) <= 1.0); // resampling at integer points
        to[8] = 56;
        cv::Mat moved = image.clone();
        QVERIFY(ThinPlateWarp(from, to).apply(moved, cv::Rect(10, 10, 80, 80), 8.0));
        // The pixel at the moved point's target shows what was at its source.
        QVERIFY(cv::norm(moved.at<cv::Vec3b>(50, 56), image.at<cv::Vec3b>(50, 50)) <= 3.0);
        // Outside the region nothing changes; at its border hardly anything.
        cv::Mat outside = moved.clone();
        image(cv::Rect(10, 10, 80, 80)).copyTo(outside(cv::Rect(10, 10, 80, 80)));
        QCOMPARE(cv::norm(outside, image, cv::NORM_INF), 0.0);
        QVERIFY(cv::norm(moved.row(10), image.row(10), cv::NORM_INF) <= 1.0);
    }

    void lowerFaceMovesEyesStay()
    {
        const cv::Mat image = pattern(360, 288);
        const Eigen::VectorXd tracked = face(360, 288);
        cv::Mat unchanged = image.clone();
        QVERIFY(LowerFaceWarp::apply(unchanged, tracked, tracked).empty());
        // The jaw and lower lip drop 6 px (the mouth opens).
        Eigen::VectorXd generated = tracked;
        for (int i : {13, 14, 15, 17, 19, 20, 21})
            generated[2 * i + 1] += 6.0;
        cv::Mat frame = image.clone();
        const cv::Rect region = LowerFaceWarp::apply(frame, tracked, generated);
        QVERIFY(!region.empty());
        // The lower lip's centre now shows what was 6 px above it.
        const int lx = int(std::lround(generated[2 * 14])), ly = int(std::lround(generated[2 * 14 + 1]));
        QVERIFY(cv::norm(frame.at<cv::Vec3b>(ly, lx), image.at<cv::Vec3b>(ly - 6, lx)) <= 6.0);
        // The eyes are where they were.
        for (int i = 0; i < 8; ++i) {
            const int x = int(std::lround(tracked[2 * i])), y = int(std::lround(tracked[2 * i + 1]));
            QVERIFY2(cv::norm(frame.at<cv::Vec3b>(y, x), image.at<cv::Vec3b>(y, x)) <= 2.0, qPrintable(QString::number(i)));
        }
        // Outside the region the frame is untouched.
        cv::Mat outside = frame.clone();
        image(region).copyTo(outside(region));
        QCOMPARE(cv::norm(outside, image, cv::NORM_INF), 0.0);
        // The inside of the mouth: a lens from corner to corner through the inner-lip points.
        generated[2 * 17 + 1] += 4.0;
        const std::vector<cv::Point2f> lens = LowerFaceWarp::mouthInterior(generated);
        QVERIFY(cv::pointPolygonTest(lens, cv::Point2f(float(0.5 * (generated[32] + generated[34])),
                                                          float(0.5 * (generated[33] + generated[35]))), false) > 0);
        QVERIFY(std::abs(LowerFaceWarp::opening(generated) - (generated[35] - generated[33])) < 1.0);
    }

    // The shape the recording's face is moved to takes from the generated one only the lips'
    // moves along the face (eyes to chin) and the mouth's width, on a tilted head: the model's
    // sideways drift of the lips, its outline of them, its eyes and the jaw's upper ends are not
    // drawn.
    void speechShapeTakesOpeningAndWidthOnly()
    {
        Eigen::VectorXd tracked = face(360, 288);
        const double tilt = 20.0 * M_PI / 180.0, c = std::cos(tilt), s = std::sin(tilt);
        for (Eigen::Index i = 0; i < tracked.size(); i += 2) {
            const double x = tracked[i] - 180.0, y = tracked[i + 1] - 144.0;
            tracked[i] = 180.0 + c * x - s * y;
            tracked[i + 1] = 144.0 + s * x + c * y;
        }
        QVERIFY((LowerFaceWarp::speechShape(tracked, tracked) - tracked).cwiseAbs().maxCoeff() < 1e-12);
        auto at = [](const Eigen::VectorXd &shape, int i) { return Eigen::Vector2d(shape.segment<2>(2 * i)); };
        Eigen::Vector2d eyes = Eigen::Vector2d::Zero();
        for (int i = 0; i < 8; ++i)
            eyes += at(tracked, i) / 8.0;
        const Eigen::Vector2d down = (at(tracked, 20) - eyes).normalized(), across(down.y(), -down.x()); // to the right
        Eigen::VectorXd generated = tracked;
        auto shift = [&generated](int i, const Eigen::Vector2d &by) { generated.segment<2>(2 * i) += by; };
        shift(16, 2.0 * down + 3.0 * across); // the upper lip down 2 px and 3 px sideways
        shift(17, 5.0 * down + 3.0 * across); // the lower lip down 5 px
        shift(10, -3.0 * down);               // the model's thicker upper lip
        shift(14, 1.0 * across);
        shift(8, -2.0 * across);              // the corners 2 px further apart each
        shift(12, 2.0 * across);
        for (int i : {0, 3, 6, 18, 22})
            shift(i, Eigen::Vector2d(1.0, -1.0)); // eyes and jaw ends off by a pixel
        const Eigen::VectorXd speech = LowerFaceWarp::speechShape(tracked, generated);
        for (int i : {0, 1, 2, 3, 4, 5, 6, 7, 18, 22})
            QVERIFY2((at(speech, i) - at(tracked, i)).norm() < 1e-9, qPrintable(QString::number(i)));
        for (int i : {9, 10, 11, 16})
            QVERIFY2((at(speech, i) - at(tracked, i) - 2.0 * down).norm() < 1e-9, qPrintable(QString::number(i)));
        for (int i : {13, 14, 15, 17, 20})
            QVERIFY2((at(speech, i) - at(tracked, i) - 5.0 * down).norm() < 1e-9, qPrintable(QString::number(i)));
        for (int i : {19, 21})
            QVERIFY((at(speech, i) - at(tracked, i) - 2.5 * down).norm() < 1e-9);
        QVERIFY(std::abs(LowerFaceWarp::mouthWidth(speech) - LowerFaceWarp::mouthWidth(generated)) < 1e-9);
        QVERIFY(std::abs((at(speech, 17) - at(speech, 16)).dot(down) - (at(tracked, 17) - at(tracked, 16)).dot(down) - 3.0) < 1e-9);
        // The corners midway between the lips' moves, apart along the line between them.
        const Eigen::Vector2d corners = (at(tracked, 12) - at(tracked, 8)).normalized();
        const double widen = 0.5 * (LowerFaceWarp::mouthWidth(generated) - LowerFaceWarp::mouthWidth(tracked));
        QVERIFY(widen > 1.5);
        QVERIFY((at(speech, 8) - at(tracked, 8) - 3.5 * down + widen * corners).norm() < 1e-9);
        QVERIFY((at(speech, 12) - at(tracked, 12) - 3.5 * down - widen * corners).norm() < 1e-9);
    }

    // An open mouth asked to close past itself (the inner lips 12 px through each other, the
    // corners pulled in): the frame is squeezed, never folded. A frame that encodes every pixel's
    // own row shows it: down any column the rows read stay in order.
    void neverFoldsTheFace()
    {
        cv::Mat rows(288, 360, CV_8UC3);
        for (int y = 0; y < 288; ++y)
            for (int x = 0; x < 360; ++x)
                rows.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(y * 255 / 287), uchar(x * 255 / 359), 0);
        Eigen::VectorXd tracked = face(360, 288);
        tracked[2 * 17 + 1] += 10.0; // recorded open
        for (int i : {13, 14, 15})
            tracked[2 * i + 1] += 10.0;
        Eigen::VectorXd generated = tracked;
        generated[2 * 16 + 1] += 16.0; // the upper lip pulled down past the lower
        generated[2 * 17 + 1] -= 16.0;
        generated[2 * 10 + 1] += 14.0;
        generated[2 * 14 + 1] -= 14.0;
        generated[2 * 8] += 12.0;
        generated[2 * 12] -= 12.0;
        // The plain spline through these points folds.
        Eigen::VectorXd sources, targets;
        cv::Rect2d ring;
        LowerFaceWarp::controlPoints(tracked, generated, sources, targets, ring);
        const cv::Rect box = cv::Rect(ring) & cv::Rect(0, 0, 360, 288);
        QVERIFY2(ThinPlateWarp(sources, targets).minJacobian(box, 20.0) < 0.25,
                 qPrintable(QString::number(ThinPlateWarp(sources, targets).minJacobian(box, 20.0))));
        cv::Mat frame = rows.clone();
        QVERIFY(!LowerFaceWarp::apply(frame, tracked, generated).empty());
        int reversals = 0;
        for (int x = 0; x < 360; ++x)
            for (int y = 1; y < 288; ++y)
                reversals += frame.at<cv::Vec3b>(y, x)[0] + 2 < frame.at<cv::Vec3b>(y - 1, x)[0];
        QCOMPARE(reversals, 0);
        QVERIFY(cv::norm(frame, rows, cv::NORM_INF) > 5); // and it did move
    }
};

QTEST_GUILESS_MAIN(TestLowerFaceWarp)
#include "tst_lowerfacewarp.moc"
