#include "aam/FrameSelection.h"

#include "aam/AamFitter.h"
#include "aam/LandmarkScheme.h"
#include "aam/Pca.h"
#include "aam/Procrustes.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

namespace {

// The canonical frame of the descriptor: eye keypoints at (12, 16) and (36, 16) in a 48 x 72
// canvas, so the chin (about two eye distances below the eyes) is inside; the mouth (about 1.3
// eye distances below) lies in the band of rows 34-60.
constexpr int kCanvasWidth = 48, kCanvasHeight = 72;
constexpr double kEyeY = 16.0, kLeftEyeX = 12.0, kRightEyeX = 36.0;
constexpr double kNoseX = 24.0, kNoseY = 31.0; // YuNet's nose tip on GRID s1, about 0.6 eye distances down
const cv::Rect kMouthRegion(8, 34, 32, 26);
const cv::Size kMouthSize(16, 13), kFaceSize(12, 18);
constexpr double kFaceWeight = 0.5;
// The 23-point scheme: eye points first (8), then mouth (10) and jaw (5).
constexpr int kEyePoints = 8;
constexpr int kShapePoints = scheme23::kPointCount - kEyePoints;
constexpr double kShapeWeight = 2.0;

// templateShape() placed in the canvas: the similarity that puts its eye centres on the canvas's.
const Eigen::VectorXd &canvasTemplate()
{
    static const Eigen::VectorXd shape = [] {
        const Eigen::VectorXd t = templateShape();
        Eigen::VectorXd eyes(4), canvasEyes(4);
        eyes << t.segment(0, 8).reshaped(2, 4).rowwise().mean(), t.segment(8, 8).reshaped(2, 4).rowwise().mean();
        canvasEyes << kLeftEyeX, kEyeY, kRightEyeX, kEyeY;
        return alignSimilarity(eyes, canvasEyes).apply(t);
    }();
    return shape;
}

// Mean removed, unit length (zero stays zero), appended to `out` at `offset`.
void appendNormalisedPatch(const cv::Mat &patch, double weight, Eigen::VectorXd &out, Eigen::Index offset)
{
    Eigen::VectorXd v(patch.rows * patch.cols);
    for (int y = 0; y < patch.rows; ++y)
        for (int x = 0; x < patch.cols; ++x)
            v[y * patch.cols + x] = patch.at<float>(y, x);
    v.array() -= v.mean();
    const double norm = v.norm();
    if (norm > 1e-9)
        v *= weight / norm;
    out.segment(offset, v.size()) = v;
}

} // namespace

Eigen::VectorXd faceAppearanceDescriptor(const cv::Mat &frame, const FaceDetection &face,
                                         const Eigen::VectorXd &points)
{
    const bool withPoints = points.size() == 2 * scheme23::kPointCount;
    const Eigen::VectorXd &canvasShape = canvasTemplate();
    // Canvas -> image similarity p = s R u + t: fitted to the eye points when the face's points are
    // known, else to the detector's eye keypoints and nose tip (a few pixels off on GRID's faces),
    // else to the box's upper half.
    Similarity toImage;
    if (withPoints) {
        toImage = alignSimilarity(canvasShape.head(2 * kEyePoints), points.head(2 * kEyePoints));
    } else {
        Eigen::VectorXd canvasPoints(6), imagePoints(6);
        canvasPoints << kLeftEyeX, kEyeY, kRightEyeX, kEyeY, kNoseX, kNoseY;
        if (face.hasKeypoints) {
            imagePoints << face.keypoints[0], face.keypoints[1], face.keypoints[2];
        } else {
            const cv::Rect2d &b = face.box;
            imagePoints << b.x + 0.3 * b.width, b.y + 0.4 * b.height, b.x + 0.7 * b.width, b.y + 0.4 * b.height,
                b.x + 0.5 * b.width, b.y + 0.6 * b.height;
        }
        toImage = alignSimilarity(canvasPoints, imagePoints);
    }
    const double scale = toImage.scale();
    const Eigen::Index patches = Eigen::Index(kMouthSize.area()) + Eigen::Index(kFaceSize.area());
    Eigen::VectorXd out = Eigen::VectorXd::Zero(patches + 2 * kShapePoints);
    if (!(scale > 0) || !std::isfinite(scale))
        return out;
    cv::Mat grey = greyFloat(frame);
    // Anti-aliasing for the reduction to the canvas.
    if (scale > 1.2)
        cv::GaussianBlur(grey, grey, cv::Size(), 0.5 * scale);
    const cv::Matx23d canvasToImage(toImage.a, -toImage.b, toImage.tx, toImage.b, toImage.a, toImage.ty);
    cv::Mat canvas;
    cv::warpAffine(grey, canvas, canvasToImage, cv::Size(kCanvasWidth, kCanvasHeight),
                   cv::INTER_LINEAR | cv::WARP_INVERSE_MAP, cv::BORDER_REPLICATE);
    // Both parts at reduced resolution: a face placed a pixel off then moves the patch by a
    // fraction of its pixels.
    cv::Mat mouth, whole;
    cv::resize(canvas(kMouthRegion), mouth, kMouthSize, 0, 0, cv::INTER_AREA);
    cv::resize(canvas, whole, kFaceSize, 0, 0, cv::INTER_AREA);
    appendNormalisedPatch(mouth, 1.0, out, 0);
    appendNormalisedPatch(whole, kFaceWeight, out, kMouthSize.area());
    // The mouth and jaw points in the canvas, relative to the template, in eye distances.
    if (withPoints) {
        const Eigen::VectorXd inCanvas = toImage.inverse().apply(points);
        out.tail(2 * kShapePoints) = kShapeWeight / (kRightEyeX - kLeftEyeX)
            * (inCanvas - canvasShape).tail(2 * kShapePoints);
    }
    return out;
}

