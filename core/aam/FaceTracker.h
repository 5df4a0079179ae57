#pragma once
// Tracks a face through video frames with an AAM: the previous frame's fit initialises the next;
// the face is detected again when there is no previous fit or when the fit error jumps (above
// `redetectFactor` x the running median and above `minRedetectError`), and the better of the two
// fits is kept. Each tracked frame yields the combined AAM parameters, the paper's y_t.
#include "aam/AamFitter.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <deque>

namespace lipsync {

class FaceDetector;

struct FaceTrackerOptions
{
    double redetectFactor = 2.0;
    double minRedetectError = 0.15;
    int historyLength = 25;    // frames in the running median of the fit error
    bool fineLevelOnly = true; // frame-to-frame motion is small: fit the finest level only
};

struct TrackedFrame
{
    bool found = false;      // false: no face (detector found none and there was no previous fit)
    bool redetected = false; // the detector (re)initialised this frame
    AamFitResult fit;
    Eigen::VectorXd features; // combined parameters c
};

class FaceTracker
{
public:
    // `detector` may be null: then the first frame needs an initial shape (setShape()).
    FaceTracker(const AamModel &model, FaceDetector *detector, FaceTrackerOptions options = {});

    // Tracks one BGR frame. `fitOptions` carries fixed points, if any.
    TrackedFrame track(const cv::Mat &bgr, const AamFitOptions &fitOptions = {});
    // Starts (or restarts) from a known shape in the next frame.
    void setShape(const Eigen::VectorXd &shape);
    void reset();

    const AamFitter &fitter() const { return m_fitter; }

private:
    double medianError() const;
    bool fitFromDetection(const cv::Mat &bgr, const cv::Mat &grey, const AamFitOptions &options,
                          AamFitResult &out);

    AamFitter m_fitter;
    FaceDetector *m_detector;
    FaceTrackerOptions m_options;
    Eigen::VectorXd m_previous;
    std::deque<double> m_errors;
};

} // namespace lipsync
