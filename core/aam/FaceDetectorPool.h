#pragma once
// Face detectors shared by the jobs of parallel work (the realism report, the folder forms of
// `landmarks detect` and `track`): a detector loads its models once (dlib's 68-point predictor
// alone is ~100 MB) and then serves job after job, one at a time.
#include "aam/FaceDetector.h"
#include "util/ObjectPool.h"

namespace lipsync {

class FaceDetectorPool : public ObjectPool<FaceDetector>
{
public:
    explicit FaceDetectorPool(FaceDetectorPaths paths = {})
        : ObjectPool([paths] { return std::make_unique<FaceDetector>(paths); }), m_paths(std::move(paths))
    {
    }
    const FaceDetectorPaths &paths() const { return m_paths; }

private:
    FaceDetectorPaths m_paths;
};

} // namespace lipsync
