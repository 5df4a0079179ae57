#pragma once
// Choosing which frames to label for a person-specific AAM. The paper's AAM (§4, after Cootes,
// Edwards & Taylor 2001) needs training images that cover the face's range of shape and
// appearance; frames of one speaker's clips are mostly alike, so picking them at random labels the
// same closed, neutral mouth many times. Instead every candidate frame is described by its
// detected face, normalised for position, size and roll, at low resolution (the mouth weighted
// over the rest of the face), the descriptors are reduced by PCA, and frames are picked by
// farthest-point sampling in that space: each pick is the candidate farthest from all picks so
// far, so the picks spread over the appearances the clips hold (Gonzalez 1985: within a factor
// two of the best possible spread).
#include "aam/FaceDetector.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

// The appearance descriptor of a detected face in a BGR (or grey) frame. The face is mapped into a
// 48 x 72 grey canvas by the similarity that puts its eyes at fixed positions: fitted to the eye
// points of `points` (23 points of the face, e.g. dlib's mapped by mapIbug68To23) when given,
// else to YuNet's eye and nose keypoints (a few pixels less precise), else to the box. The mouth
// region at half the canvas resolution and the whole face at a quarter, each with its mean removed
// and scaled to unit length (the face weighted one half), then, with `points`, the mouth and jaw
// points in the canvas relative to a typical face (templateShape), in eye distances, doubled
// (zeros without). Comparable between frames of one camera set-up described the same way.
Eigen::VectorXd faceAppearanceDescriptor(const cv::Mat &frame, const FaceDetection &face,
                                         const Eigen::VectorXd &points = {});

struct DiverseSelection
{
    std::vector<int> picks;         // column indices, in the order picked
    std::vector<double> distances;  // each pick's distance to the picks before it (first: +inf)
};

// Farthest-point sampling of `count` columns of `points` (dimensions x n), starting from the
// column nearest the mean. Fewer picks when there are fewer distinct columns.
DiverseSelection farthestPointSample(const Eigen::MatrixXd &points, int count);

// Columns of `points` unlike anything in other groups (clips): the distance to their k-th nearest
// column of another group is far out among all columns' (above Q3 + 3 IQR, Tukey's far-out
// fence). Farthest-point sampling seeks out the most unusual frames, and a frame unusual only
// within its own clip is usually a defect — frames decoded before a stream's first keyframe, a
// hand in front of the face — where an expression the speaker makes recurs in other clips.
// Empty `groups`, or a single group: no outliers.
std::vector<bool> isolatedColumns(const Eigen::MatrixXd &points, const std::vector<int> &groups, int k = 3);

// faceAppearanceDescriptor columns reduced to their first `dimensions` principal components,
// isolated columns (by `groups`) left out, then farthestPointSample. `excluded`, when given,
// receives the isolated columns' indices.
DiverseSelection selectDiverseFrames(const Eigen::MatrixXd &descriptors, int count, int dimensions = 24,
                                     const std::vector<int> &groups = {}, std::vector<int> *excluded = nullptr);

} // namespace lipsync
