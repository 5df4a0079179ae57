#include "tasks/Feedback.h"

#include <algorithm>

namespace lipsync {

Feedback &Feedback::none()
{
    thread_local Feedback unwatched;
    return unwatched;
}

Feedback::Feedback(Feedback &parent, double from, double to)
    : m_parent(&parent), m_from(from), m_to(to)
{
}

void Feedback::setProgress(double fraction)
{
    fraction = std::clamp(fraction, 0.0, 1.0);
    m_progress.store(fraction);
    if (onProgress)
        onProgress(fraction);
    if (m_parent)
        m_parent->setProgress(m_from + (m_to - m_from) * fraction);
}

void Feedback::setStatus(const std::string &status)
{
    {
        std::lock_guard lock(m_statusMutex);
        m_status = status;
    }
    if (onStatus)
        onStatus(status);
    if (m_parent)
        m_parent->setStatus(status);
}

std::string Feedback::status() const
{
    std::lock_guard lock(m_statusMutex);
    return m_status;
}

void Feedback::reportIteration(int iteration, double objective)
{
    // Not forwarded to the parent (see the constructor).
    if (onIteration)
        onIteration(iteration, objective);
}

void Feedback::cancel()
{
    m_canceled.store(true);
}

bool Feedback::isCanceled() const
{
    return m_canceled.load() || (m_parent && m_parent->isCanceled());
}

} // namespace lipsync
