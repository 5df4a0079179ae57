#include "tasks/TaskRunner.h"

#include "tasks/FencedJob.h"
#include "util/Error.h"

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

    Feedback *feedback = &task->feedback();
    watcher->setFuture(startFenced<void>(m_pool, [work = std::move(work), outcome, feedback] {
        try {
            outcome->commit = work(*feedback);
        } catch (const Canceled &) {
            outcome->state = Task::State::Canceled;
        } catch (const std::exception &e) {
            outcome->state = Task::State::Failed;
            outcome->error = QString::fromUtf8(e.what());
        }
    }));
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
