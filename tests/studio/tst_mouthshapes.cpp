// File ▸ Export ▸ Mouth Shapes and the two animation exports, on a studio context with the demo:
//  - the dialog learns the nine shapes from the demo's tracked, aligned frames in the background,
//    shows each one's picture, what taught it and its four features;
//  - editing a feature is the user's shape: one undo step for a run of edits of one row, undone
//    as a whole; From Frame takes the shown frame's mouth; Learned resets;
//  - the exports write Rhubarb cues and controls that follow the user's shapes.
#include "DemoWindow.h"

#include "animation/AnimationControls.h"
#include "animation/MouthCues.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "export/ExportMenu.h"
#include "export/MouthShapesDialog.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;

class TestMouthShapes : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    StudioContext m_context;
    QMenu m_file;
    QWidget m_window;
    ExportMenu *m_menu = nullptr;

    MouthShapesDialog *dialog() const { return m_menu->mouthShapesDialog(); }
    void waitIdle() { QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000); }

private slots:
    void initTestCase()
    {
        ErrorReporter::setBatchMode(true);
        testing::openDemo(m_context);
        m_menu = new ExportMenu(&m_context, &m_file, &m_window);
        testing::makeCurrent(m_context, 0);
    }

    void dialogShowsTheLearnedShapes()
    {
        QVERIFY(m_menu->mouthShapesAction()->isEnabled());
        m_menu->mouthShapesAction()->trigger();
        QVERIFY(dialog() && dialog()->isVisible());
        waitIdle();
        QVERIFY(dialog()->mapping());
        QVERIFY2(dialog()->statusLabel()->text().contains("750 frames"), qPrintable(dialog()->statusLabel()->text()));
        for (MouthShape s : {MouthShape::A, MouthShape::B, MouthShape::D, MouthShape::F}) {
            QVERIFY(dialog()->featureBox(s, 0)->isEnabled());
            QCOMPARE(dialog()->featureBox(s, 0)->value(), std::round(dialog()->mapping()->shape(s)[0] * 100) / 100);
            QVERIFY(!dialog()->resetButton(s)->isEnabled()); // nothing of the user's yet
        }
        QVERIFY(!dialog()->featureBox(MouthShape::X, 0)->isEnabled()); // rest: nothing to set
        QVERIFY(dialog()->findChildren<QLabel *>().size() > 30);
        if (qEnvironmentVariableIsSet("LIPSYNC_TEST_SCREENSHOTS"))
            dialog()->grab().save(qEnvironmentVariable("LIPSYNC_TEST_SCREENSHOTS") + "/mouth-shapes.png");
    }

    void editsAreOneUndoStepPerRow()
    {
        QUndoStack *undo = m_context.undoStack();
        const int steps = undo->count();
        QDoubleSpinBox *opening = dialog()->featureBox(MouthShape::D, 0);
        QDoubleSpinBox *width = dialog()->featureBox(MouthShape::D, 1);
        opening->setValue(0.95);
        width->setValue(0.30);
        QCOMPARE(undo->count(), steps + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Set Mouth Shape D"));
        const auto &shapes = m_context.document()->project().mouthShapes;
        QCOMPARE(shapes.size(), size_t(1));
        QCOMPARE(shapes.at("D")[0], 0.95);
        QCOMPARE(shapes.at("D")[1], 0.30);
        QVERIFY(dialog()->resetButton(MouthShape::D)->isEnabled());
        QCOMPARE(dialog()->mapping()->shape(MouthShape::D)[1], 0.30);
        undo->undo();
        QVERIFY(m_context.document()->project().mouthShapes.empty());
        QVERIFY(std::abs(opening->value() - 0.95) > 0.01); // the learned value shown again
        undo->redo();
        QTest::mouseClick(dialog()->resetButton(MouthShape::D), Qt::LeftButton);
        QVERIFY(m_context.document()->project().mouthShapes.empty());
        QCOMPARE(undo->undoText(), QStringLiteral("Reset Mouth Shape D"));
    }

    void fromFrameTakesTheShownMouth()
    {
        m_context.setCurrentFrame(40);
        QTest::mouseClick(dialog()->fromFrameButton(MouthShape::C), Qt::LeftButton);
        QCOMPARE(m_context.undoStack()->undoText(), QStringLiteral("Mouth Shape C from Frame 41"));
        const auto &shapes = m_context.document()->project().mouthShapes;
        QVERIFY(shapes.count("C"));
        QCOMPARE(dialog()->featureBox(MouthShape::C, 2)->value(), std::round(shapes.at("C")[2] * 100) / 100);
        m_context.undoStack()->undo();
    }

    void exportsFollowTheUsersShapes()
    {
        QTemporaryDir dir;
        QString path;
        m_menu->setPathPrompt([&path](const ExportMenu::PathRequest &) { return path; });
        path = dir.filePath("cues.json");
        QSignalSpy exported(m_menu, &ExportMenu::exported);
        QVERIFY(m_menu->trigger(ExportMenu::Kind::MouthCues));
        waitIdle();
        QCOMPARE(exported.count(), 1);
        const MouthCueTrack before = readMouthCues(path.toStdString());
        QCOMPARE(before.duration, 3.0);
        // Every speech shape but B far from any frame: B takes what the phones leave free.
        std::map<std::string, Project::MouthShapeFeatures> far;
        for (const char *s : {"C", "D", "E", "F", "G", "H"})
            far[s] = {1, 0, 1, 0};
        far["B"] = {0.5, 0.5, 0.5, 0.5};
        QVERIFY(m_context.document()->requestMouthShapes(far, QStringLiteral("far")));
        path = dir.filePath("cues.tsv");
        QVERIFY(m_menu->trigger(ExportMenu::Kind::MouthCues));
        waitIdle();
        for (const MouthCue &c : readMouthCues(path.toStdString()).cues)
            QVERIFY(c.shape == MouthShape::A || c.shape == MouthShape::B || c.shape == MouthShape::X);
        m_context.undoStack()->undo();

        path = dir.filePath("controls.csv");
        QVERIFY(m_menu->trigger(ExportMenu::Kind::Controls));
        waitIdle();
        const AnimationControls controls = readAnimationControls(path.toStdString());
        QCOMPARE(controls.frameCount(), 75);
        QCOMPARE(controls.names, animationControlNames());
    }
};

QTEST_MAIN(TestMouthShapes)
#include "tst_mouthshapes.moc"
