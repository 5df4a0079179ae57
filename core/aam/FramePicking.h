#pragma once
// Frames of a speaker's clips to label for a person-specific AAM, the cheap way (what `lipsync aam
// select` and the studio's Faces > Pick Frames to Label do): every step-th frame with a confident
// face is a candidate, described by its appearance; selectDiverseFrames (FrameSelection.h) picks
// the ones that differ most; each pick gets automatic 23 points (AutoLandmarks.h); and the picks are
// ranked for review by how far an AAM built from the other picks moves their points (5-fold, so a
// misplaced point is not in the model that judges it): the frames to check first.
#include "aam/AutoLandmarks.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace lipsync {

class AamModel;
class FaceDetector;
class Feedback;

struct FramePickingOptions
{
    int count = 150;     // frames to pick
    int step = 5;        // look at every step-th frame
    int dimensions = 24; // PCA dimensions of the appearance descriptors
    AutoLandmarkMethod method = AutoLandmarkMethod::Auto;
    const AamModel *aam = nullptr; // for AutoLandmarkMethod::Aam (and Auto without dlib)
    bool review = true;            // rank the picks by disagreement (needs 3 picks or more)
    // Detections below this score are not candidates (flat grey frames before a keyframe, blur).
    static constexpr double kMinScore = 0.8;
};

struct PickedFrame
{
    int source = 0;          // index into the videos given
    int frame = 0;           // 0-based
    double distance = 0.0;   // farthest-point distance when picked (first: +inf)
    Eigen::VectorXd shape;   // automatic 23 points, flat, 0-based pixels
    std::string method;      // what placed them (AutoLandmarks::method)
    double disagreement = -1.0; // NME the held-out AAM moves the points by (-1: not reviewed)
    cv::Mat pixels;          // the frame (BGR)
};

struct FramePicking
{
    std::vector<PickedFrame> frames;      // by video, then frame
    std::vector<int> worstFirst;          // indices into frames, largest disagreement first
    int candidates = 0;                   // frames with a confident face
    std::vector<std::pair<int, int>> isolated; // (video, frame) left out as unlike other clips
    std::vector<std::string> warnings;
};

// Picks from `videos` (paths). Throws lipsync::Error naming a video that cannot be read, or when no
// candidate frame has a face; Canceled when `feedback` is canceled. Progress: the candidates up to
// 0.7, the points to 0.85, the review to 1.
FramePicking pickFramesToLabel(const std::vector<std::string> &videos, const FramePickingOptions &options,
                               FaceDetector &detector, Feedback &feedback);

} // namespace lipsync
