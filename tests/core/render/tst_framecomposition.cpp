// Side-by-side and grid composition: layout, scaling, labels confined to their corner.
#include "render/FrameComposition.h"

#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <QTest>

using namespace lipsync;

namespace {

cv::Mat solid(int width, int height, cv::Vec3b colour)
{
    return cv::Mat(height, width, CV_8UC3, cv::Scalar(colour[0], colour[1], colour[2]));
}

const cv::Vec3b kRed(0, 0, 255), kGreen(0, 255, 0), kBlue(255, 0, 0), kGrey(128, 128, 128);

} // namespace

class TestFrameComposition : public QObject
{
    Q_OBJECT

private slots:
    void sideBySideKeepsBothFrames()
    {
        CompositionStyle style;
        style.gap = 4;
        style.background = cv::Scalar(255, 255, 255);
        const cv::Mat out = composeSideBySide(solid(360, 288, kRed), solid(360, 288, kGreen), {}, {}, style);
        QCOMPARE(out.cols, 360 + 4 + 360);
        QCOMPARE(out.rows, 288);
        QCOMPARE(out.type(), CV_8UC3);
        QCOMPARE(out.at<cv::Vec3b>(100, 0), kRed);
        QCOMPARE(out.at<cv::Vec3b>(100, 359), kRed);
        QCOMPARE(out.at<cv::Vec3b>(100, 361), cv::Vec3b(255, 255, 255)); // the gap
        QCOMPARE(out.at<cv::Vec3b>(100, 364), kGreen);
        QCOMPARE(out.at<cv::Vec3b>(287, 723), kGreen);
    }

    // A panel of another height is scaled to the first one's height, keeping its aspect.
    void panelsAreScaledToTheFirstHeight()
    {
        cv::Mat gray(144, 180, CV_8UC1, cv::Scalar(128));
        const cv::Mat out = composeSideBySide(solid(360, 288, kRed), gray);
        QCOMPARE(out.rows, 288);
        QCOMPARE(out.cols, 360 + 360);
        QCOMPARE(out.at<cv::Vec3b>(200, 500), kGrey);
    }

    void labelsStayInTheirCorner()
    {
        const cv::Mat plain = composeSideBySide(solid(360, 288, kRed), solid(360, 288, kGreen));
        const cv::Mat labelled = composeSideBySide(solid(360, 288, kRed), solid(360, 288, kGreen), "real", "DPDS");
        cv::Mat difference;
        cv::absdiff(plain, labelled, difference);
        cv::Mat changed;
        cv::cvtColor(difference, changed, cv::COLOR_BGR2GRAY);
        const cv::Rect box = cv::boundingRect(changed > 0);
        QVERIFY(box.area() > 0);
        // Changes in both panels' top-left corners only.
        QVERIFY2(box.y == 0 && box.height < 40, qPrintable(QString::number(box.height)));
        QVERIFY(cv::countNonZero(changed(cv::Rect(0, 0, 100, 40))) > 0);
        QVERIFY(cv::countNonZero(changed(cv::Rect(360, 0, 100, 40))) > 0);
        QCOMPARE(cv::countNonZero(changed(cv::Rect(100, 0, 260, 288))), 0);
        QCOMPARE(cv::countNonZero(changed(cv::Rect(0, 40, 720, 248))), 0);
    }

    void gridFillsRowByRow()
    {
        const cv::Mat out = composeGrid({solid(100, 80, kRed), solid(100, 80, kGreen), solid(100, 80, kBlue)}, 2);
        QCOMPARE(out.cols, 200);
        QCOMPARE(out.rows, 160);
        QCOMPARE(out.at<cv::Vec3b>(10, 10), kRed);
        QCOMPARE(out.at<cv::Vec3b>(10, 150), kGreen);
        QCOMPARE(out.at<cv::Vec3b>(120, 50), kBlue);
        QCOMPARE(out.at<cv::Vec3b>(120, 150), cv::Vec3b(0, 0, 0)); // empty cell
    }

    void badInputIsRejected()
    {
        QVERIFY_THROWS_EXCEPTION(Error, composeGrid({}, 2));
        QVERIFY_THROWS_EXCEPTION(Error, composeGrid({solid(10, 10, kRed)}, 0));
        QVERIFY_THROWS_EXCEPTION(Error, composeGrid({solid(10, 10, kRed), cv::Mat()}, 2));
        QVERIFY_THROWS_EXCEPTION(Error, composeGrid({solid(10, 10, kRed)}, 1, {"a", "b"}));
    }
};

QTEST_GUILESS_MAIN(TestFrameComposition)
#include "tst_framecomposition.moc"
