// Timeline ▸ Model ▸ Make the Speaker's Own Aligner… on a studio context with a writable copy of
// the demo: the shipped model adapted to the project's speaker in the background is written into
// the project's models folder and becomes the project's aligner (one undo step; undone, the
// project says its earlier aligner again); the read-only demo and a project with too little
// transcribed speech are refused with the reason, and nothing is left behind; the timeline's hint
// on opening offers it when there is enough speech and no aligner of the project's own.
#include "DemoWindow.h"

#include "align/AcousticModel.h"
#include "align/ProjectAligner.h"
#include "app/DemoProject.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "timeline/SpeakerAlignerAdapter.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;

class TestSpeakerAligner : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase() { ErrorReporter::setBatchMode(true); }

    void adaptsAndBecomesTheProjectsAligner()
    {
        QTemporaryDir dir;
        QVERIFY(testing::copyFolder(DemoProject::locate(), dir.path()));
        StudioContext context;
        QWidget window;
        context.document()->reset(Project::load(dir.path().toStdString()), dir.path(), false);
        SpeakerAlignerAdapter adapter(&context, &window);
        QVERIFY(adapter.action()->isEnabled());
        // Offered on opening: ten transcribed clips of 3 s.
        QVERIFY2(adapter.offer().contains(QStringLiteral("30 s of transcribed speech")), qPrintable(adapter.offer()));
        QSignalSpy adapted(&adapter, &SpeakerAlignerAdapter::adapted);
        Task *task = adapter.start();
        QVERIFY(task);
        QVERIFY(!adapter.action()->isEnabled()); // one at a time
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 120000);
        QCOMPARE(task->state(), Task::State::Finished);
        QCOMPARE(adapted.count(), 1);
        const QString file = adapted.at(0).at(0).toString();
        QCOMPARE(file, QStringLiteral("models/aligner.aligner"));
        const Project &project = context.document()->project();
        const std::optional<AlignerChoice> choice = projectAlignerChoice(project);
        QVERIFY(choice && !choice->isSphinx());
        QCOMPARE(QString::fromStdString(choice->model), QDir(dir.path()).filePath(file));
        AcousticModel::load(choice->model); // a model the aligner reads
        QVERIFY(adapter.offer().isEmpty()); // it has its own now
        QCOMPARE(context.undoStack()->undoText(), QStringLiteral("Make the Speaker's Own Aligner"));
        context.undoStack()->undo();
        QVERIFY(!context.document()->project().model("aligner"));
        QCOMPARE(projectAlignerChoice(context.document()->project())->model, std::string()); // builtin again
    }

    void refusesTheDemoAndTooLittleSpeech()
    {
        StudioContext context;
        QWidget window;
        const QString demo = DemoProject::locate();
        context.document()->reset(DemoProject::load(demo), demo, true);
        SpeakerAlignerAdapter adapter(&context, &window);
        QVERIFY(!adapter.action()->isEnabled());
        QVERIFY(!adapter.start());

        QTemporaryDir dir;
        QVERIFY(testing::copyFolder(demo, dir.path()));
        Project two = Project::load(dir.path().toStdString());
        two.sequences.resize(2); // 6 s of sound, under 20 s
        context.document()->reset(two, dir.path(), false);
        QVERIFY(adapter.action()->isEnabled());
        QVERIFY(adapter.offer().isEmpty()); // 6 s: not offered
        Task *task = adapter.start();
        QVERIFY(task);
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 60000);
        QCOMPARE(task->state(), Task::State::Failed);
        QVERIFY2(task->errorMessage().contains(QStringLiteral("at least 20 s")), qPrintable(task->errorMessage()));
        QVERIFY(!context.document()->project().model("aligner"));
        QVERIFY(!QFileInfo::exists(QDir(dir.path()).filePath(QStringLiteral("models/aligner.aligner"))));
    }
};

QTEST_MAIN(TestSpeakerAligner)
#include "tst_speakeraligner.moc"
