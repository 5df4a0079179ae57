#pragma once
// Face detectors shared by the jobs of parallel work (the realism report, the folder forms of
// `landmarks detect` and `track`): a detector loads its models once (dlib's 68-point predictor
// alone is ~100 MB) and then serves job after job, one job at a time. Thread-safe.
#include "aam/FaceDetector.h"

#include <memory>
#include <mutex>
#include <vector>

namespace lipsync {

class FaceDetectorPool
{
public:
    explicit FaceDetectorPool(FaceDetectorPaths paths = {}) : m_paths(std::move(paths)) {}

    const FaceDetectorPaths &paths() const { return m_paths; }

    // An idle detector, or a new one; give it back when the job is done.
    std::unique_ptr<FaceDetector> take();
    void give(std::unique_ptr<FaceDetector> detector);

    // A detector taken for one scope and given back at its end.
    class Lease
    {
    public:
        explicit Lease(FaceDetectorPool &pool) : m_pool(pool), m_detector(pool.take()) {}
        ~Lease() { m_pool.give(std::move(m_detector)); }
        Lease(const Lease &) = delete;
        Lease &operator=(const Lease &) = delete;
        FaceDetector &operator*() const { return *m_detector; }
        FaceDetector *operator->() const { return m_detector.get(); }

    private:
        FaceDetectorPool &m_pool;
        std::unique_ptr<FaceDetector> m_detector;
    };

private:
    FaceDetectorPaths m_paths;
    std::mutex m_mutex;
    std::vector<std::unique_ptr<FaceDetector>> m_idle;
};

} // namespace lipsync
