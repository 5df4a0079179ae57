#pragma once
// Rendering AAM parameters (real or generated) as video frames, at the pose of the face in a
// background frame. By default the recording keeps its own face: its lower face is moved from the
// shape tracked in the frame to that shape with the lips' opening and width the parameters give
// (warpedShape: LowerFaceWarp::speechShape, then its thin-plate spline), and only the inside of a
// mouth opened wider than recorded is drawn: the person's own open mouth from another moment of
// the video (MouthExemplars;
// CompositeOptions::recordedInsides) or, without one, from the AAM (shape + texture + exemplar
// detail, AamSynthesizer), blended into the lips with a feathered edge. Lips asked to close where
// the recording's are open are the person's own closed lips from another moment of the video
// (MouthExemplars; CompositeOptions::recordedClosures).
// CompositeOptions::synthesizeSkin pastes the AAM's whole lower-face synthesis instead, and
// FaceRegion::Full the whole modelled face, colour-matched to the frame along the seam.
//
// Two backgrounds:
//  - a video (the sequence's own clip): its face is tracked once with the AAM (trackVideo), and
//    each frame's pose (model coordinates -> image) is the similarity between the shape implied
//    by the tracked parameters and the fitted points, lightly smoothed over time so the pasted
//    face does not jitter with the tracker. Frames past the end of the video hold its last frame.
//  - a neutral frame when there is no video (generation from an audio file): the AAM's mean face
//    on a mid-grey frame, centred and scaled to fill half the frame height.
// Per frame the work is one synthesis and one pass over the face's pixels (no allocation beyond
// the output frame), so rendering runs far faster than real time.
#include "aam/AamModel.h"
#include "aam/AamSynthesizer.h"
#include "render/BackgroundRetiming.h"
#include "render/MouthExemplars.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;
class FaceDetector;
class VideoReader;

class FaceRenderer
{
public:
    // Neutral background of `size` pixels.
    explicit FaceRenderer(const AamModel &aam, cv::Size size = cv::Size(360, 288));
    // The frames of `videoPath`, the face tracked with `detector` (null: a default FaceDetector);
    // only its first `frames` when that is above 0 (1: a still of the person, drawn into again
    // and again). Throws lipsync::Error naming the file if it cannot be read or holds no face;
    // Canceled.
    FaceRenderer(const AamModel &aam, const std::string &videoPath, Feedback &feedback,
                 FaceDetector *detector = nullptr, int frames = 0);
    ~FaceRenderer();
    FaceRenderer(const FaceRenderer &) = delete;
    FaceRenderer &operator=(const FaceRenderer &) = delete;

    const AamModel &aam() const { return m_aam; }
    bool hasVideo() const;
    // Frames of the background video used (0 for the neutral background).
    int videoFrameCount() const;
    double videoFrameRate() const; // 0 for the neutral background
    cv::Size frameSize() const;

    // Frames `index` from now on stand for the background frames of a re-timing of the video to
    // `frames` frames (new speech in the person's own video, BackgroundRetiming); `frames` 0
    // undoes it. No effect without a video.
    void retime(int frames, const BackgroundRetimingOptions &options = {});
    // The re-timing retime() would use, leaving this renderer as it is (for a renderer shared
    // with views that show the video's frames themselves).
    BackgroundRetiming retimingFor(int frames, const BackgroundRetimingOptions &options = {}) const;
    const BackgroundRetiming &retiming() const { return m_retiming; }

    // The untouched background of frame `index` (BGR 8-bit; a copy). The frame last asked for is
    // kept, so a still asked for frame by frame is decoded once, not sought again each time.
    cv::Mat background(int index);
    // Parameters tracked in the background video (frames x d; empty for the neutral background).
    const Eigen::MatrixXd &trackedFeatures() const { return m_tracked; }
    // Pose of the face in frame `index` (the last frame's beyond the end).
    const Similarity &pose(int index) const;
    // The background's slow posture at frame `index`: its tracked parameters smoothed over time
    // (PostureTransfer::slowPosture); empty for the neutral background, NaN where no face is near.
    Eigen::VectorXd posture(int index) const;

    // How the face is composited (the lower face, colour-matched, unless set otherwise).
    void setCompositeOptions(const CompositeOptions &options) { m_composite = options; }
    const CompositeOptions &compositeOptions() const { return m_composite; }

    // Whether the face in background frame `index` is hidden or lost: the tracker found none, or
    // its fit error is over 25 times the video's median (a hand or a microphone over the mouth;
    // a blink stays under 15).
    // Such frames are left as recorded: nothing is drawn over what covers the face.
    bool occluded(int index) const;
    // The rule, on a video's per-frame fit errors (NaN: no face): covered where the error is over
    // 25 times the median and over 4 times the upper quartile — a rare outlier, not the wide-open
    // mouths an AAM of few frames fits far worse than the closed ones.
    static std::vector<bool> occludedFrames(const Eigen::VectorXd &errors);

