#pragma once
// A point both threads of a hand-over pass, so that ThreadSanitizer sees the order Qt guarantees.
// Qt's thread pool and queued calls order the hand-over with QMutex, which locks by futex inside
// libQt6Core; Debian's Qt is not built with -fsanitize=thread, so TSan cannot see that lock and
// reports every first read of a task's data on the pool thread (and of its result on the GUI thread)
// as a race. A std::mutex is intercepted by TSan: the side that hands over passes the fence after
// writing, the side that takes over passes it before reading, and TSan then checks the work itself.
// Costs two uncontended lock/unlock pairs per hand-over.
#include <mutex>

namespace lipsync {

inline void handoffFence()
{
    static std::mutex mutex;
    std::lock_guard lock(mutex);
}

} // namespace lipsync
