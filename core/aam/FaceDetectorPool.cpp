#include "aam/FaceDetectorPool.h"

namespace lipsync {

std::unique_ptr<FaceDetector> FaceDetectorPool::take()
{
    {
        const std::lock_guard lock(m_mutex);
        if (!m_idle.empty()) {
            auto detector = std::move(m_idle.back());
            m_idle.pop_back();
            return detector;
        }
    }
    return std::make_unique<FaceDetector>(m_paths);
}

void FaceDetectorPool::give(std::unique_ptr<FaceDetector> detector)
{
    if (!detector)
        return;
    const std::lock_guard lock(m_mutex);
    m_idle.push_back(std::move(detector));
}

} // namespace lipsync
