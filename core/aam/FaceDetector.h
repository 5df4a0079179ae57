#pragma once
// Automatic landmarks for a new face: YuNet (OpenCV's cv::FaceDetectorYN with the 2022mar model
// shipped in resources/models) finds the face box and five keypoints; a Haar cascade (Debian's
// opencv-data) is the fallback when YuNet is missing or finds nothing; dlib's 68-point shape
// predictor (Debian's libdlib-data) gives all 68 iBUG points when it is installed, mapped to the
// 23-point scheme. Everything optional degrades cleanly: a missing file just disables that stage
// (see available()).
#include "aam/Procrustes.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

struct FaceDetection
{
    cv::Rect2d box;
    double score = 0.0;
    // Image-left eye, image-right eye, nose tip, image-left and image-right mouth corner.
    bool hasKeypoints = false;
    std::array<Eigen::Vector2d, 5> keypoints{};
    std::string source; // "yunet" or "haar"
};

struct FaceDetectorPaths
{
    std::string yunetModel;   // empty: $LIPSYNC_YUNET_MODEL, else the shipped one (util/ResourceLocator)
    std::string haarCascade;  // empty: systempaths::kHaarCascade
    std::string dlibPredictor; // empty: systempaths::kDlibPredictor
    bool useDlib = true;

    // Face boxes with their five keypoints only (YuNet, else Haar), for fitting and tracking:
    // dlib's 68-point predictor takes seconds to load and the AAM fit refines the points anyway.
    static FaceDetectorPaths boxesOnly();

    // The files the detectors are read from: the given ones, else Debian's (opencv-data,
    // libdlib-data).
    std::string haarCascadeFile() const;
    std::string dlibPredictorFile() const;
};

class FaceDetector
{
public:
    explicit FaceDetector(const FaceDetectorPaths &paths = {});
    ~FaceDetector();
    FaceDetector(const FaceDetector &) = delete;
    FaceDetector &operator=(const FaceDetector &) = delete;

    bool hasYunet() const;
    bool hasHaar() const;
    bool hasDlib() const;
    // One line saying which stages are available (for --json and messages).
    std::string available() const;

    // Faces in a BGR image, best first. Empty when none is found.
    std::vector<FaceDetection> detect(const cv::Mat &bgr);
    // 68 iBUG points (flat, 0-based) inside `face` from dlib, or an empty vector without dlib.
    Eigen::VectorXd dlibLandmarks(const cv::Mat &bgr, const FaceDetection &face);
    // The two halves of dlibLandmarks: the box dlib's predictor expects for `face` (its HOG
    // detector's box overlapping the face, else the YuNet box moved towards that convention;
    // nothing without dlib), and the 68 points predicted inside a given box. Measuring several
    // renderings of one recorded frame (core/eval/LipOpening) reuses the recording's box.
    std::optional<cv::Rect2d> dlibFaceBox(const cv::Mat &bgr, const FaceDetection &face);
    Eigen::VectorXd dlibLandmarksInBox(const cv::Mat &bgr, const cv::Rect2d &box);

    // Where the YuNet model was found (empty if not).
    static std::string findYunetModel();

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

// The four reference points of a 23-point shape that detector keypoints correspond to: the eye
// centres (mean of each eye's four points) and the mouth corners (flat, 8 values).
Eigen::VectorXd keypointAnchors(const Eigen::VectorXd &shape);
// The detector keypoints matching keypointAnchors() (flat, 8 values); empty without keypoints.
Eigen::VectorXd detectionAnchors(const FaceDetection &face);

// All five keypoints (flat, 10 values: eyes, nose tip, mouth corners); empty without keypoints.
Eigen::VectorXd detectionKeypoints(const FaceDetection &face);

// Places `meanShape` (normalised 23 points) on a detection: a similarity fitted to the eye
// centres and mouth corners for keypoint detections, or to fixed fractions of the box for Haar.
Eigen::VectorXd initialShapeFromDetection(const Eigen::VectorXd &meanShape,
                                          const FaceDetection &face);
// As above with a model: uses its detector-calibrated shape when it has one, and its regression
// on all five keypoints (AamModel::detectorRegression) when it has that too.
class AamModel;
Eigen::VectorXd initialShapeFromDetection(const AamModel &model, const FaceDetection &face);

} // namespace lipsync
