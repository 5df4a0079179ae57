#pragma once
// Generated faces drawn over frames that arrive one at a time, as from a camera (the Live view's
// camera background): the face in each frame is tracked with the AAM (FaceTracker: the previous
// frame's fit starts the next, the detector finds it again when it is lost), its pose is the
// similarity from the shape of the tracked parameters to the fitted points — what FaceRenderer
// computes for a recorded video — smoothed causally, since later frames are not there yet; the
// detector checks every few frames that the tracked face is still there; and
// the generated face is composited at that pose, laid on the tracked face by the eye corners
// (alignByEyes; AamSynthesizer: by default the lower face, colour-matched to the frame along the
// seam).
#include "aam/AamSynthesizer.h"
#include "aam/FaceTracker.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <memory>
#include <optional>

namespace lipsync {

class AamModel;
class FaceDetector;

class CameraCompositor
{
public:
    // Share of the new pose in each frame's smoothed pose (an exponential moving average): the
    // tracker's jitter of a pixel or so is damped, a moving head is followed within a few frames.
    static constexpr double kPoseSmoothing = 0.5;
    // Frames between the detector's checks that a tracked face is still there (0.2 s at 25 fps):
    // a face that leaves the picture stops being drawn within them.
    static constexpr int kVerifyFrames = 5;

    // `detector` null: a YuNet FaceDetector of its own (dlib's predictor is not needed: the AAM
    // fit places the points). The model must outlive the compositor.
    explicit CameraCompositor(const AamModel &aam, FaceDetector *detector = nullptr);
    ~CameraCompositor();
    CameraCompositor(const CameraCompositor &) = delete;
    CameraCompositor &operator=(const CameraCompositor &) = delete;

    // Composites `features` (combined AAM parameters) into `frame` (BGR, 8-bit, changed in place)
    // at the face tracked there. False, the frame unchanged, when no face is found in it (or the
    // detector's check finds the tracked one gone).
    bool compose(cv::Mat &frame, const Eigen::VectorXd &features, const CompositeOptions &options = {});
    // The smoothed pose of the last frame with a face (model coordinates -> frame).
    const std::optional<Similarity> &pose() const { return m_pose; }
    // Forgets the face (a new camera, or a jump): the next frame is detected afresh.
    void reset();

private:
    const AamModel &m_aam;
    std::unique_ptr<FaceDetector> m_ownDetector;
    FaceDetector *m_detector;
    AamSynthesizer m_synthesizer;
    FaceTracker m_tracker;
    std::optional<Similarity> m_pose;
    int m_sinceDetection = 0;
};

} // namespace lipsync
