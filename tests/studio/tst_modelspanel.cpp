// The dynamics workflow from the Models panel: the bundled demo carries features and phonemes, so
// clicking Train trains the checked models as background tasks; the Training plot receives the
// objective per iteration, the models appear in the panel's list and in the document (one undo
// step each), a canceled training keeps the previous model, and Evaluate (k-fold) draws Figure 4.
#include "aam/AamModel.h"
#include "DemoWindow.h"

#include "annotate/FacesController.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "build/ModelsPanel.h"
#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "dynamics/ContextDependentModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/LabelledFolder.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneCoverage.h"
#include "dynamics/PhoneLabels.h"
#include "eval/RealismReport.h"
#include "plots/EvaluationChart.h"
#include "plots/ObjectivePlot.h"
#include "plots/ResultsPage.h"
#include "plots/TrajectoryView.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/ResourceLocator.h"
#include "widgets/ElidedLabel.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QPushButton>
#include <QScrollArea>
#include <QSet>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>
#include <QWheelEvent>

#include <algorithm>
#include <limits>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::studio::testing::openDemoWindow;

class TestModelsPanel : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    void checkOnly(const QStringList &kinds)
    {
        for (const QString &k : {"dpds", "slds", "brand", "hmm"})
            m_panel->kindCheck(k)->setChecked(kinds.contains(k));
    }
    bool listed(const QString &kind) const
    {
        for (int i = 0; i < m_panel->list()->topLevelItemCount(); ++i)
            if (m_panel->list()->topLevelItem(i)->data(1, Qt::UserRole).toString() == kind)
                return true;
        return false;
    }
    void waitIdle() { testing::waitForTasks(m_window); }

    MainWindow *m_window = nullptr;
    ModelsPanel *m_panel = nullptr;
    QTemporaryDir m_dir; // the saved copy of the demo, for the tests after savingTheDemoWritesTheTrainedModels

