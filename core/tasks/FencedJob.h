#pragma once
// One function run on a thread pool, both hand-overs through handoffFence() (see there), so that
// ThreadSanitizer checks the work itself instead of a suppression hiding the pool's hand-over
// (Qt orders it with locks inside uninstrumented libQt6Core). What the task runner's jobs and the
// autosave's background write run on, instead of QtConcurrent::run.
#include "tasks/HandoffFence.h"

#include <QFuture>
#include <QPromise>
#include <QRunnable>
#include <QThreadPool>

#include <functional>
#include <type_traits>
#include <utility>

namespace lipsync {

namespace detail {

template <typename R>
class FencedJob final : public QRunnable
{
public:
    explicit FencedJob(std::function<R()> work) : m_work(std::move(work)) { m_promise.start(); }
    QFuture<R> future() { return m_promise.future(); }

    void run() override
    {
        handoffFence();
        if constexpr (std::is_void_v<R>) {
            m_work();
            m_work = nullptr;
        } else {
            R result = m_work();
            m_work = nullptr;
            m_promise.addResult(std::move(result));
        }
        handoffFence();
        m_promise.finish();
    }

private:
    std::function<R()> m_work;
    QPromise<R> m_promise;
};

} // namespace detail

// Starts `work` on `pool` and returns its future. `work` must not throw (catch inside it and put
// the error in the result). Its captures are destroyed on the pool thread, before the future
// finishes: a finished future's watcher never frees what the worker still uses.
template <typename R>
QFuture<R> startFenced(QThreadPool &pool, std::function<R()> work)
{
    auto *job = new detail::FencedJob<R>(std::move(work));
    QFuture<R> future = job->future();
    handoffFence(); // after everything `work` captured was written
    pool.start(job); // the pool deletes the job after run()
    return future;
}

} // namespace lipsync
