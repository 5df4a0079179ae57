#pragma once
// The reference frame of an AAM and its piecewise-affine warp (Cootes et al. 2001, §4; Matthews &
// Baker 2004, §2.1). The mean shape, scaled to pixels, is triangulated once; every pixel inside
// the triangulation gets a precomputed triangle index and barycentric coordinates, so sampling an
// image under a new shape is one affine combination of three vertices plus a bilinear lookup per
// pixel — no per-frame triangle search.
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <array>
#include <vector>

namespace lipsync {

using Triangle = std::array<int, 3>;

// Delaunay triangulation (cv::Subdiv2D) of a flat shape; triangles list vertex indices, counter
// -clockwise in image coordinates is not guaranteed. Throws lipsync::Error for a degenerate shape.
std::vector<Triangle> delaunayTriangles(const Eigen::VectorXd &shape);

class PiecewiseAffineWarp
{
public:
    PiecewiseAffineWarp() = default;
    // `referenceShape` in pixel coordinates of the reference frame (all points >= 0).
    PiecewiseAffineWarp(const Eigen::VectorXd &referenceShape, std::vector<Triangle> triangles);

    int width() const { return m_width; }
    int height() const { return m_height; }
    int pixelCount() const { return int(m_pixelX.size()); }
    const Eigen::VectorXd &referenceShape() const { return m_reference; }
    const std::vector<Triangle> &triangles() const { return m_triangles; }
    // CV_32S map of the frame: pixel index or -1 outside.
    const cv::Mat &indexMap() const { return m_indexMap; }
    int pixelX(int i) const { return m_pixelX[size_t(i)]; }
    int pixelY(int i) const { return m_pixelY[size_t(i)]; }
    int pixelTriangle(int i) const { return m_triangle[size_t(i)]; }
    const float *pixelBarycentric(int i) const { return &m_bary[size_t(3 * i)]; }

    // Samples a single-channel CV_32F image at every reference pixel warped by `shape`
    // (image coordinates), bilinear, clamped at the border.
    void sampleGrey(const cv::Mat &image, const Eigen::VectorXd &shape, float *out) const;
    // Samples a CV_8UC3 image (Catmull-Rom, CubicInterpolation.h: the colour texture is what
    // synthesis draws, and bilinear sampling blurs it): out holds 3 values per pixel (B, G, R).
    void sampleColour(const cv::Mat &image, const Eigen::VectorXd &shape, float *out) const;
    // Image position of every reference pixel under `shape` (2 per pixel).
    void pixelPositions(const Eigen::VectorXd &shape, float *out) const;

    // A reference-frame image (CV_32FC(channels)) from per-pixel values; outside pixels get `fill`.
    cv::Mat toImage(const float *values, int channels, float fill = 0.f) const;
    // Maps a point of the reference frame through the warp defined by `shape` (each triangle the
    // point lies in or near contributes; Matthews & Baker 2004 §4.1.2 average over the triangles
    // of a vertex). Used for the compositional update.
    Eigen::VectorXd warpVertices(const Eigen::VectorXd &referencePoints,
                                 const Eigen::VectorXd &shape) const;

private:
    Eigen::VectorXd m_reference;
    std::vector<Triangle> m_triangles;
    std::vector<std::vector<int>> m_vertexTriangles;
    int m_width = 0;
    int m_height = 0;
    std::vector<int> m_pixelX, m_pixelY, m_triangle;
    std::vector<float> m_bary;
    cv::Mat m_indexMap;
};

} // namespace lipsync
