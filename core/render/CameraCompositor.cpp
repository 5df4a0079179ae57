#include "render/CameraCompositor.h"

#include "aam/AamModel.h"
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "util/Error.h"

#include <algorithm>

namespace lipsync {

namespace {

std::unique_ptr<FaceDetector> detectorUnless(FaceDetector *given)
{
    if (given)
        return nullptr;
    return std::make_unique<FaceDetector>(FaceDetectorPaths::boxesOnly());
}

} // namespace

CameraCompositor::CameraCompositor(const AamModel &aam, FaceDetector *detector)
    : m_aam(aam),
      m_ownDetector(detectorUnless(detector)),
      m_detector(detector ? detector : m_ownDetector.get()),
      m_synthesizer(aam),
      m_tracker(aam, m_detector)
{
}

CameraCompositor::~CameraCompositor() = default;

bool CameraCompositor::compose(cv::Mat &frame, const Eigen::VectorXd &features, const CompositeOptions &options)
{
    if (frame.empty() || frame.type() != CV_8UC3)
        throw Error("a camera frame must be an 8-bit BGR image");
    if (features.size() != m_aam.combinedModes())
        throw Error("the features have " + std::to_string(features.size()) + " parameters, the AAM "
                    + std::to_string(m_aam.combinedModes()));
    const TrackedFrame tracked = m_tracker.track(frame);
    // The tracker follows its last fit wherever it is; the detector says whether a face is still
    // there: every kVerifyFrames frames since it last found it, one of its faces must hold the
    // tracked face's centre.
    bool lost = !tracked.found;
    if (tracked.found && (tracked.redetected || ++m_sinceDetection >= kVerifyFrames)) {
        m_sinceDetection = 0;
        if (!tracked.redetected) {
            const Eigen::Vector2d centre = shapeCentroid(tracked.fit.shape);
            const std::vector<FaceDetection> faces = m_detector->detect(frame);
            lost = std::none_of(faces.begin(), faces.end(),
                                [&](const FaceDetection &f) { return f.box.contains({centre.x(), centre.y()}); });
        }
    }
    if (lost) {
        reset();
        return false;
    }
    const Similarity measured = alignSimilarity(m_synthesizer.shape(tracked.features), tracked.fit.shape);
    if (!m_pose || tracked.redetected) {
        m_pose = measured;
    } else {
        const double w = kPoseSmoothing;
        m_pose = Similarity{(1 - w) * m_pose->a + w * measured.a, (1 - w) * m_pose->b + w * measured.b,
                            (1 - w) * m_pose->tx + w * measured.tx, (1 - w) * m_pose->ty + w * measured.ty};
    }
    // Laid by the eye corners on the tracked face at that pose, as FaceRenderer draws.
    const Similarity drawn = alignByEyes(m_synthesizer.shape(features), m_pose->apply(m_synthesizer.shape(tracked.features)));
    m_synthesizer.composite(features, drawn, frame, options);
    return true;
}

void CameraCompositor::reset()
{
    m_tracker.reset();
    m_pose.reset();
    m_sinceDetection = 0;
}

} // namespace lipsync
