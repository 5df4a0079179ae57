// The task runner's contract: work runs off the GUI thread, its result is applied on the runner's
// thread only when the task finished, and cancel or failure leave the caller's state untouched.
#include "tasks/TaskRunner.h"

#include <QSignalSpy>
#include <QTest>
#include <QThread>

#include <atomic>

using namespace lipsync;

// Generous: a wait returns as soon as the task finishes; under ThreadSanitizer on a loaded machine a
// task of a few milliseconds can take seconds.
constexpr int kWaitMs = 60000;

class TestTaskRunner : public QObject
{
    Q_OBJECT
private slots:
    void resultAppliedOnRunnerThread()
    {
        TaskRunner runner;
        std::atomic<QThread *> workerThread{nullptr};
        QThread *applyThread = nullptr;
        int document = 0;
        Task *task = runner.run<int>(
            QStringLiteral("sum"),
            [&](Feedback &feedback) {
                workerThread = QThread::currentThread();
                int sum = 0;
                for (int i = 1; i <= 100; ++i) {
                    feedback.throwIfCanceled();
                    sum += i;
                    feedback.setProgress(i / 100.0);
                }
                return sum;
            },
            [&](int sum) {
                applyThread = QThread::currentThread();
                document = sum;
            });
        QSignalSpy finished(task, &Task::finished);
        QVERIFY(finished.wait(kWaitMs));
        QCOMPARE(task->state(), Task::State::Finished);
        QCOMPARE(document, 5050);
        QCOMPARE(applyThread, QThread::currentThread());
        QVERIFY(workerThread.load() != QThread::currentThread());
        QCOMPARE(task->progress(), 1.0);
    }

    void cancelLeavesDocumentUntouched()
    {
        TaskRunner runner;
        int document = 7;
        std::atomic<bool> started{false};
        Task *task = runner.run<int>(
            QStringLiteral("endless"),
            [&](Feedback &feedback) {
                started = true;
                for (;;) {
                    feedback.throwIfCanceled();
                    QThread::msleep(1);
                }
                return 1;
            },
            [&](int value) { document = value; });
        QTRY_VERIFY(started.load());
        QSignalSpy finished(task, &Task::finished);
        task->cancel();
        QVERIFY(finished.wait(kWaitMs));
        QCOMPARE(task->state(), Task::State::Canceled);
        QCOMPARE(document, 7);
        QCOMPARE(runner.runningCount(), 0);
    }

    void cancelAfterLastPollStillDropsResult()
    {
        // Work that never polls: a cancel that arrives while it runs must still drop the result.
        TaskRunner runner;
        int document = 0;
        std::atomic<bool> release{false};
        Task *task = runner.run<int>(
            QStringLiteral("no polling"),
            [&](Feedback &) {
                while (!release.load())
                    QThread::msleep(1);
                return 42;
            },
            [&](int value) { document = value; });
        QSignalSpy finished(task, &Task::finished);
        task->cancel();
        release = true;
        QVERIFY(finished.wait(kWaitMs));
        QCOMPARE(task->state(), Task::State::Canceled);
        QCOMPARE(document, 0);
    }

    void failureReportsMessage()
    {
        TaskRunner runner;
        int document = 3;
        Task *task = runner.run<int>(
            QStringLiteral("failing"),
            [](Feedback &) -> int { throw std::runtime_error("clip.mpg: truncated"); },
            [&](int value) { document = value; });
        QSignalSpy finished(task, &Task::finished);
        QVERIFY(finished.wait(kWaitMs));
        QCOMPARE(task->state(), Task::State::Failed);
        QCOMPARE(task->errorMessage(), QStringLiteral("clip.mpg: truncated"));
        QCOMPARE(document, 3);
    }

    void iterationsReachGuiThread()
    {
        TaskRunner runner;
        Task *task = runner.run<int>(
            QStringLiteral("optimiser"),
            [](Feedback &feedback) {
                for (int i = 0; i < 5; ++i)
                    feedback.reportIteration(i, -10.0 + i);
                return 0;
            },
            [](int) {});
        QSignalSpy iterations(task, &Task::iterationReported);
        QSignalSpy finished(task, &Task::finished);
        QVERIFY(finished.wait(kWaitMs));
        QCOMPARE(iterations.count(), 5);
        QCOMPARE(iterations.last().at(0).toInt(), 4);
        QCOMPARE(iterations.last().at(1).toDouble(), -6.0);
    }

    void childFeedbackMapsRangeAndSharesCancel()
    {
        Feedback parent;
        int parentIterations = 0;
        parent.onIteration = [&](int, double) { ++parentIterations; };
        Feedback child(parent, 0.5, 1.0);
        int childIterations = 0;
        child.onIteration = [&](int, double) { ++childIterations; };
        // A child's iterations are a sub-problem's: the parent's objective plot must not get them.
        child.reportIteration(1, -3.0);
        QCOMPARE(childIterations, 1);
        QCOMPARE(parentIterations, 0);
        child.setProgress(0.5);
        QCOMPARE(parent.progress(), 0.75);
        QVERIFY(!child.isCanceled());
        parent.cancel();
        QVERIFY(child.isCanceled());
        QVERIFY_THROWS_EXCEPTION(Canceled, child.throwIfCanceled());
    }

    void clearFinishedKeepsRunningTasks()
    {
        TaskRunner runner;
        std::atomic<bool> release{false};
        Task *quick = runner.run<int>(QStringLiteral("quick"), [](Feedback &) { return 1; }, [](int) {});
        QSignalSpy quickDone(quick, &Task::finished);
        QVERIFY(quickDone.wait(kWaitMs));
        Task *slow = runner.run<int>(
            QStringLiteral("slow"),
            [&](Feedback &) {
                while (!release.load())
                    QThread::msleep(1);
                return 1;
            },
            [](int) {});
        runner.clearFinished();
        QCOMPARE(runner.tasks().size(), 1);
        QCOMPARE(runner.tasks().first(), slow);
        QSignalSpy slowDone(slow, &Task::finished);
        release = true;
        QVERIFY(slowDone.wait(kWaitMs));
    }
};

QTEST_GUILESS_MAIN(TestTaskRunner)
#include "tst_taskrunner.moc"
