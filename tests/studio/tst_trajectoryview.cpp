// The trajectory plot of the Plots dock: after training, the current sequence's real AAM
// parameter and each model's generation are drawn (their colours are on screen) over shaded
// phoneme bands; the parameter spin box switches the parameter; the cursor follows the current
// frame (the next-frame command); the wheel zooms. The panel on a studio context, without a window.
#include "DemoWindow.h"

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
#include <QHBoxLayout>
#include <QTabWidget>
#include <QTest>
#include <QTreeWidget>

#include <cmath>
#include <memory>

using namespace lipsync;
using namespace lipsync::studio;

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
    StudioContext m_context;
    QWidget m_host; // the Models panel beside the Plots tabs, as the window docks them
    ModelsPanel *m_panel = nullptr;
    std::unique_ptr<StudioActions> m_actions;

private slots:
    void initTestCase()
    {
        ErrorReporter::setBatchMode(true);
        auto *layout = new QHBoxLayout(&m_host);
        auto *plots = new QTabWidget(&m_host);
        m_panel = new ModelsPanel(&m_host);
        m_panel->attach(&m_context, plots);
        layout->addWidget(m_panel);
        layout->addWidget(plots, 1);
        m_actions = std::make_unique<StudioActions>(&m_host, &m_context);
        m_host.resize(1000, 400);
        m_host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&m_host));
        testing::openDemo(m_context);
        QCOMPARE(m_panel->list()->topLevelItemCount(), 1); // the demo's AAM: the panel follows the document
        m_context.selectSequence(0);
        QTRY_VERIFY_WITH_TIMEOUT(m_context.media() != nullptr, 60000);
    }

    void cleanupTestCase() { QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000); }

    void drawsRealFeaturesBeforeTraining()
    {
        TrajectoryView *view = m_panel->trajectoryView();
        m_panel->plotTabs()->setCurrentWidget(view->parentWidget());
        QTRY_VERIFY(view->isVisible());
        QCOMPARE(view->seriesCount(), 1);
        QVERIFY(view->phoneBandCount() > 6);
        QCOMPARE(m_panel->parameterSpin()->maximum() + 1, int(m_context.document()->sequence(0).features.cols()));
        const QImage image = view->grab().toImage();
        QVERIFY2(countColour(image, kReal) > 30, "the real trajectory is not drawn");
        QVERIFY2(countColour(image, kBand, 4) > 500, "the phoneme bands are not drawn");
        // In the docked chart the phonemes' names would run into each other: some are left out,
        // the rest written; wider, more of them fit.
        const int docked = view->phoneLabelsShown();
        QVERIFY2(docked > 2 && docked < view->phoneBandCount(), qPrintable(QString::number(docked)));
        TrajectoryView wide;
        wide.resize(1800, 400);
        const Sequence &first = m_context.document()->sequence(0);
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
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 120000);
        QCOMPARE(m_panel->list()->topLevelItemCount(), 3); // the AAM and the two trained models
        TrajectoryView *view = m_panel->trajectoryView();
        QCOMPARE(view->seriesCount(), 3); // real, DPDS, HMM
        m_panel->plotTabs()->setCurrentWidget(view->parentWidget());
        QTRY_VERIFY(view->isVisible());
        const QImage image = view->grab().toImage();
        QVERIFY2(countColour(image, kReal) > 30, "real");
        QVERIFY2(countColour(image, kDpds) > 30, "DPDS");
        QVERIFY2(countColour(image, kHmm) > 30, "HMM");
        if (qEnvironmentVariableIsSet("LIPSYNC_SCREENSHOT"))
            m_host.grab().save(qEnvironmentVariable("LIPSYNC_SCREENSHOT"));

        // Another parameter: another picture, same series.
        const QImage before = image;
        m_panel->parameterSpin()->setValue(1);
        QCOMPARE(view->seriesCount(), 3);
        QVERIFY(view->grab().toImage() != before);
    }

    void cursorFollowsTheCurrentFrame()
    {
        TrajectoryView *view = m_panel->trajectoryView();
        m_context.setCurrentFrame(0);
        QCOMPARE(view->cursorTime(), 0.5 / 25.0);
        const QImage at0 = view->grab().toImage();
        // Five frames on through the next-frame command (what the arrow key does).
        for (int i = 0; i < 5; ++i)
            m_actions->nextFrame->trigger();
        QCOMPARE(m_context.currentFrame(), 5);
        QVERIFY(std::abs(view->cursorTime() - 5.5 / 25.0) < 1e-12);
        QVERIFY(view->grab().toImage() != at0);
        m_context.setCurrentFrame(40);
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
