// The status-bar task list: a task that runs until canceled is canceled by clicking its cancel
// button (in the status bar and in the expanded list); it ends Canceled and its commit closure,
// the only thing that may touch the document, never runs.
#include "tasks/TaskListModel.h"
#include "tasks/TaskListPopup.h"
#include "tasks/TaskRowWidget.h"
#include "tasks/TaskRunner.h"
#include "tasks/TaskStatusWidget.h"

#include <QSignalSpy>
#include <QTest>
#include <QThread>
#include <QThreadPool>
#include <QToolButton>

#include <atomic>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

// Loops until canceled; `throwOnCancel` chooses between the two ways work may end.
TaskRunner::Work loopUntilCanceled(std::atomic<bool> &committed, bool throwOnCancel)
{
    return [&committed, throwOnCancel](Feedback &f) -> TaskRunner::Commit {
        int i = 0;
        while (!f.isCanceled()) {
            f.setProgress((i++ % 100) / 100.0);
            QThread::msleep(5);
        }
        if (throwOnCancel)
            f.throwIfCanceled();
        return [&committed] { committed = true; };
    };
}

} // namespace

class TestTaskStatus : public QObject
{
    Q_OBJECT
private slots:
    void cancelFromStatusBar_data()
    {
        QTest::addColumn<bool>("throwOnCancel");
        QTest::newRow("work throws Canceled") << true;
        QTest::newRow("work returns a commit") << false;
    }
    void cancelFromStatusBar()
    {
        QFETCH(bool, throwOnCancel);
        TaskRunner runner;
        TaskStatusWidget status(&runner);
        status.show();
        QVERIFY(QTest::qWaitForWindowExposed(&status));

        std::atomic<bool> committed{false};
        Task *task = runner.start(QStringLiteral("Loop"), loopUntilCanceled(committed, throwOnCancel));
        QSignalSpy finished(task, &Task::finished);
        QTRY_VERIFY(status.cancelButton()->isVisible());
        QCOMPARE(status.shownTask(), task);
        QCOMPARE(status.model()->rowCount(), 1);

        QTest::mouseClick(status.cancelButton(), Qt::LeftButton);
        QTRY_COMPARE(finished.count(), 1);
        QCOMPARE(task->state(), Task::State::Canceled);
        QVERIFY(!committed);
        QTRY_VERIFY(!status.cancelButton()->isVisible());
        QCOMPARE(status.model()->data(status.model()->index(0), TaskListModel::StateRole).toInt(),
                 int(Task::State::Canceled));
    }

    void cancelFromTaskList()
    {
        TaskRunner runner;
        TaskStatusWidget status(&runner);
        status.show();
        QVERIFY(QTest::qWaitForWindowExposed(&status));

        std::atomic<bool> committedA{false};
        std::atomic<bool> committedB{false};
        Task *a = runner.start(QStringLiteral("A"), loopUntilCanceled(committedA, true));
        Task *b = runner.start(QStringLiteral("B"), [](Feedback &) -> TaskRunner::Commit { return {}; });
        QTRY_COMPARE(b->state(), Task::State::Finished);
        QTest::mouseClick(status.listButton(), Qt::LeftButton);
        QTRY_VERIFY(status.popup()->isVisible());
        const QList<TaskRowWidget *> rows = status.popup()->rows();
        QCOMPARE(rows.size(), 2);
        QCOMPARE(rows[0]->task(), b); // newest first
        QCOMPARE(rows[1]->task(), a);
        QVERIFY(!rows[0]->cancelButton()->isVisible()); // finished: nothing to cancel

        QTest::mouseClick(rows[1]->cancelButton(), Qt::LeftButton);
        QTRY_COMPARE(a->state(), Task::State::Canceled);
        QVERIFY(!rows[1]->cancelButton()->isVisible());
        QVERIFY(!committedA && !committedB);
        status.popup()->hide();
    }

    // Qt 6.4 paints large areas by splitting the work over QThreadPool::globalInstance() and
    // waiting for it on the GUI thread, so tasks that fill the global pool freeze painting for
    // as long as they run. The runner must therefore keep its own pool.
    void paintingWhileWorkersAreBusy()
    {
        TaskRunner runner;
        std::atomic<bool> committed{false};
        const int workers = QThreadPool::globalInstance()->maxThreadCount();
        Task *probe = runner.start(QStringLiteral("probe"), loopUntilCanceled(committed, true));
        QTest::qWait(50);
        const bool usesGlobalPool = QThreadPool::globalInstance()->activeThreadCount() > 0;
        probe->cancel();
        QTRY_VERIFY(!probe->isRunning());
        if (usesGlobalPool)
            QSKIP("TaskRunner runs on QThreadPool::globalInstance(): painting would deadlock here");

        for (int i = 0; i < workers; ++i)
            runner.start(QStringLiteral("busy %1").arg(i), loopUntilCanceled(committed, true));
        TaskStatusWidget status(&runner);
        status.resize(600, 400);
        status.show();
        QVERIFY(QTest::qWaitForWindowExposed(&status));
        QVERIFY(!status.grab().isNull());
        runner.cancelAll();
        runner.waitForAll();
        QVERIFY(!committed);
    }

    void finishedTaskCommits()
    {
        TaskRunner runner;
        TaskStatusWidget status(&runner);
        bool committed = false;
        Task *task = runner.start(QStringLiteral("Quick"), [&committed](Feedback &) -> TaskRunner::Commit {
            return [&committed] { committed = true; };
        });
        QTRY_COMPARE(task->state(), Task::State::Finished);
        QVERIFY(committed);
        runner.clearFinished();
        QTRY_COMPARE(status.model()->rowCount(), 0);
    }
};

QTEST_MAIN(TestTaskStatus)
#include "tst_taskstatus.moc"
