// File ▸ Import Long Recording… in the studio, on a copy of the demo project, with a recording of
// three demo clips' sound one after the other and a plain-text transcript of their words:
//  - the dialog enables Import only once both files exist, finds the transcript beside the
//    recording and offers the default utterance lengths (the longest never below the shortest);
//  - through the File menu and the dialog (utterances of at least 1 s), the import runs as one
//    background task and adds three sequences talk_0001..talk_0003 with their clips in the
//    project's clips folder, shown in the sequence list, the first of them selected; one Undo
//    removes all three (the sequence shown gives way to the last demo clip), Redo brings them
//    back, and Save writes them;
//  - a cancel right after the start, or after the work finished but before its result was applied,
//    adds nothing and leaves no clip; importing the same recording again, or a recording that
//    cannot be read, fails naming the file and adds nothing.
// LIPSYNC_PREVIEW_SHOT=DIR keeps pictures of the dialog, the File menu and the window for a look
// by eye.
#include "DemoWindow.h"

#include "app/ImportLongRecordingDialog.h"
#include "app/LongRecordingImporter.h"
#include "app/MainWindow.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "io/AudioDecoder.h"
#include "io/Transcript.h"
#include "io/WavWriter.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QPushButton>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
const QStringList kClips = {QStringLiteral("bbaf2n"), QStringLiteral("bgin3a"), QStringLiteral("bwbg8n")};

// A GRID sentence lasts about 1.3 s: utterances of one each (the default shortest is 2 s).
UtteranceSplitOptions clipSplit()
{
    UtteranceSplitOptions split;
    split.shortest = 1.0;
    return split;
}

// Spins the event loop until the task has ended (its result applied or dropped).
void waitFor(Task *task)
{
    QTRY_VERIFY_WITH_TIMEOUT(!task->isRunning(), 120000);
}

} // namespace

