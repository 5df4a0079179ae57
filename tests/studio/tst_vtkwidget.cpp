// The VTK adaptor must really draw under Xvfb: render a line chart in the widget, grab it (the
// grab includes the GL content) and find the series' colour inside the plot area.
#include "app/SurfaceFormat.h"
#include "plots/LineChartView.h"

#include <QTest>

#include <cmath>

using namespace lipsync::studio;

namespace {

int countNear(const QImage &image, const QColor &color, int tolerance)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - color.red()) <= tolerance && std::abs(c.green() - color.green()) <= tolerance
                && std::abs(c.blue() - color.blue()) <= tolerance)
                ++n;
        }
    return n;
}

} // namespace

class TestVtkWidget : public QObject
{
    Q_OBJECT
public:
    static void initMain() { setDefaultSurfaceFormat(); }

private slots:
    void chartDrawsSeries()
    {
        LineChartView chart;
        chart.resize(480, 320);
        chart.setTitle(QStringLiteral("sine"));
        chart.setAxisTitles(QStringLiteral("t"), QStringLiteral("y"));
        QVector<double> x;
        QVector<double> y;
        for (int i = 0; i <= 200; ++i) {
            x.append(i / 20.0);
            y.append(std::sin(i / 20.0));
        }
        const QColor series(200, 30, 30);
        QCOMPARE(chart.addSeries(QStringLiteral("sin"), x, y, series, 3.0f), 0);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));

        // Plot area: the inner part of the widget, away from axes and title.
        const QImage image = chart.grab().toImage().convertToFormat(QImage::Format_RGB32);
        QVERIFY(!image.isNull());
        const QRect plotArea(image.width() / 6, image.height() / 6, image.width() * 2 / 3, image.height() * 2 / 3);
        const QImage plot = image.copy(plotArea);
        const int seriesPixels = countNear(plot, series, 60);
        const int white = countNear(plot, Qt::white, 3);
        QVERIFY2(seriesPixels > 200, qPrintable(QStringLiteral("series pixels: %1").arg(seriesPixels)));
        QVERIFY2(white > plot.width() * plot.height() / 2, "the background is not the chart's white");
    }

    void cursorAndClear()
    {
        LineChartView chart;
        chart.resize(320, 240);
        chart.addSeries(QStringLiteral("a"), {0, 1, 2}, {0, 1, 0}, Qt::blue);
        chart.setCursor(1.0);
        QCOMPARE(chart.seriesCount(), 1);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        const QImage image = chart.grab().toImage().convertToFormat(QImage::Format_RGB32);
        int reddish = 0; // the cursor line: thin and anti-aliased, so "clearly red" rather than exact
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                reddish += c.red() > 180 && c.green() < 170 && c.blue() < 170 && c.red() - c.green() > 60 ? 1 : 0;
            }
        QVERIFY2(reddish > 20, qPrintable(QStringLiteral("%1 cursor pixels").arg(reddish)));
        chart.clearSeries();
        QCOMPARE(chart.seriesCount(), 0);
    }
};

QTEST_MAIN(TestVtkWidget)
#include "tst_vtkwidget.moc"
