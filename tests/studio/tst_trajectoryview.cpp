// The trajectory plot of the Plots dock: after training, the current sequence's real AAM
// parameter and each model's generation are drawn (their colours are on screen) over shaded
// phoneme bands; the parameter spin box switches the parameter; the cursor follows the current
// frame of the main window (the transport's next-frame action); the wheel zooms.
#include "DemoWindow.h"

#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "build/ModelsPanel.h"
#include "context/ErrorReporter.h"
#include "context/StudioActions.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "plots/TrajectoryView.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QCheckBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTest>

#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::studio::testing::openDemoWindow;

namespace {

int countColour(const QImage &image, QColor colour, int tolerance = 16)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const QColor c = image.pixelColor(x, y);
            n += qAbs(c.red() - colour.red()) < tolerance && qAbs(c.green() - colour.green()) < tolerance
                 && qAbs(c.blue() - colour.blue()) < tolerance;
        }
    return n;
}

const QColor kReal(0x1e, 0x88, 0xe5);
const QColor kDpds(0xe5, 0x39, 0x35);
const QColor kHmm(0x8e, 0x24, 0xaa);
const QColor kBand(225, 232, 240);

} // namespace

class TestTrajectoryView : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    MainWindow *m_window = nullptr;
    ModelsPanel *m_panel = nullptr;

private slots:
    void initTestCase()
    {
        openDemoWindow(m_window);
        if (QTest::currentTestFailed())
            return;
        m_panel = m_window->findChild<ModelsPanel *>();
        QVERIFY(m_panel);
    }

    void cleanupTestCase() { delete m_window; }

    void drawsRealFeaturesBeforeTraining()
    {
        TrajectoryView *view = m_panel->trajectoryView();
        m_panel->plotTabs()->setCurrentWidget(view->parentWidget());
        QTRY_VERIFY(view->isVisible());
        QCOMPARE(view->seriesCount(), 1);
        QVERIFY(view->phoneBandCount() > 6);
        QCOMPARE(m_panel->parameterSpin()->maximum() + 1, int(m_window->context()->document()->sequence(0).features.cols()));
        const QImage image = view->grab().toImage();
        QVERIFY2(countColour(image, kReal) > 30, "the real trajectory is not drawn");
        QVERIFY2(countColour(image, kBand, 4) > 500, "the phoneme bands are not drawn");
        // In the docked chart the phonemes' names would run into each other: some are left out,
        // the rest written; wider, more of them fit.
        const int docked = view->phoneLabelsShown();
        QVERIFY2(docked > 2 && docked < view->phoneBandCount(), qPrintable(QString::number(docked)));
        TrajectoryView wide;
        wide.resize(1800, 400);
        const Sequence &first = m_window->context()->document()->sequence(0);
        QVector<double> values;
        for (Eigen::Index f = 0; f < first.features.rows(); ++f)
            values.append(first.features(f, 0));
        wide.setData(QStringLiteral("wide"), first.clock(), first.phones, {{QStringLiteral("real"), values, QColor(Qt::blue)}});
        wide.show();
        QVERIFY(QTest::qWaitForWindowExposed(&wide));
        (void)wide.grab();
        QVERIFY2(wide.phoneLabelsShown() > docked, qPrintable(QString::number(wide.phoneLabelsShown())));
        QCOMPARE(countColour(image, kDpds), 0);
    }

    void drawsGeneratedSeriesAfterTraining()
    {
        for (const QString &k : {"dpds", "slds", "brand", "hmm"})
            m_panel->kindCheck(k)->setChecked(k == QLatin1String("dpds") || k == QLatin1String("hmm"));
        QTest::mouseClick(m_panel->trainButton(), Qt::LeftButton);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->taskRunner()->runningCount(), 0, 120000);
        TrajectoryView *view = m_panel->trajectoryView();
        QCOMPARE(view->seriesCount(), 3); // real, DPDS, HMM
        m_panel->plotTabs()->setCurrentWidget(view->parentWidget());
        QTRY_VERIFY(view->isVisible());
        const QImage image = view->grab().toImage();
        QVERIFY2(countColour(image, kReal) > 30, "real");
        QVERIFY2(countColour(image, kDpds) > 30, "DPDS");
        QVERIFY2(countColour(image, kHmm) > 30, "HMM");
        if (qEnvironmentVariableIsSet("LIPSYNC_SCREENSHOT"))
            m_window->grab().save(qEnvironmentVariable("LIPSYNC_SCREENSHOT"));

        // Another parameter: another picture, same series.
        const QImage before = image;
        m_panel->parameterSpin()->setValue(1);
        QCOMPARE(view->seriesCount(), 3);
        QVERIFY(view->grab().toImage() != before);
    }

    void cursorFollowsTheCurrentFrame()
    {
        TrajectoryView *view = m_panel->trajectoryView();
        m_window->context()->setCurrentFrame(0);
        QCOMPARE(view->cursorTime(), 0.5 / 25.0);
        const QImage at0 = view->grab().toImage();
        // Five frames on through the window's own next-frame action (what the arrow key does).
        for (int i = 0; i < 5; ++i)
            m_window->actions().nextFrame->trigger();
        QCOMPARE(m_window->context()->currentFrame(), 5);
        QVERIFY(std::abs(view->cursorTime() - 5.5 / 25.0) < 1e-12);
        QVERIFY(view->grab().toImage() != at0);
        m_window->context()->setCurrentFrame(40);
        QVERIFY(std::abs(view->cursorTime() - 40.5 / 25.0) < 1e-12);
    }

    void wheelZooms()
    {
        TrajectoryView *view = m_panel->trajectoryView();
        double from = 0, to = 0;
        view->visibleRange(from, to);
        const double width = to - from;
        QVERIFY(width > 2.5);
        const QPoint centre = view->rect().center();
        QWheelEvent wheel(centre, view->mapToGlobal(centre), QPoint(), QPoint(0, 120), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(view, &wheel);
        view->grab(); // render, so the chart applies the interaction
        view->visibleRange(from, to);
        QVERIFY2(to - from < width, qPrintable(QStringLiteral("%1 -> %2").arg(width).arg(to - from)));
    }
};

QTEST_MAIN(TestTrajectoryView)
#include "tst_trajectoryview.moc"