class TestImportLongRecording : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The recording: the three clips' sound, one after the other, and their words.
        std::vector<float> samples;
        Transcript words;
        for (const QString &clip : kClips) {
            const AudioBuffer audio = AudioDecoder::decode((kDemo + "/media/" + clip + ".mpg").toStdString(), 16000);
            samples.insert(samples.end(), audio.samples.begin(), audio.samples.end());
            const Transcript t = readTranscript((kDemo + "/media/" + clip + ".align").toStdString());
            words.words.insert(words.words.end(), t.words.begin(), t.words.end());
        }
        m_recording = m_dir.filePath(QStringLiteral("talk.wav"));
        m_transcript = m_dir.filePath(QStringLiteral("talk.txt"));
        writeWav(m_recording.toStdString(), samples, 0, samples.size(), 16000);
        writePlainTranscript(m_transcript.toStdString(), words);
        QCOMPARE(int(words.words.size()), 18);

        // A copy of the demo the import may write into.
        m_project = m_dir.filePath(QStringLiteral("project"));
        QVERIFY(testing::copyFolder(kDemo, m_project));
        testing::openWindowOnProject(m_window, m_project);
        if (QTest::currentTestFailed())
            return;
        m_demoCount = m_window->context()->document()->sequenceCount();
        QCOMPARE(m_demoCount, 10);
    }

    void cleanupTestCase() { delete m_window; }

    void dialogEnablesImportOnceBothFilesExist()
    {
        ImportLongRecordingDialog dialog(m_window);
        QPushButton *ok = dialog.buttons()->button(QDialogButtonBox::Ok);
        QVERIFY(!ok->isEnabled());
        dialog.recordingEdit()->setText(m_dir.filePath(QStringLiteral("missing.wav")));
        QVERIFY(!ok->isEnabled());
        // The recording found, and its transcript beside it with it.
        dialog.setRecordingPath(m_recording);
        QCOMPARE(dialog.transcriptPath(), m_transcript);
        QVERIFY(ok->isEnabled());
        dialog.transcriptEdit()->setText(m_dir.filePath(QStringLiteral("missing.txt")));
        QVERIFY(!ok->isEnabled());
        dialog.transcriptEdit()->setText(m_transcript);
        QVERIFY(ok->isEnabled());
        // The utterance lengths start at the defaults, the longest never below the shortest.
        QCOMPARE(dialog.splitOptions().shortest, UtteranceSplitOptions().shortest);
        QCOMPARE(dialog.splitOptions().longest, UtteranceSplitOptions().longest);
        dialog.shortestSpin()->setValue(20.0);
        QCOMPARE(dialog.longestSpin()->value(), 20.0);
        dialog.shortestSpin()->setValue(UtteranceSplitOptions().shortest);
        dialog.longestSpin()->setValue(UtteranceSplitOptions().longest);
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        // It fits the smallest screen the studio is made for.
        QVERIFY(dialog.width() <= 1280 && dialog.height() <= 800);
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
            dialog.grab().save(dir + QStringLiteral("/import-dialog.png"));
    }

    void cancelRightAfterTheStartAddsNothing()
    {
        const int undoIndex = m_window->context()->undoStack()->index();
        Task *task = importer()->start(m_recording, m_transcript, clipSplit());
        QVERIFY(task);
        QVERIFY(!importer()->action()->isEnabled()); // one import at a time
        task->cancel();
        waitFor(task);
        QCOMPARE(task->state(), Task::State::Canceled);
        checkNothingAdded(undoIndex);
    }

    // Canceled after the work was done (the clips written) but before its result reached the
    // document: dropped, and the clips removed.
    void cancelBeforeTheResultIsAppliedAddsNothing()
    {
        const int undoIndex = m_window->context()->undoStack()->index();
        Task *task = importer()->start(m_recording, m_transcript, clipSplit());
        QVERIFY(task);
        m_window->context()->taskRunner()->waitForAll(); // the worker is done; its result waits for the event loop
        QCOMPARE(clips().size(), 3);
        task->cancel();
        waitFor(task);
        QCOMPARE(task->state(), Task::State::Canceled);
        checkNothingAdded(undoIndex);
    }

    void importsThroughTheMenu()
    {
        ProjectDocument *doc = m_window->context()->document();
        QUndoStack *undo = m_window->context()->undoStack();
        const int undoIndex = undo->index();
        QVERIFY(!doc->isModified());
        bool filled = false;
        const QMetaObject::Connection fill = connect(
            importer(), &LongRecordingImporter::dialogOpened, this, [&](ImportLongRecordingDialog *dialog) {
                dialog->setRecordingPath(m_recording);
                filled = dialog->transcriptPath() == m_transcript;
                dialog->shortestSpin()->setValue(clipSplit().shortest);
                QTimer::singleShot(0, dialog, [dialog] {
                    if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
                        dialog->grab().save(dir + QStringLiteral("/import-dialog-open.png"));
                    QVERIFY(dialog->buttons()->button(QDialogButtonBox::Ok)->isEnabled());
                    dialog->buttons()->button(QDialogButtonBox::Ok)->click();
                });
            });
        Task *task = nullptr;
        const QMetaObject::Connection started = connect(importer(), &LongRecordingImporter::importStarted, this,
                                                        [&](Task *t) { task = t; });
        QAction *action = importer()->action();
        QCOMPARE(action->text(), QStringLiteral("Import &Long Recording…"));
        QVERIFY(action->isEnabled());
        QMenu *file = m_window->menuBar()->actions().value(0)->menu();
        QVERIFY(file && file->actions().contains(action));
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty()) {
            file->popup(m_window->mapToGlobal(QPoint(0, m_window->menuBar()->height())));
            QVERIFY(QTest::qWaitForWindowExposed(file));
            file->grab().save(dir + QStringLiteral("/file-menu.png"));
            file->hide();
        }
        action->trigger();
        disconnect(fill);
        disconnect(started);
        QVERIFY(filled);
        QVERIFY(task);
        waitFor(task);
        QVERIFY2(task->state() == Task::State::Finished, qPrintable(task->errorMessage()));

        // Three sequences, named after the recording, their clips in the project's clips folder.
        QCOMPARE(doc->sequenceCount(), m_demoCount + 3);
        QAbstractItemModel *list = m_window->sequenceView()->model();
        QCOMPARE(list->rowCount(), m_demoCount + 3);
        for (int k = 0; k < 3; ++k) {
            const int row = m_demoCount + k;
            const QString id = QStringLiteral("talk_%1").arg(k + 1, 4, 10, QLatin1Char('0'));
            QCOMPARE(QString::fromStdString(doc->sequence(row).id), id);
            QCOMPARE(list->data(list->index(row, 0)).toString(), id);
            QVERIFY2(QFileInfo(doc->mediaPath(row)).isFile(), qPrintable(doc->mediaPath(row)));
            QCOMPARE(QFileInfo(doc->mediaPath(row)).absolutePath(), QDir(m_project).filePath(QStringLiteral("clips")));
            QVERIFY(!doc->sequence(row).transcript.empty());
            QVERIFY(!doc->sequence(row).phones.isEmpty());
        }
        // Each clip says one demo clip's words.
        QCOMPARE(doc->sequence(m_demoCount).transcript, doc->sequence(0).transcript);
        QCOMPARE(clips().size(), 3);
        // One undo step, the project modified, the first new sequence shown.
        QCOMPARE(undo->index(), undoIndex + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Import talk.wav"));
        QVERIFY(doc->isModified());
        QVERIFY(m_window->isWindowModified());
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->media()->sequenceId == QStringLiteral("talk_0001"),
                                 60000);
        QCOMPARE(m_window->context()->currentSequence(), m_demoCount);
        QCOMPARE(m_window->sequenceView()->currentIndex().row(), m_demoCount);
        testing::waitForTasks(m_window);
        QVERIFY(action->isEnabled());
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
            m_window->grab().save(dir + QStringLiteral("/imported.png"));

        // Undo removes all three in one step; the sequence shown was one of them: the last demo
        // clip takes its place.
        undo->undo();
        QCOMPARE(doc->sequenceCount(), m_demoCount);
        QCOMPARE(list->rowCount(), m_demoCount);
        QCOMPARE(undo->index(), undoIndex);
        QVERIFY(!doc->isModified());
        const QString lastDemo = QString::fromStdString(doc->sequence(m_demoCount - 1).id);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->media()->sequenceId == lastDemo, 60000);
        QCOMPARE(m_window->context()->currentSequence(), m_demoCount - 1);
        QCOMPARE(clips().size(), 3); // kept for the redo

        undo->redo();
        QCOMPARE(doc->sequenceCount(), m_demoCount + 3);
        QCOMPARE(list->rowCount(), m_demoCount + 3);
        QCOMPARE(QString::fromStdString(doc->sequence(m_demoCount + 2).id), QStringLiteral("talk_0003"));
        QCOMPARE(list->data(list->index(m_demoCount + 2, 0)).toString(), QStringLiteral("talk_0003"));
        m_window->context()->selectSequence(m_demoCount + 1);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->media()->sequenceId == QStringLiteral("talk_0002"),
                                 60000);
        testing::waitForTasks(m_window);

        // Saved, the project holds them.
        QVERIFY(m_window->files()->save());
        const Project saved = Project::load(m_project.toStdString());
        QCOMPARE(int(saved.sequences.size()), m_demoCount + 3);
        QVERIFY(QFileInfo::exists(QString::fromStdString(saved.mediaPath(saved.sequences.back()))));
    }

    // A second import of the same recording, and a recording that cannot be read: failures that
    // name the file and add nothing.
    void failuresNameTheFileAndAddNothing()
    {
        const int undoIndex = m_window->context()->undoStack()->index();
        const int count = m_window->context()->document()->sequenceCount();
        Task *again = importer()->start(m_recording, m_transcript, clipSplit());
        QVERIFY(again);
        waitFor(again);
        QCOMPARE(again->state(), Task::State::Failed);
        QVERIFY2(again->errorMessage().contains(QStringLiteral("talk_0001")), qPrintable(again->errorMessage()));
        QVERIFY(ErrorReporter::lastMessage().contains(again->errorMessage()));

        const QString missing = m_dir.filePath(QStringLiteral("missing.wav"));
        Task *task = importer()->start(missing, m_transcript, clipSplit());
        QVERIFY(task);
        waitFor(task);
        QCOMPARE(task->state(), Task::State::Failed);
        QVERIFY2(task->errorMessage().contains(missing), qPrintable(task->errorMessage()));
        QVERIFY(ErrorReporter::lastMessage().contains(missing));
        QCOMPARE(m_window->context()->document()->sequenceCount(), count);
        QCOMPARE(m_window->context()->undoStack()->index(), undoIndex);
        QCOMPARE(clips().size(), 3); // the first import's, untouched
    }

private:
    LongRecordingImporter *importer() const { return m_window->longRecordingImporter(); }

    // The clips of the recording in the project's clips folder.
    QStringList clips() const
    {
        return QDir(QDir(m_project).filePath(QStringLiteral("clips")))
            .entryList({QStringLiteral("talk_*")}, QDir::Files);
    }

    void checkNothingAdded(int undoIndex)
    {
        QCOMPARE(m_window->context()->document()->sequenceCount(), m_demoCount);
        QCOMPARE(m_window->sequenceView()->model()->rowCount(), m_demoCount);
        QCOMPARE(m_window->context()->undoStack()->index(), undoIndex);
        QVERIFY(!m_window->context()->document()->isModified());
        QVERIFY(clips().isEmpty());
        QVERIFY(importer()->action()->isEnabled());
    }

    QTemporaryDir m_dir;
    QString m_recording, m_transcript, m_project;
    MainWindow *m_window = nullptr;
    int m_demoCount = 0;
};

QTEST_MAIN(TestImportLongRecording)
#include "tst_importlongrecording.moc"
