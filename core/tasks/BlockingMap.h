#pragma once
// QtConcurrent::blockingMap with its hand-overs made visible to ThreadSanitizer (see HandoffFence.h).
// Qt orders the caller's writes before each item's work, and each item's work before the caller's
// reads after the map, with QThreadPool's QMutex and QtConcurrent's barrier — both inside
// uninstrumented Qt, so TSan reported the first read of a fitted dimension after the map (DPDS) as
// a race. Passing the fence at those four points lets TSan check the items' work itself.
// Costs two uncontended lock/unlock pairs per item; the items are whole model dimensions or folds.
#include "tasks/HandoffFence.h"

#include <QtConcurrent/QtConcurrentMap>

namespace lipsync {

template <typename Sequence, typename Work>
void blockingMap(Sequence &sequence, const Work &work)
{
    handoffFence();
    QtConcurrent::blockingMap(sequence, [&work](typename Sequence::value_type &item) {
        handoffFence();
        work(item);
        handoffFence();
    });
    handoffFence();
}

} // namespace lipsync
