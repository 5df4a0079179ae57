#pragma once
// A machine observer for the realism report (docs/models.md §6.5): can a simple classifier tell
// recorded frames from rendered ones by how the mouth looks? Its input is the mouth's appearance,
// a crop around dlib's mouth points of the frame judged (each frame its own, as a detector of
// rendered faces crops them):
// OpenCV's HOG of the grey crop (48 x 24 pixels, 8-pixel cells, 16-pixel blocks) and the mean and
// standard deviation of CIE Lab over the crop and over a 3 x 2 grid of it. Its classifier is L2
// regularised logistic regression on standardised features (Newton's method with Eigen's LDLT),
// trained on the sequences of the other folds and tested on a fold's own: frame accuracy over
// the held-out frames, video accuracy from each held-out video's mean score. 0.5 means it cannot
// tell them apart; 1.0 that it always can.
//
// Both sides pass through the same encoder first (the renders are exported, the recording is
// re-encoded by the same exporter; by default losslessly at full colour resolution), so that
// compression cannot give the render away; a control compares the recording with its own second
// re-encode, which should read about 0.5.
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <array>
#include <limits>
#include <vector>

namespace lipsync {

// The mouth's appearance in `frame` inside `mouth` (widened by half its width and height).
Eigen::VectorXf mouthAppearance(const cv::Mat &frame, const cv::Rect2d &mouth);

class LinearObserver
{
public:
    // Rows of `real` and `rendered` are appearance vectors; `ridge` the L2 weight.
    void fit(const Eigen::MatrixXf &real, const Eigen::MatrixXf &rendered, double ridge = 1.0);
    // > 0: judged rendered.
    double score(const Eigen::VectorXf &appearance) const;

private:
    Eigen::VectorXd m_mean, m_scale, m_weights;
    double m_bias = 0.0;
};

// What the renderer did to a rendered frame: moved the recording's own face only, or also drew an
// inside into a mouth opened wider than recorded, or closed lips over an open recorded mouth
// (FaceRenderer::synthesisedWeight); or moved the face only, squeezing the recorded mouth's
// opening narrower (of the frames where only the face moved, those the observer tells most often;
// closed lips drawn in are told more often still, docs/performance.md).
enum class FrameDrawing { Warped = 0, Inside = 1, Closed = 2, Narrowed = 3 };
constexpr int kFrameDrawings = 4;

struct ObservedClip
{
    int fold = 0;
    Eigen::MatrixXf real;     // appearance of the recording's frames (re-encoded)
    Eigen::MatrixXf rendered; // of the render's frames (encoded the same way)
    // What was drawn in each row of `rendered` (empty, or of another length: not split).
    std::vector<FrameDrawing> drawing;
};

struct ObserverAccuracy
{
    static constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    double frames = kNone; // fraction of held-out frames judged right
    double videos = kNone; // fraction of held-out videos (each clip's real and rendered) judged right
    double recordedJudgedRendered = kNone; // held-out recorded frames judged rendered (false alarms)
    // Held-out rendered frames judged rendered, by what was drawn in them (FrameDrawing; NaN
    // where the fold has none).
    std::array<double, kFrameDrawings> drawnJudgedRendered{kNone, kNone, kNone, kNone};
};

// The accuracy on each fold's clips of an observer trained on the other folds' (NaN for a fold
// without clips or without training clips).
std::vector<ObserverAccuracy> observeByFold(const std::vector<ObservedClip> &clips, int folds);

} // namespace lipsync