DiverseSelection farthestPointSample(const Eigen::MatrixXd &points, int count)
{
    DiverseSelection out;
    const Eigen::Index n = points.cols();
    if (n == 0 || count <= 0)
        return out;
    const Eigen::VectorXd mean = points.rowwise().mean();
    Eigen::Index first = 0;
    (points.colwise() - mean).colwise().squaredNorm().minCoeff(&first);
    // Squared distance of every column to its nearest pick so far.
    Eigen::VectorXd nearest = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
    Eigen::Index next = first;
    double nextDistance = std::numeric_limits<double>::infinity();
    while (int(out.picks.size()) < count) {
        out.picks.push_back(int(next));
        out.distances.push_back(std::sqrt(nextDistance));
        nearest = nearest.cwiseMin((points.colwise() - points.col(next)).colwise().squaredNorm().transpose());
        nextDistance = nearest.maxCoeff(&next);
        if (!(nextDistance > 0))
            break; // every column coincides with a pick
    }
    return out;
}

std::vector<bool> isolatedColumns(const Eigen::MatrixXd &points, const std::vector<int> &groups, int k)
{
    const Eigen::Index n = points.cols();
    std::vector<bool> out(size_t(n), false);
    if (groups.size() != size_t(n) || n < 4 || k < 1
        || std::all_of(groups.begin(), groups.end(), [&](int g) { return g == groups.front(); }))
        return out;
    std::vector<double> support(size_t(n), std::numeric_limits<double>::infinity());
    std::vector<double> others;
    for (Eigen::Index i = 0; i < n; ++i) {
        others.clear();
        for (Eigen::Index j = 0; j < n; ++j)
            if (groups[size_t(j)] != groups[size_t(i)])
                others.push_back((points.col(j) - points.col(i)).squaredNorm());
        if (int(others.size()) >= k) {
            std::nth_element(others.begin(), others.begin() + (k - 1), others.end());
            support[size_t(i)] = std::sqrt(others[size_t(k - 1)]);
        }
    }
    std::vector<double> sorted = support;
    std::sort(sorted.begin(), sorted.end());
    auto quantile = [&](double q) { return sorted[size_t(std::lround(q * double(n - 1)))]; };
    const double q1 = quantile(0.25), q3 = quantile(0.75);
    const double fence = q3 + 3.0 * (q3 - q1);
    for (Eigen::Index i = 0; i < n; ++i)
        out[size_t(i)] = support[size_t(i)] > fence;
    return out;
}

DiverseSelection selectDiverseFrames(const Eigen::MatrixXd &descriptors, int count, int dimensions,
                                     const std::vector<int> &groups, std::vector<int> *excluded)
{
    if (descriptors.cols() < 2)
        return farthestPointSample(descriptors, count);
    const Pca pca = computePca(descriptors, 1.0, dimensions);
    const Eigen::MatrixXd reduced = pca.basis.transpose() * (descriptors.colwise() - pca.mean);
    const std::vector<bool> isolated = isolatedColumns(reduced, groups);
    std::vector<int> kept;
    for (Eigen::Index i = 0; i < reduced.cols(); ++i) {
        if (!isolated[size_t(i)])
            kept.push_back(int(i));
        else if (excluded)
            excluded->push_back(int(i));
    }
    Eigen::MatrixXd keptPoints(reduced.rows(), Eigen::Index(kept.size()));
    for (size_t i = 0; i < kept.size(); ++i)
        keptPoints.col(Eigen::Index(i)) = reduced.col(kept[i]);
    DiverseSelection selection = farthestPointSample(keptPoints, count);
    for (int &pick : selection.picks)
        pick = kept[size_t(pick)];
    return selection;
}

} // namespace lipsync
