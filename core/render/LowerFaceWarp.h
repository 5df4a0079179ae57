#pragma once
// The recording's own face moved to a generated shape (Video Rewrite's and Ezzat et al.'s way to
// photorealism: keep the person's pixels — skin, moles, stubble, lighting — and move them): a
// thin-plate spline (ThinPlateWarp) takes the mouth and lower jaw points of the 23-point shape tracked
// in the frame to where the generated shape puts them (FaceRenderer passes speechShape(): the
// generated lips' opening and width on the tracked shape). The eyes and the jaw line's upper ends
// (level with the nose) are held where they are, and so
// is a ring of anchors around the lower face that reaches down the neck, so the chin and the neck
// below it move together (no second jaw line) and the warp fades out before the ring: there is no
// edge to see, at any pose, since nothing is pasted. What the recording cannot supply — the
// inside of a mouth opened wider than it was recorded — is drawn by the caller (mouthInterior).
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

struct LowerFaceWarp
{
    // Warps `frame` (CV_8UC3) in place from `tracked` to `generated` (23-point shapes in its
    // pixels). Returns the region changed (empty if nothing was).
    static cv::Rect apply(cv::Mat &frame, const Eigen::VectorXd &tracked, const Eigen::VectorXd &generated);

    // The shape the recording's face is moved to for a generated shape: `tracked` with only what
    // speech changes taken from `generated`. Each lip moves along the face's axis (eyes to chin) as
    // far as its generated inner-lip centre is from the tracked one, the chin with the lower lip and
    // the jaw points beside it half as far; the corners move midway between the lips and apart by
    // the generated mouth's width. The rest of a generated shape (the lips' outline, their place
    // sideways, the jaw's set) is the model's average where the recording shows the person's own,
    // and moving the recording's face by it is what a viewer reads as made [docs/performance.md,
    // held-out GRID s1: the machine observer tells 0.620 of rendered frames with this shape, 0.684
    // with the generated one; within speech 0.838 against 0.823].
    static Eigen::VectorXd speechShape(const Eigen::VectorXd &tracked, const Eigen::VectorXd &generated);

    // The control points' sources and targets apply() uses (the anchors included).
    static void controlPoints(const Eigen::VectorXd &tracked, const Eigen::VectorXd &generated,
                              Eigen::VectorXd &sources, Eigen::VectorXd &targets, cv::Rect2d &region);

    // The inside of the lips of `shape` in frame pixels: the lens between the mouth corners bounded
    // by the quadratic curves through the inner-lip top and bottom points.
    static std::vector<cv::Point2f> mouthInterior(const Eigen::VectorXd &shape);
    // Inner-lip opening of `shape` (pixels between the inner-lip centres).
    static double opening(const Eigen::VectorXd &shape);
    // The outer outline of the lips of `shape` (corners and outer-lip points), pushed out by
    // `margin` pixels from the mouth's centre.
    static std::vector<cv::Point2f> outerLips(const Eigen::VectorXd &shape, double margin);
    // The distance between the mouth corners of `shape`.
    static double mouthWidth(const Eigen::VectorXd &shape);
};

} // namespace lipsync
