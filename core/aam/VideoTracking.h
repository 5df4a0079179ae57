#pragma once
// Feature extraction for a whole video: tracks the face through every frame with FaceTracker and
// returns one row of combined AAM parameters per frame — the paper's y_t, what Sequence::features
// holds. Frames with landmarks a user placed or fixed are fitted with those points held in place.
// Frames where no face can be found (e.g. GRID clips whose first frames decode as flat grey) take
// the parameters of the nearest tracked frame, and are listed.
#include "aam/AamModel.h"
#include "annotation/LandmarkSet.h"

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;
class FaceDetector;

struct VideoTrackingResult
{
    Eigen::MatrixXd features;           // frames x combined modes
    Eigen::MatrixXd shapes;             // frames x 46: fitted 23 points
    Eigen::VectorXd errors;             // per-frame fit error (NaN where no face)
    std::vector<int> framesWithoutFace; // filled from the nearest tracked frame
    int redetections = 0;
    double trackingSeconds = 0.0;       // time spent fitting (excludes decoding)
    double frameRate = 0.0;             // the video's frames per second

    // Frame indices ordered by decreasing fit error: the worst fits, for correction first.
    std::vector<int> worstFrames(int count) const;
};

// The video's first `frames` frames when that is above 0, else all of them. Throws
// lipsync::Error naming the file if the video cannot be read or no frame holds a face; Canceled
// when `feedback` is canceled.
VideoTrackingResult trackVideo(const AamModel &model, const std::string &videoPath,
                               FaceDetector &detector, Feedback &feedback,
                               const std::map<int, LandmarkSet> &landmarks = {}, int frames = 0);

} // namespace lipsync
