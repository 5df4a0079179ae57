// FrameView draws the frame and its landmarks in their state colours; the wheel zooms about
// the cursor (the image point under it stays put), a double-click fits the frame again, and a
// left-drag with Space held pans instead of editing.
#include "annotate/FrameView.h"

#include <QTest>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

int countColour(const QImage &image, const QColor &colour)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            n += image.pixelColor(x, y) == colour ? 1 : 0;
    return n;
}

} // namespace

class TestFrameView : public QObject
{
    Q_OBJECT
private slots:
    void drawsFrameAndLandmarks()
    {
        FrameView view;
        view.resize(400, 320);
        QImage frame(200, 160, QImage::Format_RGB32);
        frame.fill(QColor(90, 90, 90));
        view.setImage(frame);
        LandmarkSet set;
        set.points[0] = {40, 40, PointState::Placed};
        set.points[1] = {100, 80, PointState::Automatic};
        set.points[2] = {160, 120, PointState::Fixed};
        view.setLandmarks(set);
        const QImage image = view.grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY(countColour(image, QColor(90, 90, 90)) > 200 * 160 * 3);
        for (PointState state : {PointState::Placed, PointState::Automatic, PointState::Fixed})
            QVERIFY2(countColour(image, FrameView::stateColor(state)) > 10, pointStateName(state));

        view.setLandmarks(std::nullopt);
        const QImage bare = view.grab().toImage().convertToFormat(QImage::Format_RGB32);
        QCOMPARE(countColour(bare, FrameView::stateColor(PointState::Placed)), 0);
    }

    void wheelZoomsAboutTheCursor()
    {
        FrameView view;
        view.resize(400, 320);
        QImage frame(200, 160, QImage::Format_RGB32);
        frame.fill(Qt::black);
        // A white marker at image (150, 40): it must stay under the cursor while zooming.
        for (int y = 38; y < 42; ++y)
            for (int x = 148; x < 152; ++x)
                frame.setPixelColor(x, y, Qt::white);
        view.setImage(frame);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QPoint marker(300, 80); // fit scale 2, no offset: (150, 40) * 2
        QCOMPARE(view.grab().toImage().pixelColor(marker), QColor(Qt::white));

        QWheelEvent wheel(QPointF(marker), view.mapToGlobal(QPointF(marker)), QPoint(), QPoint(0, 240),
                          Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(&view, &wheel);
        QVERIFY(view.zoom() > 1.5);
        QCOMPARE(view.grab().toImage().pixelColor(marker), QColor(Qt::white));

        QTest::mouseDClick(&view, Qt::LeftButton, {}, QPoint(10, 10));
        QCOMPARE(view.zoom(), 1.0);
    }

    void spaceDragPans()
    {
        // In an editable view a left click places the next point; with Space held a left-drag
        // pans instead and edits nothing.
        FrameView view;
        view.resize(400, 320);
        QImage frame(200, 160, QImage::Format_RGB32);
        frame.fill(Qt::black);
        view.setImage(frame);
        view.setEditable(true);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        int edits = 0;
        connect(&view, &FrameView::landmarksEdited, &view, [&] { ++edits; });
        const QPointF before = view.imageToWidget(QPointF(50, 50));

        QTest::keyPress(&view, Qt::Key_Space);
        QTest::mousePress(&view, Qt::LeftButton, {}, QPoint(100, 100));
        QMouseEvent move(QEvent::MouseMove, QPointF(130, 80), view.mapToGlobal(QPointF(130, 80)),
                         Qt::NoButton, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&view, &move);
        QTest::mouseRelease(&view, Qt::LeftButton, {}, QPoint(130, 80));
        QKeyEvent release(QEvent::KeyRelease, Qt::Key_Space, Qt::NoModifier, QStringLiteral(" "));
        QApplication::sendEvent(&view, &release);

        QCOMPARE(edits, 0);
        QVERIFY(!view.landmarks() || view.nextUndefinedPoint() == 0);
        const QPointF after = view.imageToWidget(QPointF(50, 50));
        QCOMPARE(after - before, QPointF(30, -20));

        // Space released: a click edits again.
        QTest::mouseClick(&view, Qt::LeftButton, {}, QPoint(200, 160));
        QCOMPARE(edits, 1);
        QVERIFY(view.landmarks() && view.landmarks()->points[0].isDefined());
    }
};

QTEST_MAIN(TestFrameView)
#include "tst_frameview.moc"
