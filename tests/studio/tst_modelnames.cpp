// Every place the studio names a dynamic model names it as the registry (ModelKinds) does: the
// Models panel's check boxes and list, the status bar's models in use, the legends of the
// Training and Trajectory plots, the bars of the Evaluation chart, File ▸ Export's choice of
// model, the Generate from Speech dialog and the study set-up and results. Two panels that name
// a model differently fail here.
#include "DemoWindow.h"

#include "app/MainWindow.h"
#include "build/ModelsPanel.h"
#include "compare/StudyResultsView.h"
#include "compare/StudySetupDialog.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "dynamics/ModelKind.h"
#include "export/ExportMenu.h"
#include "plots/EvaluationChart.h"
#include "plots/ObjectivePlot.h"
#include "plots/TrajectoryView.h"
#include "preview/SpeechDialog.h"
#include "project/ForcedChoiceStudy.h"
#include "tasks/TaskRunner.h"

#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>
#include <QTreeWidget>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::studio::testing::openDemoWindow;

class TestModelNames : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    void waitIdle() { testing::waitForTasks(m_window, 300000); }

    MainWindow *m_window = nullptr;
    ModelsPanel *m_panel = nullptr;

private slots:
    void initTestCase()
    {
        openDemoWindow(m_window);
        if (QTest::currentTestFailed())
            return;
        m_panel = m_window->modelsPanel();
        QVERIFY(m_panel);
        // All four kinds, trained on the demo (few iterations: only the names matter here).
        for (const QString &kind : ModelKinds::ids())
            m_panel->kindCheck(kind)->setChecked(true);
        QTest::mouseClick(m_panel->trainButton(), Qt::LeftButton);
        waitIdle();
        for (const QString &kind : ModelKinds::ids())
            QVERIFY2(m_window->context()->modelStore()->dynamicModel(kind), qPrintable(kind));
    }

    void cleanupTestCase() { delete m_window; }

    void registryCoversCoreKinds()
    {
        QCOMPARE(ModelKinds::ids().size(), qsizetype(dynamicModelKinds().size()));
        QStringList names;
        for (const std::string &id : dynamicModelKinds()) {
            const QString kind = QString::fromStdString(id);
            QVERIFY(ModelKinds::ids().contains(kind));
            QVERIFY(!ModelKinds::name(kind).isEmpty());
            QVERIFY(ModelKinds::name(kind) != kind);
            QVERIFY(!names.contains(ModelKinds::name(kind)));
            names.append(ModelKinds::name(kind));
        }
    }

    void modelsPanel()
    {
        for (const QString &kind : ModelKinds::ids())
            QCOMPARE(m_panel->kindCheck(kind)->text(), ModelKinds::name(kind));
        int listed = 0;
        for (int i = 0; i < m_panel->list()->topLevelItemCount(); ++i) {
            const QTreeWidgetItem *item = m_panel->list()->topLevelItem(i);
            const QString kind = item->data(1, Qt::UserRole).toString();
            if (!ModelKinds::contains(kind))
                continue;
            QCOMPARE(item->text(1), ModelKinds::name(kind));
            ++listed;
        }
        QCOMPARE(listed, 4);
    }

    void statusBar()
    {
        const auto *active = m_window->findChild<QLabel *>(QStringLiteral("activeModels"));
        QVERIFY(active);
        QStringList shown = active->text().section(QStringLiteral("Models: "), 1).split(QStringLiteral(", "));
        shown.sort();
        QStringList expected;
        for (const QString &kind : ModelKinds::ids())
            expected.append(ModelKinds::name(kind));
        expected.sort();
        QCOMPARE(shown, expected);
    }

    void trainingLegend()
    {
        // One legend entry "<name>: <objective>" per model trained iteratively (SLDS, DPDS).
        const QStringList legend = m_panel->objectivePlot()->seriesNames();
        QVERIFY(!legend.isEmpty());
        for (const QString &entry : legend) {
            const QString name = entry.section(QStringLiteral(": "), 0, 0);
            bool known = false;
            for (const QString &kind : ModelKinds::ids())
                known = known || name == ModelKinds::name(kind);
            QVERIFY2(known, qPrintable(entry));
        }
        for (const char *kind : {"dpds", "slds"})
            QVERIFY2(legend.filter(ModelKinds::name(QString::fromLatin1(kind)) + QStringLiteral(": ")).size() == 1,
                     qPrintable(legend.join(QLatin1Char('|'))));
    }

    void trajectoryLegend()
    {
        m_window->context()->selectSequence(0);
        QStringList expected{QStringLiteral("real")};
        for (const QString &kind : ModelKinds::ids())
            expected.append(ModelKinds::name(kind));
        QTRY_COMPARE(m_panel->trajectoryView()->seriesNames(), expected);
    }

    void evaluationBars()
    {
        m_panel->foldsSpin()->setValue(2);
        QTest::mouseClick(m_panel->evaluateButton(), Qt::LeftButton);
        waitIdle();
        const QStringList bars = m_panel->evaluationChart()->modelNames();
        QCOMPARE(bars.size(), 4);
        for (const QString &kind : ModelKinds::ids())
            QVERIFY2(bars.contains(ModelKinds::name(kind)), qPrintable(bars.join(QLatin1Char('|'))));
    }

    void exportModelChoice()
    {
        // With several trained models Export asks which one: by the registry's names.
        ExportMenu *menu = m_window->exportMenu();
        QStringList kinds, names;
        menu->setModelPrompt([&](const QStringList &k, const QStringList &n) {
            kinds = k;
            names = n;
            return QString(); // cancel
        });
        QVERIFY(!menu->trigger(ExportMenu::Kind::Model));
        QCOMPARE(kinds, ModelKinds::ids());
        for (int i = 0; i < kinds.size(); ++i)
            QCOMPARE(names.value(i), ModelKinds::name(kinds[i]));
    }

    void speechDialog()
    {
        SpeechDialog dialog(ModelKinds::ids(), 25.0, m_window);
        QCOMPARE(dialog.modelCombo()->count(), 4);
        for (int i = 0; i < dialog.modelCombo()->count(); ++i)
            QCOMPARE(dialog.modelCombo()->itemText(i), ModelKinds::name(dialog.modelCombo()->itemData(i).toString()));
    }

    void studySetupAndResults()
    {
        StudySetupDialog setup(m_window->context()->document()->project(), m_window);
        int models = 0;
        for (int i = 0; i < setup.methodList()->count(); ++i) {
            const QListWidgetItem *item = setup.methodList()->item(i);
            const QString method = item->data(Qt::UserRole).toString();
            if (!ModelKinds::contains(method))
                continue;
            QCOMPARE(item->text(), ModelKinds::name(method));
            ++models;
        }
        QCOMPARE(models, 4);

        // The results tables name the methods as the set-up does.
        setup.utteranceCount()->setValue(1);
        QString problem;
        std::optional<ForcedChoiceStudy> study = setup.study(&problem);
        QVERIFY2(study, qPrintable(problem));
        StudyResultsView results;
        results.setStudy(&*study);
        QStringList shown;
        for (QTableWidget *table : results.findChildren<QTableWidget *>())
            for (int r = 0; r < table->rowCount(); ++r)
                if (table->item(r, 0))
                    shown.append(table->item(r, 0)->text());
        for (const QString &name : shown)
            QVERIFY2(!ModelKinds::contains(name), qPrintable(name)); // no id where a name belongs
        int named = 0;
        for (const QString &kind : ModelKinds::ids())
            named += shown.contains(ModelKinds::name(kind)) ? 1 : 0;
        QCOMPARE(named, 4);
    }
};

QTEST_MAIN(TestModelNames)
#include "tst_modelnames.moc"
