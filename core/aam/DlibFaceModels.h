#pragma once
// dlib's HOG frontal-face detector and its 68-point shape predictor (Debian's libdlib-dev and
// libdlib-data) behind a small interface. This is the only translation unit that includes dlib's
// headers: dlib is header-template code, compiled into whoever includes it, so sanitized builds
// compile this file without instrumentation and optimised like the system libraries they do not
// instrument either (core/aam/CMakeLists.txt): instrumented at -O1, dlib's filters took four
// fifths of the sanitized realism evaluation's time.
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class DlibFaceModels
{
public:
    DlibFaceModels();
    ~DlibFaceModels();
    DlibFaceModels(const DlibFaceModels &) = delete;
    DlibFaceModels &operator=(const DlibFaceModels &) = delete;

    // Whether this build has dlib at all.
    static bool available();
    // Reads the shape predictor; false (and nothing loaded) when the file cannot be read.
    bool loadPredictor(const std::string &path);
    bool hasPredictor() const;
    // Boxes of dlib's HOG frontal-face detector in an 8-bit grey image (created on first use).
    std::vector<cv::Rect2d> hogFaces(const cv::Mat &grey);
    // The 68 iBUG points (flat x0 y0 x1 y1 …) the predictor places in `box` of an 8-bit grey
    // image; empty without a predictor.
    Eigen::VectorXd landmarks68(const cv::Mat &grey, const cv::Rect2d &box) const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace lipsync