    // `features` (combined AAM parameters c) drawn into the background of frame `index`.
    cv::Mat render(int index, const Eigen::VectorXd &features);
    // Same, into a caller's frame (CV_8UC3, frameSize()) already holding the background; with
    // `options`, composited that way instead of compositeOptions().
    void renderInto(int index, const Eigen::VectorXd &features, cv::Mat &frame) const;
    void renderInto(int index, const Eigen::VectorXd &features, cv::Mat &frame,
                    const CompositeOptions &options) const;
    // How much of each pixel renderInto() replaces with synthesis for these features (CV_32F,
    // 0..1; what the warp moves is the recording's own and counts 0).
    // `inside` (optional) is set when that is the drawn inside of a mouth opened wider than
    // recorded (the default composite), not closed lips or a synthesised face; `closing`
    // (optional) when it is closed lips drawn over an open recorded mouth.
    cv::Mat synthesisedWeight(int index, const Eigen::VectorXd &features, bool *inside = nullptr,
                              bool *closing = nullptr) const;
    // The inside of the mouth of `shape` (23 points in the frame's pixels) at full weight, feathered
    // and faded toward the corners as a drawn inside is (CV_32F, frame size): where a recorded
    // mouth's own inner-lip edge lies, the real counterpart of a drawn inside's edge
    // (RealismReport's seamDeltaENatural).
    cv::Mat insideWeight(const Eigen::VectorXd &shape) const;
    // The video's own mouths the renderer draws closures and insides with (empty without a video).
    const MouthExemplars &mouths() const { return m_mouths; }
    // The AAM's synthesis the renderer draws with (its shapes and textures of parameters).
    const AamSynthesizer &synthesizer() const { return m_synthesizer; }
    // The 23 points of the face tracked in frame `index`, in its pixels (the mean shape at the
    // neutral frame's pose without a video).
    Eigen::VectorXd trackedShape(int index) const;
    // Where parameters `features` are drawn into frame `index` (model coordinates -> its pixels):
    // their shape laid on the tracked face by the eye corners (alignByEyes), so the mouth opens
    // and closes about eyes that stay where the recording has them (pose(index) for the tracked
    // parameters themselves).
    Similarity drawnPose(int index, const Eigen::VectorXd &features) const;
    // The 23 points of parameters `features` drawn into frame `index`, in its pixels.
    Eigen::VectorXd drawnShape(int index, const Eigen::VectorXd &features) const;
    // The 23 points the default composite moves the recording's face in frame `index` to for
    // `features`: its tracked shape with the lips' opening and width of drawnShape()
    // (LowerFaceWarp::speechShape).
    Eigen::VectorXd warpedShape(int index, const Eigen::VectorXd &features) const;
    // Where a render composited as `options` says puts the face's 23 points: warpedShape() for the
    // default composite, drawnShape() for a synthesised face.
    Eigen::VectorXd renderedShape(int index, const Eigen::VectorXd &features, const CompositeOptions &options) const;
    // The real frame on the left and the rendered one on the right, one frame (optional labels).
    cv::Mat renderSideBySide(int index, const Eigen::VectorXd &features,
                             const std::string &leftLabel = {}, const std::string &rightLabel = {});

private:
    // The background video's frame that output frame `index` shows.
    int sourceFrame(int index) const;
    // The synthesised inside of the mouth over the warped frame: its alpha (CV_32F, frame size),
    // zero where the recording's own mouth, moved, already shows as much opening.
    // `generated` and `tracked`: the generated and the tracked 23 points in the frame's pixels.
    // `closing` (optional) is set when the alpha draws closed lips over an open recorded mouth.
    cv::Mat mouthInteriorAlpha(const Eigen::VectorXd &generated, const Eigen::VectorXd &tracked,
                               bool *closing = nullptr) const;
    // `outline` filled at `weight` over the frame (CV_32F), its edge blurred by `feather` pixels;
    // `reach` (optional) is set to a box outside which the result is zero.
    cv::Mat featheredPolygon(const std::vector<cv::Point2f> &outline, double feather, float weight,
                             cv::Rect *reach = nullptr) const;
    // The inside of the mouth of `shape` at `weight`, feathered and faded toward its corners.
    cv::Mat insideAlpha(const Eigen::VectorXd &shape, float weight) const;

    const AamModel &m_aam;
    AamSynthesizer m_synthesizer;
    std::unique_ptr<VideoReader> m_video;
    int m_frameCount = 0;              // the video's frames used
    cv::Mat m_neutral;                 // the neutral background (no video)
    int m_lastIndex = -1;              // the background frame last decoded, and its image
    cv::Mat m_last;
    cv::Size m_size;
    std::vector<Similarity> m_poses;   // one per video frame, or one for the neutral frame
    Eigen::MatrixXd m_tracked;
    Eigen::MatrixXd m_posture;         // PostureTransfer::slowPosture of m_tracked
    std::vector<bool> m_occluded;      // per video frame (occluded())
    MouthExemplars m_mouths;           // the video's own closed and open mouths
    CompositeOptions m_composite;
    BackgroundRetiming m_retiming;     // empty: frame i is the video's frame i
};

} // namespace lipsync
