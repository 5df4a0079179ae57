#pragma once
// A smooth warp of an image that moves a few control points to new places: the thin-plate spline
// through the displacements (Bookstein 1989), d(p) = a0 + A p + sum_i w_i U(|p - q_i|),
// U(r) = r^2 log r^2, interpolating d(q_i) = q_i - s_i at the targets q_i of the sources s_i.
// The output pixel p takes the input at p - d(p) (a backward map, so every output pixel is
// filled once). Points that must stay put are control points with s_i = q_i.
//
// The spline is evaluated on a grid of `kGridStep` pixels and interpolated between (it is smooth
// at that scale), and only inside `region`: outside it the image is unchanged, and over the
// `falloff` pixels inside its border each pixel's displacement fades to zero (smoothstep), and the
// resampled pixels fade into the untouched ones over the outer part of that band, so the warped
// region joins the untouched frame without a seam.
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <limits>

namespace lipsync {

class ThinPlateWarp
{
public:
    static constexpr int kGridStep = 4;

    // Sources and targets as flat (x0, y0, x1, y1, ...) pixel coordinates of the same length.
    // `regularisation` (λ, in squared pixels) relaxes interpolation into smoothing.
    ThinPlateWarp(const Eigen::VectorXd &sources, const Eigen::VectorXd &targets, double regularisation = 0.0);

    // The displacement d(p) at a pixel (the input is read at p - d(p)).
    Eigen::Vector2d displacement(const Eigen::Vector2d &p) const;
    // The same at many pixels at once (x[k], y[k]) -> (dx[k], dy[k]).
    void displacements(const Eigen::ArrayXd &x, const Eigen::ArrayXd &y, Eigen::ArrayXd &dx,
                       Eigen::ArrayXd &dy) const;

    // Warps `image` (any type cv::remap takes) inside `region` in place; returns false (and leaves
    // it) if the region is empty, the spline could not be fitted, or the warp's Jacobian falls
    // below `minJacobian` somewhere (minJacobian() on the same grid, computed once).
    bool apply(cv::Mat &image, cv::Rect region, double falloff,
               double minJacobian = -std::numeric_limits<double>::infinity()) const;

    // The smallest Jacobian determinant of the map p -> p - d(p) over `region` (with the same
    // fade as apply()), on the grid: below 0 the warp folds the image over itself (a lip pulled
    // through the other), near 0 it crushes it. 1 for an invalid spline (apply() does nothing).
    double minJacobian(cv::Rect region, double falloff) const;

    bool valid() const { return m_valid; }

private:
    // The displacement at grid nodes every kGridStep pixels from the region's corner (unfaded).
    void gridDisplacement(cv::Rect region, cv::Mat &dx, cv::Mat &dy) const;
    static double smallestJacobian(cv::Rect region, double falloff, const cv::Mat &dx, const cv::Mat &dy);

    Eigen::MatrixX2d m_points; // the targets q_i
    Eigen::MatrixX2d m_weights; // w_i
    Eigen::Matrix<double, 3, 2> m_affine; // a0 (row 0), A (rows 1-2)
    bool m_valid = false;
};

} // namespace lipsync
