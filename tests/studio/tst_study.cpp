// The blind study in the studio (paper §4, Table 1): set up a study on the demo project with a
// model trained in the test, run participants through the full-screen participant mode with the
// keys a participant uses, and check that every answer is in the project on disk right after its
// trial, that participants are kept apart, and that the results view shows the tally. The Study
// menu and the Models panel on a studio context, without the main window.
#include "DemoWindow.h"

#include "app/ProjectFiles.h"
#include "build/ModelsPanel.h"
#include "compare/ParticipantSession.h"
#include "compare/ParticipantView.h"
#include "compare/StudyController.h"
#include "compare/StudyResultsView.h"
#include "compare/StudySetupDialog.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "eval/StudyTally.h"
#include "project/Project.h"
#include "tasks/Task.h"

#include <QAbstractButton>
#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QListWidget>
#include <QMenu>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;

class TestStudy : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    StudioContext m_context;
    QWidget m_host; // the dialogs' parent, as the window is
    QMenu m_recent;
    ProjectFiles *m_files = nullptr;
    StudyController *m_study = nullptr;
    QTemporaryDir m_dir;
    QString m_folder;

    void waitIdle() { QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 120000); }
    const ForcedChoiceStudy &study() const { return *m_context.document()->project().study; }
    ForcedChoiceStudy onDisk() const
    {
        return ForcedChoiceStudy::load(QDir(m_folder).filePath("study.json").toStdString());
    }
    // Waits for the current trial's videos, checks what the participant sees, answers by key.
    QString taskReport() const
    {
        QStringList lines;
        for (Task *t : m_context.taskRunner()->tasks())
            lines << QStringLiteral("%1: %2 %3").arg(t->title()).arg(int(t->state())).arg(t->errorMessage());
        return lines.join(QLatin1Char('\n'));
    }
    void answerByKey(ParticipantView *view, int trial, int count, Qt::Key key)
    {
        QTRY_VERIFY2_WITH_TIMEOUT(view->isAcceptingAnswers(), qPrintable(taskReport()), 40000);
        QCOMPARE(view->progressText(), QStringLiteral("Trial %1 of %2").arg(trial + 1).arg(count));
        // No method name anywhere on the participant's screen (only the question says "real").
        for (QLabel *label : view->findChildren<QLabel *>())
            for (const char *name : {"recorded", "Real", "hmm", "HMM", "dpds", "DPDS", "model"})
                QVERIFY2(!label->text().contains(QLatin1String(name)), qPrintable(label->text()));
        QTest::keyClick(view, key);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QCoreApplication::setOrganizationName(QStringLiteral("lipsync-tests"));
        ErrorReporter::setBatchMode(true);
        m_files = new ProjectFiles(m_context.document(), &m_host, &m_recent, m_context.taskRunner());
        m_study = new StudyController(&m_context, [this] { return m_files->save(); }, &m_host);
        m_host.resize(800, 600);
        m_host.show();
        QVERIFY(QTest::qWaitForWindowExposed(&m_host));
        testing::openDemo(m_context);
        // A model to compare with the recordings: HMM-mean trains in a moment on the demo features.
        auto *panel = new ModelsPanel(&m_host);
        panel->attach(&m_context, new QTabWidget(&m_host));
        for (const char *kind : {"dpds", "slds", "brand", "hmm"})
            panel->kindCheck(kind)->setChecked(QLatin1String(kind) == QLatin1String("hmm"));
        QTest::mouseClick(panel->trainButton(), Qt::LeftButton);
        waitIdle();
        QVERIFY(m_context.modelStore()->dynamicModel("hmm"));
        // Participants' answers go to the project on disk: work on a saved copy of the demo.
        m_folder = m_dir.filePath("demo-study");
        m_context.document()->saveTo(m_folder);
    }

    void cleanupTestCase() { waitIdle(); }

    void setUpIsAnUndoableEdit()
    {
        QVERIFY(!m_study->runAction()->isEnabled()); // nothing to run before a study exists
        const int undoBefore = m_context.undoStack()->count();
        // Through the menu: the dialog lists real and the trained model; two utterances.
        QTimer::singleShot(0, this, [] {
            auto *dialog = qobject_cast<StudySetupDialog *>(QApplication::activeModalWidget());
            QVERIFY(dialog);
            QStringList methods;
            for (int i = 0; i < dialog->methodList()->count(); ++i)
                methods << dialog->methodList()->item(i)->data(Qt::UserRole).toString();
            QCOMPARE(methods, QStringList({"real", "hmm"}));
            // Held out of the models' training by default (the paper's design): a fifth of the
            // ten, at most nine so that one is left to train on; unticked, all ten and a warning.
            QVERIFY(dialog->holdOutCheck()->isChecked());
            QCOMPARE(dialog->utteranceCount()->value(), 2);
            QCOMPARE(dialog->utteranceCount()->maximum(), 9);
            dialog->holdOutCheck()->setChecked(false);
            QCOMPARE(dialog->utteranceCount()->maximum(), 10);
            bool warned = false;
            for (QLabel *label : dialog->findChildren<QLabel *>())
                warned = warned || label->text().contains(QStringLiteral("Warning: the models were trained on these"));
            QVERIFY(warned);
            dialog->holdOutCheck()->setChecked(true);
            dialog->utteranceCount()->setValue(2);
            dialog->seed()->setValue(7);
            dialog->accept();
        });
        m_study->setUpAction()->trigger();
        QVERIFY(m_context.document()->project().study);
        QVERIFY(study().methods() == (std::vector<std::string>{"real", "hmm"}));
        QCOMPARE(study().utterances().size(), size_t(2));
        QVERIFY(study().holdsOutUtterances()); // the participants see HMM-mean retrained on the other 8
        QCOMPARE(study().trialsPerSession(), 2); // one pair, shown twice with sides swapped
        QCOMPARE(m_context.undoStack()->count(), undoBefore + 1);
        QVERIFY(m_study->runAction()->isEnabled());
        m_context.undoStack()->undo();
        QVERIFY(!m_context.document()->project().study);
        m_context.undoStack()->redo();
        QVERIFY(m_context.document()->project().study);
        QVERIFY(m_context.document()->isModified());
    }

    void participantModeRecordsEveryAnswer()
    {
        // Starting saves the study with the project (answers are written after every trial).
        ParticipantSession *session = m_study->startParticipant(QStringLiteral("P01"));
        QVERIFY(session);
        QVERIFY(!m_context.document()->isModified());
        QVERIFY(QFile::exists(QDir(m_folder).filePath("study.json")));
        ParticipantView *view = session->view();
        view->setAudioEnabled(false);
        QVERIFY(view->isFullScreen());

        answerByKey(view, 0, 2, Qt::Key_Left);
        // The first answer is on disk before the second trial starts.
        QVERIFY(onDisk().sessions().at(0).trials[0].choice == StudyChoice::Left);
        QVERIFY(onDisk().sessions().at(0).trials[1].choice == StudyChoice::Unanswered);
        QVERIFY(onDisk().sessions().at(0).trials[0].responseSeconds >= 0);

        QTRY_VERIFY_WITH_TIMEOUT(view->isAcceptingAnswers(), 60000);
        QTRY_VERIFY(view->currentFrame() > 3); // the videos play
        const QString shot = QDir(QString::fromLatin1(LIPSYNC_BINARY_DIR)).filePath("participant-mode.png");
        QVERIFY(view->grab().save(shot));
        // Replay restarts both videos.
        QTest::keyClick(view, Qt::Key_R);
        QVERIFY(view->currentFrame() < 3);
        answerByKey(view, 1, 2, Qt::Key_Down);
        QVERIFY(!view->isAcceptingAnswers());
        QVERIFY(view->promptText().contains("Esc"));
        QVERIFY(onDisk().sessions().at(0).trials[1].choice == StudyChoice::Undecided);
        QTest::keyClick(view, Qt::Key_Escape); // finished: leaves without asking
        QTRY_VERIFY(!m_study->participantSession());
        QVERIFY(!m_context.document()->isModified());

        // Reloading the project gives the same answers.
        const Project reloaded = Project::load(m_folder.toStdString());
        QVERIFY(reloaded.study);
        QVERIFY(*reloaded.study == study());
        QVERIFY(reloaded.study->sessions()[0].complete());
    }

    void secondParticipantIsKeptApart()
    {
        QCOMPARE(m_study->nextPseudonym(), QStringLiteral("P02"));
        ParticipantSession *session = m_study->startParticipant(QStringLiteral("P02"), false);
        QVERIFY(session);
        ParticipantView *view = session->view();
        view->setAudioEnabled(false);
        answerByKey(view, 0, 2, Qt::Key_Right);
        // Esc in the middle asks first, in a legible box (text and buttons on the application's
        // light background, not the view's black); Enter continues the study.
        QTRY_VERIFY_WITH_TIMEOUT(view->isAcceptingAnswers(), 60000);
        bool legible = false;
        QStringList buttons;
        QTimer::singleShot(0, this, [&] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            QVERIFY(box);
            QVERIFY(QTest::qWaitForWindowExposed(box));
            const QImage shot = box->grab().toImage().convertToFormat(QImage::Format_Grayscale8);
            int light = 0, dark = 0;
            for (int y = 0; y < shot.height(); ++y)
                for (int x = 0; x < shot.width(); ++x)
                    (shot.constScanLine(y)[x] > 128 ? light : dark) += 1;
            legible = light > shot.width() * shot.height() / 2 && dark > 200; // a light box with dark text
            for (QAbstractButton *b : box->buttons())
                buttons << b->text();
            QTest::keyClick(box, Qt::Key_Return);
        });
        QTest::keyClick(view, Qt::Key_Escape);
        QVERIFY(legible);
        QCOMPARE(buttons.size(), 2);
        QVERIFY(m_study->participantSession());
        QTimer::singleShot(0, this, [] {
            auto *box = qobject_cast<QMessageBox *>(QApplication::activeModalWidget());
            QVERIFY(box);
            for (QAbstractButton *b : box->buttons())
                if (box->buttonRole(b) == QMessageBox::AcceptRole)
                    b->click();
        });
        QTest::keyClick(view, Qt::Key_Escape);
        QTRY_VERIFY(!m_study->participantSession());

        QCOMPARE(study().sessions().size(), size_t(2));
        const StudySession &first = study().sessions()[0];
        const StudySession &second = study().sessions()[1];
        QVERIFY(second.participant == "P02");
        QVERIFY(second.seed != first.seed); // a fresh random order of its own
        QCOMPARE(second.answered(), 1);
        QVERIFY(second.trials[0].choice == StudyChoice::Right);
        QCOMPARE(first.answered(), 2); // untouched
        QVERIFY(first.trials[0].choice == StudyChoice::Left);
        QVERIFY(onDisk() == study());

        // P02 resumes at the open trial.
        session = m_study->startParticipant(QStringLiteral("P02"), false);
        QVERIFY(session);
        session->view()->setAudioEnabled(false);
        answerByKey(session->view(), 1, 2, Qt::Key_Left);
        QTRY_VERIFY(!session->view()->isAcceptingAnswers());
        QTest::keyClick(session->view(), Qt::Key_Escape);
        QTRY_VERIFY(!m_study->participantSession());
        QVERIFY(study().sessions()[1].complete());
        QVERIFY(onDisk() == study());
        // Answers are data, not edits: none is on the undo stack, and the project is saved.
        QCOMPARE(m_context.undoStack()->undoText(), QStringLiteral("Set up study"));
        QVERIFY(!m_context.document()->isModified());
    }

    void resultsShowTheTally()
    {
        StudyResultsView *results = m_study->showResults();
        QVERIFY(results);
        const StudyTally tally = StudyTally::fromStudy(study());
        QCOMPARE(tally.answered, 4);
        QTableWidget *pairs = results->pairTable();
        QCOMPARE(pairs->rowCount(), 1);
        QCOMPARE(pairs->item(0, 0)->text(), QStringLiteral("real"));
        QCOMPARE(pairs->item(0, 4)->text(), ModelKinds::name(QStringLiteral("hmm"))); // the CSV keeps the id
        QCOMPARE(pairs->item(0, 1)->text().toInt(), tally.pairs[0].preferA);
        QCOMPARE(pairs->item(0, 2)->text().toInt(), 1); // P01's "can't decide"
        QCOMPARE(pairs->item(0, 3)->text().toInt(), tally.pairs[0].preferB);
        QCOMPARE(tally.pairs[0].preferA + tally.pairs[0].preferB, 3);
        QCOMPARE(results->rankingTable()->rowCount(), 2);
        QVERIFY(results->summary()->text().startsWith(QStringLiteral("Participants: 2, answers: 4")));
        QVERIFY(results->summary()->text().contains(ModelKinds::name(QStringLiteral("hmm"))));

        const QString csv = m_dir.filePath("table1.csv");
        results->exportCsv(csv);
        QFile file(csv);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = file.readAll().split('\n');
        QCOMPARE(lines[0], QByteArray("method_a,method_b,prefer_a,undecided,prefer_b,n_decided,p_value,p_holm"));
        QVERIFY2(lines[1].startsWith(QStringLiteral("real,hmm,%1,1,%2,3,")
                                         .arg(tally.pairs[0].preferA)
                                         .arg(tally.pairs[0].preferB)
                                         .toLatin1()),
                 lines[1].constData());
        QVERIFY(QFile::exists(StudyResultsView::rankingPath(csv)));

        // The table follows the document: a third participant's answer shows at once.
        ProjectDocument *document = m_context.document();
        const int p03 = document->addStudyParticipant(QStringLiteral("P03"));
        document->recordStudyAnswer(p03, 0, StudyChoice::Left, 1.5);
        QVERIFY(results->summary()->text().startsWith(QStringLiteral("Participants: 3, answers: 5")));
        QVERIFY(onDisk() == study());

        // Undoing the set-up takes the study with its answers away; redo brings back both.
        const ForcedChoiceStudy answered = study();
        m_context.undoStack()->undo();
        QVERIFY(!document->project().study);
        m_context.undoStack()->redo();
        QVERIFY(document->project().study && *document->project().study == answered);
    }
};

QTEST_MAIN(TestStudy)
#include "tst_study.moc"
