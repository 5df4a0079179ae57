#pragma once
// The 23 points of a detected face without a person: dlib's 68-point predictor mapped to the
// 23-point scheme when it is installed, else an AAM fitted from the detection (when a model is
// given), else the template shape placed on the detection. What `landmarks detect` writes and what
// `aam select` labels its frames with.
#include "aam/FaceDetector.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <string>

namespace lipsync {

class AamFitter;

enum class AutoLandmarkMethod { Auto, Dlib, Aam, Template };

struct AutoLandmarks
{
    Eigen::VectorXd shape; // 23 points, flat, 0-based pixels
    std::string method;    // what placed them: "dlib", "aam" or "template"
};

// "auto", "dlib", "aam" or "template"; false for anything else.
bool parseAutoLandmarkMethod(const std::string &name, AutoLandmarkMethod &method);

// The points of `face` in `bgr`. Dlib needs a detector made with useDlib; Aam needs `fitter` (an
// AamFitter precomputes per model: callers over many frames make one and pass it to every call).
// Throws lipsync::Error for Dlib without dlib's predictor.
AutoLandmarks detectAutoLandmarks(const cv::Mat &bgr, const FaceDetection &face, FaceDetector &detector,
                                  AutoLandmarkMethod method, const AamFitter *fitter = nullptr);

} // namespace lipsync
