#pragma once
// The one task runner: runs work on its own QThreadPool and applies its result on
// the runner's (GUI) thread. The work function returns a "commit" closure; the runner calls it
// only if the task was not canceled and did not throw. So cancel and failure leave the project
// exactly as before — the worker never touches the document.
#include "tasks/Task.h"

#include <QFutureWatcher>
#include <QList>
#include <QObject>
#include <QPointer>
#include <QThreadPool>

#include <functional>

namespace lipsync {

class TaskRunner : public QObject
{
    Q_OBJECT
public:
    using Commit = std::function<void()>;
    using Work = std::function<Commit(Feedback &)>;

    explicit TaskRunner(QObject *parent = nullptr);
    ~TaskRunner() override; // cancels and waits

    // Starts `work` on a worker thread. Returns the task (owned by the runner).
    Task *start(const QString &title, Work work);

    // Convenience: compute a value off-thread, hand it to `apply` on the GUI thread.
    template <typename Result>
    Task *run(const QString &title, std::function<Result(Feedback &)> compute,
              std::function<void(Result)> apply)
    {
        return start(title, [compute = std::move(compute), apply = std::move(apply)](Feedback &f) {
            auto result = std::make_shared<Result>(compute(f));
            return Commit([apply, result] { apply(std::move(*result)); });
        });
    }

    QList<Task *> tasks() const { return m_tasks; }
    int runningCount() const;
    void cancelAll();
    // Blocks until every task has finished (used at shutdown and in tests).
    void waitForAll();
    // Removes finished tasks from the list.
    void clearFinished();

signals:
    void taskStarted(lipsync::Task *task);
    void taskFinished(lipsync::Task *task);
    void tasksCleared();

private:
    // Its own pool, not QThreadPool::globalInstance(): Qt's raster engine paints large areas on
    // the global pool and the GUI thread waits for it, so long tasks filling the global pool
    // would freeze painting (QGIS made the same fix for its task manager).
    QThreadPool m_pool;
    QList<Task *> m_tasks;
    QList<QFutureWatcher<void> *> m_watchers;
    int m_nextId = 1;
};

} // namespace lipsync
