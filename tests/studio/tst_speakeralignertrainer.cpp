// Timeline ▸ Model ▸ Train the Speaker's Own Aligner… on a studio context with a writable copy of
// the demo: a model trained in the background on the project's transcribed speech, calibrated on
// its word timings (GRID's), scored on held-out sequences, is written into the project's models
// folder and becomes the project's aligner (one undo step; undone, the project says its earlier
// aligner again); the read-only demo and a project with too little speech are refused with the
// reason, and nothing is left behind; the timeline's hint on opening offers it when there is enough
// speech and no aligner of the project's own. The demo has 15 s of words, under the three minutes a
// user's project needs: the test lowers the minimum to train on it.
#include "DemoWindow.h"

#include "align/AcousticModel.h"
#include "align/ProjectAligner.h"
#include "app/DemoProject.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "timeline/SpeakerAlignerTrainer.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;

class TestSpeakerAlignerTrainer : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase() { ErrorReporter::setBatchMode(true); }

    void trainsAndBecomesTheProjectsAligner()
    {
        QTemporaryDir dir;
        QVERIFY(testing::copyFolder(DemoProject::locate(), dir.path()));
        StudioContext context;
        QWidget window;
        context.document()->reset(Project::load(dir.path().toStdString()), dir.path(), false);
        SpeakerAlignerTrainer trainer(&context, &window);
        QVERIFY(trainer.action()->isEnabled());
        const double seconds = SpeakerAlignerTrainer::speechSeconds(context.document()->project());
        QVERIFY2(seconds > 12 && seconds < 20, qPrintable(QString::number(seconds))); // GRID: 1.5 s of words a clip
        QVERIFY(trainer.offer().isEmpty()); // under three minutes: not offered
        trainer.setMinimumSpeechSeconds(10);
        QVERIFY2(trainer.offer().contains(QStringLiteral("min of words")), qPrintable(trainer.offer()));
        QSignalSpy trained(&trainer, &SpeakerAlignerTrainer::trained);
        QSignalSpy status(&context, &StudioContext::statusMessage);
        Task *task = trainer.start();
        QVERIFY(task);
        QVERIFY(!trainer.action()->isEnabled()); // one at a time
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 120000);
        QVERIFY2(task->state() == Task::State::Finished, qPrintable(task->errorMessage()));
        QVERIFY(trainer.action()->isEnabled());
        QCOMPARE(trained.count(), 1);
        const QString file = trained.at(0).at(0).toString();
        QCOMPARE(file, QStringLiteral("models/aligner.aligner"));
        const Project &project = context.document()->project();
        const std::optional<AlignerChoice> choice = projectAlignerChoice(project);
        QVERIFY(choice && !choice->isSphinx());
        QCOMPARE(QString::fromStdString(choice->model), QDir(dir.path()).filePath(file));
        const AcousticModel model = AcousticModel::load(choice->model); // a model the aligner reads
        QVERIFY(model.stateCount() > 0);
        // What it says: the held-out sequences (two of ten) and their share within 40 ms.
        QVERIFY(!status.isEmpty());
        const QString said = status.last().at(0).toString();
        QVERIFY2(said.contains(QStringLiteral("On 2 sequences it was not trained on")), qPrintable(said));
        QVERIFY(trainer.offer().isEmpty()); // it has its own now
        QCOMPARE(context.undoStack()->undoText(), QStringLiteral("Train the Speaker's Own Aligner"));
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
        SpeakerAlignerTrainer trainer(&context, &window);
        QVERIFY(!trainer.action()->isEnabled());
        QVERIFY(!trainer.start());

        QTemporaryDir dir;
        QVERIFY(testing::copyFolder(demo, dir.path()));
        Project two = Project::load(dir.path().toStdString());
        two.sequences.resize(2); // 3 s of words, under three minutes
        context.document()->reset(two, dir.path(), false);
        QVERIFY(trainer.action()->isEnabled());
        QVERIFY(trainer.offer().isEmpty());
        Task *task = trainer.start();
        QVERIFY(task);
        QTRY_COMPARE_WITH_TIMEOUT(context.taskRunner()->runningCount(), 0, 60000);
        QCOMPARE(task->state(), Task::State::Failed);
        QVERIFY2(task->errorMessage().contains(QStringLiteral("needs at least 180 s")), qPrintable(task->errorMessage()));
        QVERIFY(!context.document()->project().model("aligner"));
        QVERIFY(!QFileInfo::exists(QDir(dir.path()).filePath(QStringLiteral("models/aligner.aligner"))));
    }
};

QTEST_MAIN(TestSpeakerAlignerTrainer)
#include "tst_speakeralignertrainer.moc"