private slots:
    void initTestCase()
    {
        openDemoWindow(m_window);
        if (QTest::currentTestFailed())
            return;
        m_panel = m_window->findChild<ModelsPanel *>();
        QVERIFY(m_panel);
        waitIdle();
    }

    void cleanupTestCase() { delete m_window; }

    // The panel needs a context, not a window: built alone on the demo project, it trains and
    // plots what it trained for the context's current sequence.
    void worksWithAContextAndNoWindow()
    {
        StudioContext context;
        testing::openDemo(context);
        QTabWidget plots;
        ModelsPanel panel;
        panel.attach(&context, &plots);
        QCOMPARE(plots.count(), 4); // Trajectory, Training, Evaluation, Realism
        QVERIFY(panel.trainButton()->isEnabled());
        QVERIFY(!panel.buildAamButton()->isEnabled()); // no Faces menu to trigger
        for (const QString &kind : ModelKinds::ids())
            panel.kindCheck(kind)->setChecked(kind == QLatin1String("hmm"));
        QVERIFY(panel.compensateVarianceCheck()->isChecked()); // livelier lips unless asked otherwise
        panel.compensateVarianceCheck()->setChecked(false); // the paper's model
        QVERIFY(panel.contextStatesCheck()->isChecked()); // anticipating lips unless asked otherwise
        panel.contextStatesCheck()->setChecked(false);
        const QList<Task *> tasks = panel.train();
        QCOMPARE(tasks.size(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 60000);
        QVERIFY(context.modelStore()->dynamicModel(QStringLiteral("hmm")));
        QVERIFY(!context.modelStore()->dynamicModel(QStringLiteral("hmm"))->compensatesVariance());
        QVERIFY(!dynamic_cast<const ContextDependentModel *>(context.modelStore()->dynamicModel(QStringLiteral("hmm")).get()));
        QCOMPARE(context.undoStack()->undoText(), QStringLiteral("Train HMM-mean"));
        testing::makeCurrent(context, 2);
        QCOMPARE(panel.trajectoryView()->seriesCount(), 2); // the recording and HMM-mean
        context.setCurrentFrame(30);
        QVERIFY(std::abs(panel.trajectoryView()->cursorTime() - 30.5 / 25.0) < 1e-9);
    }

    // "Start from other speakers": HMM-mean's phone means (and Brand's) are the person's own moved by
    // the shipped prior's shift (MouthShapePrior, docs/models.md §5.4) carried onto the demo's face.
    void startsFromOtherSpeakers()
    {
        StudioContext context;
        testing::openDemo(context);
        QTabWidget plots;
        ModelsPanel panel;
        panel.attach(&context, &plots);
        for (const QString &kind : ModelKinds::ids())
            panel.kindCheck(kind)->setChecked(kind == QLatin1String("hmm"));
        panel.compensateVarianceCheck()->setChecked(false);
        panel.contextStatesCheck()->setChecked(false);
        QVERIFY(!panel.priorCheck()->isChecked()); // the person's own means unless asked
        // Trained without it on the demo's 30 s, the panel offers it for the phones they lack.
        QCOMPARE(panel.train().size(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 60000);
        QVERIFY2(panel.statusLabel()->toolTip().contains(QStringLiteral("Tick Start from other speakers")),
                 qPrintable(panel.statusLabel()->toolTip()));
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        QTest::mouseClick(panel.priorCheck(), Qt::LeftButton, {}, QPoint(8, panel.priorCheck()->height() / 2));
        QVERIFY(panel.priorCheck()->isChecked());
        // HMM-mean and Brand at once: both moved by the one shift.
        panel.kindCheck(QStringLiteral("brand"))->setChecked(true);
        QCOMPARE(panel.train().size(), 2);
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 60000);
        const auto trained = std::dynamic_pointer_cast<const HmmMeanModel>(context.modelStore()->dynamicModel(QStringLiteral("hmm")));
        QVERIFY(trained);
        const Project &project = context.document()->project();
        const std::vector<LabelledSequence> sequences = loadProjectSequences(project);
        auto plain = createDynamicModel("hmm");
        Feedback quiet;
        plain->train(sequences, quiet);
        const MouthShapePrior prior = MouthShapePrior::load(ResourceLocator::find("prior/grid-s1.mouthprior"));
        const Eigen::MatrixXd shift = projectPriorShift(prior, MouthMeasurer(*context.modelStore()->aam()), project,
                                                        sequences, MouthShapePrior::kCrossValidated);
        QVERIFY(shift.norm() > 0);
        QVERIFY2(panel.statusLabel()->toolTip().contains(QStringLiteral("their face comes from other speakers' mouths"))
                     && !panel.statusLabel()->toolTip().contains(QStringLiteral("Tick Start")),
                 qPrintable(panel.statusLabel()->toolTip()));
        QVERIFY(trained->means().isApprox(dynamic_cast<HmmMeanModel &>(*plain).means() + shift, 1e-9));
        // The model records it, and the list says so.
        QVERIFY(trained->meanShift().isApprox(shift, 1e-12));
        const auto brand = context.modelStore()->dynamicModel(QStringLiteral("brand"));
        QVERIFY(brand && brand->meanShift().isApprox(shift, 1e-12));
        QCOMPARE(brand->priorWeight(), trained->priorWeight());
        const QList<QTreeWidgetItem *> rows = panel.list()->findItems(ModelKinds::name(QStringLiteral("hmm")), Qt::MatchExactly, 1);
        QCOMPARE(rows.size(), 1);
        QVERIFY2(rows.front()->toolTip(1).endsWith(QStringLiteral("started from other speakers")),
                 qPrintable(rows.front()->toolTip(1)));
        // The paper's models hold it off.
        panel.paperModelsCheck()->setChecked(true);
        QVERIFY(!panel.priorCheck()->isChecked() && !panel.priorCheck()->isEnabled());
        panel.paperModelsCheck()->setChecked(false);
        QVERIFY(panel.priorCheck()->isChecked());
    }

    // The wheel over an unfocused spin box or combo box scrolls the panel and leaves the setting;
    // once the control has focus (a click, Tab) the wheel changes it.
    void wheelChangesOnlyAFocusedControl()
    {
        QSpinBox *folds = m_panel->foldsSpin();
        QComboBox *covariance = m_panel->brandCovariance();
        m_window->activateWindow();
        m_panel->trainButton()->setFocus();
        const int foldsBefore = folds->value();
        const int covarianceBefore = covariance->currentIndex();
        auto wheel = [](QWidget *w) {
            const QPointF at(w->width() / 2.0, w->height() / 2.0);
            QWheelEvent e(at, w->mapToGlobal(at), QPoint(), QPoint(0, -120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
            QApplication::sendEvent(w, &e);
        };
        for (int i = 0; i < 3; ++i) {
            wheel(folds);
            wheel(covariance);
        }
        QCOMPARE(folds->value(), foldsBefore);
        QCOMPARE(covariance->currentIndex(), covarianceBefore);
        QVERIFY(!folds->hasFocus());
        folds->setFocus();
        QTRY_VERIFY(folds->hasFocus());
        wheel(folds);
        QCOMPARE(folds->value(), foldsBefore - 1);
        folds->setValue(foldsBefore);
    }

    // The panel's actions and status hold still: outside the scrolled list and options, the same
    // place whatever the status says or however many models are listed.
    void actionsHoldStill()
    {
        auto *scroll = m_panel->findChild<QScrollArea *>(QStringLiteral("modelsScroll"));
        QVERIFY(scroll);
        const QList<QWidget *> still{m_panel->trainButton(), m_panel->evaluateButton(), m_panel->realismButton(),
                                     m_panel->cancelButton(), m_panel->statusLabel()};
        for (QWidget *b : still)
            QVERIFY(!scroll->isAncestorOf(b));
        const QPoint before = m_panel->evaluateButton()->mapTo(m_panel, QPoint(0, 0));
        m_panel->statusLabel()->setText(QStringLiteral("a long status ").repeated(30));
        QApplication::processEvents();
        QCOMPARE(m_panel->evaluateButton()->mapTo(m_panel, QPoint(0, 0)), before);
        m_panel->statusLabel()->clear();
    }

    // "Paper's models" holds every choice beyond the paper off while ticked (and trains so);
    // unticked, the user's settings come back.
    void paperPresetHoldsTheChoicesOff()
    {
        QCheckBox *paper = m_panel->paperModelsCheck();
        QVERIFY(!paper->isChecked());
        m_panel->compensateVarianceCheck()->setChecked(true);
        m_panel->contextStatesCheck()->setChecked(true);
        const int covariance = m_panel->brandCovariance()->currentIndex();
        paper->setChecked(true);
        QVERIFY(!m_panel->compensateVarianceCheck()->isChecked() && !m_panel->compensateVarianceCheck()->isEnabled());
        QVERIFY(!m_panel->contextStatesCheck()->isChecked() && !m_panel->contextStatesCheck()->isEnabled());
        QCOMPARE(m_panel->brandCovariance()->currentData().toInt(), int(BrandCovariance::Diagonal));
        QCOMPARE(m_panel->dpdsOptimizer()->currentData().toString(), QStringLiteral("gradient"));
        QVERIFY(!m_panel->brandCovariance()->isEnabled() && !m_panel->dpdsOptimizer()->isEnabled());
        paper->setChecked(false);
        QVERIFY(m_panel->compensateVarianceCheck()->isChecked() && m_panel->compensateVarianceCheck()->isEnabled());
        QVERIFY(m_panel->contextStatesCheck()->isChecked());
        QCOMPARE(m_panel->brandCovariance()->currentIndex(), covariance);
        QVERIFY(m_panel->brandCovariance()->isEnabled());
    }

    void demoHasTrainingData()
    {
        const Project &p = m_window->context()->document()->project();
        QCOMPARE(p.sequences.size(), size_t(10));
        for (const Sequence &s : p.sequences) {
            QCOMPARE(s.features.rows(), Eigen::Index(75));
            QVERIFY(!s.phones.isEmpty());
        }
        QVERIFY(listed(QStringLiteral("aam")));
        QVERIFY(!listed(QStringLiteral("hmm")));
        QVERIFY(m_panel->trainButton()->isEnabled());
        QVERIFY(!m_panel->cancelButton()->isEnabled());
        // Build AAM here is the Faces menu's action.
        QVERIFY(m_panel->buildAamButton()->isEnabled());
        QVERIFY(m_window->faces()->buildAamAction()->isEnabled());
    }

    void trainsHmmAndDpdsFromTheButton()
    {
        checkOnly({QStringLiteral("hmm"), QStringLiteral("dpds")});
        QSignalSpy trained(m_panel, &ModelsPanel::modelTrained);
        const int undoBefore = m_window->context()->undoStack()->count();
        QTest::mouseClick(m_panel->trainButton(), Qt::LeftButton);
        QCOMPARE(m_panel->runningTasks().size(), 2);
        QVERIFY(m_panel->cancelButton()->isEnabled());
        QVERIFY(!m_panel->trainButton()->isEnabled());
        QCOMPARE(m_panel->plotTabs()->currentWidget(), static_cast<QWidget *>(m_panel->objectivePlot()));
        waitIdle();
        QCOMPARE(trained.count(), 2);
        QVERIFY(m_window->context()->modelStore()->dynamicModel("hmm"));
        QVERIFY(m_window->context()->modelStore()->dynamicModel("dpds"));
        // The default: phones in context, tied by trees grown on the demo's clips.
        const auto *dpds = dynamic_cast<const ContextDependentModel *>(m_window->context()->modelStore()->dynamicModel("dpds").get());
        QVERIFY(dpds);
        QCOMPARE(dpds->inner().stateCount(), dpds->tree().stateCount());
        // The list says so.
        QString tip;
        for (int i = 0; i < m_panel->list()->topLevelItemCount(); ++i)
            if (m_panel->list()->topLevelItem(i)->data(1, Qt::UserRole).toString() == QLatin1String("dpds"))
                tip = m_panel->list()->topLevelItem(i)->toolTip(1);
        QVERIFY2(tip.contains(QStringLiteral("%1 states for phones in context").arg(dpds->tree().stateCount()))
                     && tip.contains(QStringLiteral("variance compensation")),
                 qPrintable(tip));
        // What the demo's 30 s lack for these options is said after training (and in full on hover).
        const PhoneCoverage coverage = PhoneCoverage::of(loadProjectSequences(m_window->context()->document()->project()));
        QVERIFY(!coverage.unseen.empty()); // GRID's small vocabulary
        QVERIFY2(m_panel->statusLabel()->text().contains(QStringLiteral("%1 of 39 phones never occur").arg(coverage.unseen.size())),
                 qPrintable(m_panel->statusLabel()->text()));
        QVERIFY(m_panel->statusLabel()->toolTip().contains(QStringLiteral("More footage of the person")));
        QCOMPARE(m_window->context()->modelStore()->dynamicModel("dpds")->dimension(), int(m_window->context()->document()->sequence(0).features.cols()));
        QVERIFY(m_window->context()->modelStore()->dynamicModel("dpds")->compensatesVariance()); // the panel's default
        // The live objective plot got the iterations of the iterative model (DPDS).
        QVERIFY2(m_panel->objectivePlot()->iterationCount("dpds") >= 2,
                 qPrintable(QString::number(m_panel->objectivePlot()->iterationCount("dpds"))));
        QVERIFY(m_panel->objectivePlot()->seriesCount() >= 1);
        // Listed in the panel and referenced by the (read-only, so in-memory) document.
        QVERIFY(listed(QStringLiteral("hmm")));
        QVERIFY(listed(QStringLiteral("dpds")));
        QCOMPARE(m_window->context()->undoStack()->count(), undoBefore + 2);
        const auto &models = m_window->context()->document()->project().models;
        QVERIFY(std::any_of(models.begin(), models.end(),
                            [](const ModelReference &m) { return m.kind == "dpds" && m.file == "models/dpds.model"; }));
        QVERIFY(m_panel->trainButton()->isEnabled());
        // Undo removes the reference again, redo restores it.
        m_window->context()->undoStack()->undo();
        QVERIFY(!listed(QStringLiteral("dpds")) || !listed(QStringLiteral("hmm")));
        m_window->context()->undoStack()->redo();
        QVERIFY(listed(QStringLiteral("hmm")) && listed(QStringLiteral("dpds")));
    }

    // The posture transfer each generated trajectory carries is built once per trained model and
    // AAM: listing the trajectories again hands back the same one.
    void postureTransferBuiltOncePerModel()
    {
        StudioContext *context = m_window->context();
        const std::shared_ptr<const AamModel> aam = context->modelStore()->aam();
        QVERIFY(aam);
        const auto first = context->generatedTrajectories(0, aam.get());
        const auto second = context->generatedTrajectories(0, aam.get());
        QCOMPARE(first.size(), second.size());
        int withPosture = 0;
        for (size_t i = 0; i < first.size(); ++i) {
            QCOMPARE(first[i].kind, second[i].kind);
            QCOMPARE(first[i].posture.get(), second[i].posture.get());
            withPosture += first[i].posture != nullptr;
        }
        QVERIFY(withPosture >= 1); // the DPDS trained above
        const auto withoutAam = context->generatedTrajectories(0, nullptr);
        QVERIFY(!withoutAam.empty());
        QVERIFY(withoutAam.front().posture == nullptr); // no AAM: none
    }

    void cancelKeepsThePreviousModel()
    {
        const std::shared_ptr<const DynamicModel> before = m_window->context()->modelStore()->dynamicModel("dpds");
        QVERIFY(before);
        checkOnly({QStringLiteral("dpds")});
        m_panel->dpdsOptimizer()->setCurrentIndex(1); // the paper's (slow) gradient ascent
        QSignalSpy trained(m_panel, &ModelsPanel::modelTrained);
        QTest::mouseClick(m_panel->trainButton(), Qt::LeftButton);
        const QList<Task *> tasks = m_panel->runningTasks();
        QCOMPARE(tasks.size(), 1);
        QPointer<Task> task = tasks.front();
        QSignalSpy finished(task.data(), &Task::finished);
        QTest::mouseClick(m_panel->cancelButton(), Qt::LeftButton);
        waitIdle();
        QTRY_COMPARE_WITH_TIMEOUT(finished.count(), 1, 60000);
        QCOMPARE(finished.front().front().value<Task::State>(), Task::State::Canceled);
        QCOMPARE(trained.count(), 0);
        QCOMPARE(m_window->context()->modelStore()->dynamicModel("dpds").get(), before.get());
        QVERIFY(listed(QStringLiteral("dpds")));
        m_panel->dpdsOptimizer()->setCurrentIndex(0);
    }

    void evaluatesByCrossValidation()
    {
        checkOnly({QStringLiteral("hmm"), QStringLiteral("brand")});
        m_panel->foldsSpin()->setValue(5);
        QSignalSpy evaluated(m_panel, &ModelsPanel::evaluated);
        QTest::mouseClick(m_panel->evaluateButton(), Qt::LeftButton);
        waitIdle();
        QCOMPARE(evaluated.count(), 1);
        QCOMPARE(m_panel->evaluationChart()->modelCount(), 2);
        QCOMPARE(m_panel->evaluationChart()->metricCount(), 4);
        QCOMPARE(m_panel->plotTabs()->currentWidget(), static_cast<QWidget *>(m_panel->evaluationPage()));
        // The values in the table below the charts, as drawn: a row per model, a column per metric.
        const QTableWidget *table = m_panel->evaluationPage()->table();
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->columnCount(), 4);
        const MetricSummary &l1 = m_panel->evaluationChart()->bars()[0].metrics.at("l1");
        QVERIFY2(table->item(0, 0)->text().startsWith(QString::number(l1.mean, 'g', 4)), qPrintable(table->item(0, 0)->text()));
        QVERIFY(table->item(0, 0)->text().contains(QStringLiteral("±")));
        QVERIFY(table->item(0, 0)->toolTip().contains(QStringLiteral("5 folds")));
        QVERIFY2(m_panel->evaluationPage()->stateText().startsWith(QStringLiteral("Evaluated 2 model")),
                 qPrintable(m_panel->evaluationPage()->stateText()));
        // Figure 4 is on screen: the bar colours of both models are in the picture.
        const QImage image = m_panel->evaluationChart()->grab().toImage();
        if (qEnvironmentVariableIsSet("LIPSYNC_SCREENSHOT"))
            image.save(qEnvironmentVariable("LIPSYNC_SCREENSHOT"));
        int purple = 0, orange = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x) {
                const QColor c = image.pixelColor(x, y);
                purple += qAbs(c.red() - 0x8e) < 12 && qAbs(c.green() - 0x24) < 12 && qAbs(c.blue() - 0xaa) < 12;
                orange += qAbs(c.red() - 0xfb) < 12 && qAbs(c.green() - 0x8c) < 12 && qAbs(c.blue() - 0x00) < 12;
            }
        QVERIFY2(purple > 50 && orange > 50, qPrintable(QStringLiteral("%1 %2").arg(purple).arg(orange)));
    }

    // The realism report from the panel: a background task over the same folds (cancelled here:
    // rendering every held-out clip is the benchmark's job), and its chart.
    void realismReportRunsAndCharts()
    {
        checkOnly({QStringLiteral("hmm")});
        QVERIFY(m_panel->realismButton()->isEnabled());
        const int evaluated = m_panel->evaluationChart()->modelCount();
        QTest::mouseClick(m_panel->realismButton(), Qt::LeftButton);
        const QList<Task *> tasks = m_panel->runningTasks();
        QCOMPARE(tasks.size(), 1);
        QVERIFY(!m_panel->realismButton()->isEnabled());
        // Its own page, shown and saying it is computing, while it runs.
        QCOMPARE(m_panel->plotTabs()->currentWidget(), static_cast<QWidget *>(m_panel->realismPage()));
        QVERIFY(m_panel->realismPage()->isComputing());
        QVERIFY2(m_panel->realismPage()->stateText().startsWith(QStringLiteral("Computing")),
                 qPrintable(m_panel->realismPage()->stateText()));
        QTest::mouseClick(m_panel->cancelButton(), Qt::LeftButton);
        waitIdle();
        QVERIFY(m_panel->realismButton()->isEnabled());
        QVERIFY(!m_panel->realismPage()->isComputing());
        QVERIFY(m_panel->realismPage()->stateText().startsWith(QStringLiteral("Canceled")));
        QCOMPARE(m_panel->evaluationChart()->modelCount(), evaluated); // the k-fold result stays

        RealismResult result;
        result.sequences = 10;
        result.folds = 2;
        for (const char *kind : {"tracked", "brand", "hmm"}) {
            RealismMethod method;
            method.kind = kind;
            for (const std::string &metric : realismMetrics())
                method.metrics[metric] = MetricSummary{{0.4, 0.6}, 0.5, 0.1};
            result.methods.push_back(method);
        }
        // The recording re-encoded: the observer's floor, no lips of its own.
        RealismMethod reencoded;
        reencoded.kind = RealismMethod::kReencoded;
        const double none = std::numeric_limits<double>::quiet_NaN();
        for (const std::string &metric : realismMetrics())
            reencoded.metrics[metric] = MetricSummary{{none, none}, none, none};
        reencoded.metrics["observerFrames"] = MetricSummary{{0.49, 0.51}, 0.5, 0.02};
        result.methods.push_back(reencoded);
        result.methods[1].metrics["lag"] = MetricSummary{{1, 2}, 1.5, 0.25};
        result.methods[0].metrics["shapeCorrelation"] = MetricSummary{{none, none}, none, none};
        result.methods[1].metrics["shapeCorrelation"] = MetricSummary{{none, none}, none, none};
        result.methods[2].metrics["shapeCorrelation"] = MetricSummary{{none, none}, none, none};
        ResultsPage *page = m_panel->realismPage();
        page->setRealism(result, QStringLiteral("test"));
        QCOMPARE(page->chart()->modelCount(), 3);
        QCOMPARE(page->chart()->metricCount(), 4);
        // The table holds every measure with a figure (a row each, explained in its tooltip) for
        // every method, the re-encoded recording included, in the report's order.
        QTableWidget *table = page->table();
        QCOMPARE(table->columnCount(), 4);
        QCOMPARE(table->horizontalHeaderItem(3)->text(), QStringLiteral("recording, re-encoded"));
        QCOMPARE(table->rowCount(), int(realismMetrics().size()) - 1); // shapeCorrelation: no figure
        QStringList rows;
        for (int r = 0; r < table->rowCount(); ++r) {
            rows << table->verticalHeaderItem(r)->text();
            QVERIFY2(!table->verticalHeaderItem(r)->toolTip().isEmpty(), qPrintable(rows.last()));
        }
        QCOMPARE(rows.first(), EvaluationChart::metricLabel("speechCorrelation"));
        QCOMPARE(rows[1], EvaluationChart::metricLabel("controlSpeechCorrelation"));
        QVERIFY(table->verticalHeaderItem(1)->toolTip().contains(QStringLiteral("another clip's render")));
        for (const char *measure : {"seamDeltaE", "seamDeltaENatural", "falseClosures", "closureRecall"})
            QVERIFY2(rows.contains(EvaluationChart::metricLabel(measure)), measure);
        QCOMPARE(QSet<QString>(rows.begin(), rows.end()).size(), rows.size()); // no two rows alike
        const int lag = int(rows.indexOf(EvaluationChart::metricLabel("lag")));
        const int observer = int(rows.indexOf(EvaluationChart::metricLabel("observerFrames")));
        QCOMPARE(table->item(lag, 1)->text(), QStringLiteral("1.5 ± 0.25"));
        QCOMPARE(table->item(lag, 0)->text(), QStringLiteral("0.5 ± 0.1"));
        QCOMPARE(table->item(lag, 3)->text(), QStringLiteral("–"));
        QCOMPARE(table->item(observer, 3)->text(), QStringLiteral("0.5 ± 0.02"));
        QVERIFY(table->item(observer, 3)->toolTip().contains(QStringLiteral("2 folds")));
        QCOMPARE(page->chart()->hoverText(0, 1), ModelKinds::name(QStringLiteral("brand")) + QStringLiteral(": 0.5"));
        if (qEnvironmentVariableIsSet("LIPSYNC_REALISM_SCREENSHOT"))
            page->grab().toImage().save(qEnvironmentVariable("LIPSYNC_REALISM_SCREENSHOT"));
        QCOMPARE(page->chart()->modelNames(),
                 (QStringList{QStringLiteral("tracked"), ModelKinds::name(QStringLiteral("brand")),
                              ModelKinds::name(QStringLiteral("hmm"))}));
    }

    void savingTheDemoWritesTheTrainedModels()
    {
        QVERIFY(m_dir.isValid());
        const QString folder = m_dir.filePath(QStringLiteral("copy"));
        m_window->context()->document()->saveTo(folder);
        QVERIFY(!m_window->context()->document()->isReadOnly());
        // The models trained in memory went to models/, the demo's AAM was copied along.
        for (const char *file : {"models/dpds.model", "models/hmm.model", "aam/demo.aam"})
            QVERIFY2(QFileInfo(QDir(folder).filePath(QString::fromLatin1(file))).isFile(), file);
        std::string recordedAam;
        const std::unique_ptr<DynamicModel> loaded =
            loadModel(QDir(folder).filePath("models/dpds.model").toStdString(), {}, &recordedAam);
        // It records the content identifier of the AAM its features came from (what `lipsync render`
        // checks), not the AAM's display name.
        QCOMPARE(recordedAam, AamModel::load(QDir(folder).filePath("aam/demo.aam").toStdString()).identifier);
        const Sequence &s = m_window->context()->document()->sequence(0);
        const std::vector<int> labels = frameLabelsFromTier(s.phones, s.frameRate, s.frameCount);
        QVERIFY(loaded->generate(labels).isApprox(m_window->context()->modelStore()->dynamicModel("dpds")->generate(labels)));
        // A project on disk: the next training writes its model file at once.
        checkOnly({QStringLiteral("brand")});
        QTest::mouseClick(m_panel->trainButton(), Qt::LeftButton);
        waitIdle();
        QVERIFY(QFileInfo(QDir(folder).filePath("models/brand.model")).isFile());
        const Project reloaded = Project::load(folder.toStdString());
        QCOMPARE(reloaded.models.size(), size_t(3)); // the AAM, HMM and DPDS (Brand: not saved yet)
    }

    void undoingARetrainRestoresThePreviousModel()
    {
        // The saved copy of the demo from the test before: DPDS is trained and on disk.
        ProjectDocument *doc = m_window->context()->document();
        QVERIFY(!doc->isReadOnly());
        ModelStore *store = m_window->context()->modelStore();
        const std::shared_ptr<const DynamicModel> first = store->dynamicModel(QStringLiteral("dpds"));
        QVERIFY(first);
        const QString firstFile = QString::fromStdString(doc->project().model("dpds")->file);
        const QString firstPath = QDir(doc->folder()).filePath(firstFile);
        QFile firstOnDisk(firstPath);
        QVERIFY(firstOnDisk.open(QIODevice::ReadOnly));
        const QByteArray firstBytes = firstOnDisk.readAll();
        firstOnDisk.close();

        // Retrain with the other optimiser: a new model in a file of its own.
        checkOnly({QStringLiteral("dpds")});
        m_panel->dpdsOptimizer()->setCurrentIndex(1);
        QTest::mouseClick(m_panel->trainButton(), Qt::LeftButton);
        waitIdle();
        m_panel->dpdsOptimizer()->setCurrentIndex(0);
        const std::shared_ptr<const DynamicModel> second = store->dynamicModel(QStringLiteral("dpds"));
        QVERIFY(second && second != first);
        const QString secondFile = QString::fromStdString(doc->project().model("dpds")->file);
        QVERIFY2(secondFile != firstFile, qPrintable(secondFile));
        QVERIFY(QFileInfo(QDir(doc->folder()).filePath(secondFile)).isFile());
        QVERIFY(firstOnDisk.open(QIODevice::ReadOnly));
        QCOMPARE(firstOnDisk.readAll(), firstBytes); // the first model's file is untouched
        firstOnDisk.close();
        QCOMPARE(m_window->context()->undoStack()->undoText(), QStringLiteral("Train DPDS"));

        // Undo: the previous model is the one in use everywhere (trajectory plot included).
        m_window->context()->undoStack()->undo();
        QCOMPARE(QString::fromStdString(doc->project().model("dpds")->file), firstFile);
        QCOMPARE(store->dynamicModel(QStringLiteral("dpds")).get(), first.get());
        // Redo: the retrained one again.
        m_window->context()->undoStack()->redo();
        QCOMPARE(store->dynamicModel(QStringLiteral("dpds")).get(), second.get());

        // Saved and opened again, the project uses the retrained model; an undo after opening
        // is not possible, but the first file is still there for whoever wants it.
        doc->saveTo(doc->folder());
        const Project reloaded = Project::load(doc->folder().toStdString());
        QCOMPARE(QString::fromStdString(reloaded.model("dpds")->file), secondFile);
        QVERIFY(QFileInfo(firstPath).isFile());
    }
};

QTEST_MAIN(TestModelsPanel)
#include "tst_modelspanel.moc"
