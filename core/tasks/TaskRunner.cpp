#include "tasks/TaskRunner.h"

#include "util/Error.h"

#include "tasks/HandoffFence.h"

#include <QPromise>
#include <QRunnable>
#include <QThread>

#include <algorithm>
#include <memory>

namespace lipsync {

namespace {

struct Outcome
{
    TaskRunner::Commit commit;
    Task::State state = Task::State::Finished;
    QString error;
};

// The work of one task on a pool thread. A QRunnable of ours rather than QtConcurrent::run so that
// the first thing the pool thread does with the task's data is pass handoffFence() (see there).
class Job : public QRunnable
{
public:
    Job(TaskRunner::Work work, std::shared_ptr<Outcome> outcome, Feedback *feedback)
        : m_work(std::move(work)), m_outcome(std::move(outcome)), m_feedback(feedback)
    {
        m_promise.start();
    }
    QFuture<void> future() { return m_promise.future(); }

    void run() override
    {
        handoffFence();
        try {
            m_outcome->commit = m_work(*m_feedback);
        } catch (const Canceled &) {
            m_outcome->state = Task::State::Canceled;
        } catch (const std::exception &e) {
            m_outcome->state = Task::State::Failed;
            m_outcome->error = QString::fromUtf8(e.what());
        }
        // Drop the work's captures here, on the worker, before the GUI thread is told.
        m_work = nullptr;
        handoffFence();
        m_promise.finish();
    }

private:
    TaskRunner::Work m_work;
    std::shared_ptr<Outcome> m_outcome;
    Feedback *m_feedback;
    QPromise<void> m_promise;
};

} // namespace

TaskRunner::TaskRunner(QObject *parent) : QObject(parent)
{
    m_pool.setMaxThreadCount(std::max(2, QThread::idealThreadCount()));
}

TaskRunner::~TaskRunner()
{
    cancelAll();
    waitForAll();
}

Task *TaskRunner::start(const QString &title, Work work)
{
    auto *task = new Task(m_nextId++, title, this);
    m_tasks.append(task);

    auto outcome = std::make_shared<Outcome>();
    auto *watcher = new QFutureWatcher<void>(this);
    m_watchers.append(watcher);

    connect(watcher, &QFutureWatcher<void>::finished, this, [this, task, watcher, outcome] {
        handoffFence();
        m_watchers.removeOne(watcher);
        watcher->deleteLater();
        Task::State state = outcome->state;
        QString error = outcome->error;
        if (state == Task::State::Finished && task->feedback().isCanceled())
            state = Task::State::Canceled; // canceled after the last poll: still drop the result
        if (state == Task::State::Finished && outcome->commit) {
            try {
                outcome->commit();
            } catch (const std::exception &e) {
                state = Task::State::Failed;
                error = QString::fromUtf8(e.what());
            }
        }
        task->finish(state, error);
        emit taskFinished(task);
    });

    auto *job = new Job(std::move(work), outcome, &task->feedback());
    watcher->setFuture(job->future());
    handoffFence();
    m_pool.start(job); // the pool deletes the job after run()
    emit taskStarted(task);
    return task;
}

int TaskRunner::runningCount() const
{
    int n = 0;
    for (const Task *t : m_tasks)
        n += t->isRunning() ? 1 : 0;
    return n;
}

void TaskRunner::cancelAll()
{
    for (Task *t : m_tasks)
        t->cancel();
}

void TaskRunner::waitForAll()
{
    for (QFutureWatcher<void> *w : QList<QFutureWatcher<void> *>(m_watchers))
        w->waitForFinished();
}

void TaskRunner::clearFinished()
{
    for (auto it = m_tasks.begin(); it != m_tasks.end();) {
        if (!(*it)->isRunning()) {
            (*it)->deleteLater();
            it = m_tasks.erase(it);
        } else {
            ++it;
        }
    }
    emit tasksCleared();
}

} // namespace lipsync
