#include "render/ThinPlateWarp.h"

#include <Eigen/Dense>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

namespace {

double kernel(double r2)
{
    return r2 > 1e-12 ? r2 * std::log(r2) : 0.0;
}

} // namespace

ThinPlateWarp::ThinPlateWarp(const Eigen::VectorXd &sources, const Eigen::VectorXd &targets, double regularisation)
{
    const Eigen::Index n = targets.size() / 2;
    if (n < 3 || sources.size() != targets.size())
        return;
    m_points.resize(n, 2);
    Eigen::MatrixX2d d(n, 2);
    for (Eigen::Index i = 0; i < n; ++i) {
        m_points(i, 0) = targets[2 * i];
        m_points(i, 1) = targets[2 * i + 1];
        d(i, 0) = targets[2 * i] - sources[2 * i];
        d(i, 1) = targets[2 * i + 1] - sources[2 * i + 1];
    }
    // [K + λI  P; Pᵀ 0] [w; a] = [d; 0], P = [1 x y] (Bookstein 1989), with P's columns
    // equilibrated to the kernel's magnitude — [α, α (x - cx) / L, α (y - cy) / L] — and the
    // affine part mapped back after: the same spline, but the rank test and the solve see columns
    // of one scale. (In a 1280 x 720 frame the kernel reaches 10^7 against P's 1: unequilibrated,
    // the rank test calls the system deficient and no HD frame would be warped.)
    const Eigen::RowVector2d centre = m_points.colwise().mean();
    const double extent = std::max(1.0, (m_points.rowwise() - centre).cwiseAbs().maxCoeff());
    Eigen::MatrixXd system = Eigen::MatrixXd::Zero(n + 3, n + 3);
    for (Eigen::Index i = 0; i < n; ++i)
        for (Eigen::Index j = 0; j < n; ++j)
            system(i, j) = kernel((m_points.row(i) - m_points.row(j)).squaredNorm());
    const double alpha = std::max(1.0, system.topLeftCorner(n, n).cwiseAbs().maxCoeff());
    for (Eigen::Index i = 0; i < n; ++i) {
        system(i, i) += regularisation;
        system(i, n) = system(n, i) = alpha;
        system(i, n + 1) = system(n + 1, i) = alpha * (m_points(i, 0) - centre.x()) / extent;
        system(i, n + 2) = system(n + 2, i) = alpha * (m_points(i, 1) - centre.y()) / extent;
    }
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(n + 3, 2);
    rhs.topRows(n) = d;
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(system);
    if (qr.rank() < n + 3)
        return; // coincident or collinear points
    const Eigen::MatrixXd solution = qr.solve(rhs);
    if (!solution.allFinite())
        return;
    m_weights = solution.topRows(n);
    // a0 + a1 x + a2 y from the equilibrated basis.
    const Eigen::MatrixXd scaled = solution.bottomRows(3);
    m_affine.resize(3, 2);
    m_affine.row(1) = alpha / extent * scaled.row(1);
    m_affine.row(2) = alpha / extent * scaled.row(2);
    m_affine.row(0) = alpha * scaled.row(0) - centre.x() * m_affine.row(1) - centre.y() * m_affine.row(2);
    m_valid = true;
}

Eigen::Vector2d ThinPlateWarp::displacement(const Eigen::Vector2d &p) const
{
    Eigen::ArrayXd dx, dy;
    displacements(Eigen::ArrayXd::Constant(1, p.x()), Eigen::ArrayXd::Constant(1, p.y()), dx, dy);
    return {dx[0], dy[0]};
}

namespace {

// The resampled pixels reach full weight where a pixel keeps this share of its displacement
// (apply()).
constexpr float kResampleFade = 8.0f;

// How much of the displacement a pixel keeps: 0 on the region's border and past it, rising
// (smoothstep) to 1 at `falloff` pixels inside.
float fadeAt(double x, double y, const cv::Rect &region, double falloff)
{
    const double inside = std::min({x - region.x, region.x + region.width - 1 - x, y - region.y,
                                     region.y + region.height - 1 - y});
    const double u = std::clamp(inside / std::max(1.0, falloff), 0.0, 1.0);
    return float(u * u * (3.0 - 2.0 * u));
}

} // namespace

void ThinPlateWarp::displacements(const Eigen::ArrayXd &x, const Eigen::ArrayXd &y, Eigen::ArrayXd &dx,
                                  Eigen::ArrayXd &dy) const
{
    if (!m_valid) {
        dx.setZero(x.size());
        dy.setZero(x.size());
        return;
    }
    dx = m_affine(0, 0) + m_affine(1, 0) * x + m_affine(2, 0) * y;
    dy = m_affine(0, 1) + m_affine(1, 1) * x + m_affine(2, 1) * y;
    // One control point at a time over every position, so Eigen's packet log does the kernel.
    for (Eigen::Index i = 0; i < m_points.rows(); ++i) {
        const Eigen::ArrayXd r2 = (x - m_points(i, 0)).square() + (y - m_points(i, 1)).square();
        const Eigen::ArrayXd k = (r2 > 1e-12).select(r2 * r2.max(1e-12).log(), 0.0);
        dx += m_weights(i, 0) * k;
        dy += m_weights(i, 1) * k;
    }
}

void ThinPlateWarp::gridDisplacement(cv::Rect region, cv::Mat &dx, cv::Mat &dy) const
{
    // The spline on a coarse grid over the region (its last nodes at or past the far border).
    const int gw = (region.width - 1) / kGridStep + 2;
    const int gh = (region.height - 1) / kGridStep + 2;
    Eigen::ArrayXd x(gw * gh), y(gw * gh), ex, ey;
    for (int gy = 0; gy < gh; ++gy)
        for (int gx = 0; gx < gw; ++gx) {
            x[gy * gw + gx] = double(region.x + gx * kGridStep);
            y[gy * gw + gx] = double(region.y + gy * kGridStep);
        }
    displacements(x, y, ex, ey);
    // Row-major, as the nodes were laid out: each grid wraps its array.
    cv::Mat(gh, gw, CV_64F, ex.data()).convertTo(dx, CV_32F);
    cv::Mat(gh, gw, CV_64F, ey.data()).convertTo(dy, CV_32F);
}

double ThinPlateWarp::smallestJacobian(cv::Rect region, double falloff, const cv::Mat &dx, const cv::Mat &dy)
{
    // Where the grid's nodes read the input, the fade applied.
    cv::Mat gx(dx.size(), CV_32F), gy(dx.size(), CV_32F);
    for (int y = 0; y < dx.rows; ++y)
        for (int x = 0; x < dx.cols; ++x) {
            const double px = region.x + x * kGridStep, py = region.y + y * kGridStep;
            const float keep = fadeAt(px, py, region, falloff);
            gx.at<float>(y, x) = float(px - keep * dx.at<float>(y, x));
            gy.at<float>(y, x) = float(py - keep * dy.at<float>(y, x));
        }
    double smallest = 1.0;
    const double step = kGridStep;
    for (int y = 0; y + 1 < gx.rows; ++y)
        for (int x = 0; x + 1 < gx.cols; ++x) {
            const double a = (gx.at<float>(y, x + 1) - gx.at<float>(y, x)) / step;
            const double b = (gx.at<float>(y + 1, x) - gx.at<float>(y, x)) / step;
            const double c = (gy.at<float>(y, x + 1) - gy.at<float>(y, x)) / step;
            const double d = (gy.at<float>(y + 1, x) - gy.at<float>(y, x)) / step;
            smallest = std::min(smallest, a * d - b * c);
        }
    return smallest;
}

double ThinPlateWarp::minJacobian(cv::Rect region, double falloff) const
{
    if (!m_valid || region.width < 2 || region.height < 2)
        return 1.0;
    cv::Mat dx, dy;
    gridDisplacement(region, dx, dy);
    return smallestJacobian(region, falloff, dx, dy);
}

bool ThinPlateWarp::apply(cv::Mat &image, cv::Rect region, double falloff, double minJacobian) const
{
    region &= cv::Rect(0, 0, image.cols, image.rows);
    if (!m_valid || region.width < 2 || region.height < 2)
        return false;
    cv::Mat dx, dy;
    gridDisplacement(region, dx, dy);
    if (minJacobian > -std::numeric_limits<double>::infinity()
        && smallestJacobian(region, falloff, dx, dy) < minJacobian)
        return false;
    const int gw = dx.cols, gh = dx.rows;
    // The displacement bilinear between grid nodes, faded per pixel (exactly 0 on the border).
    cv::Mat mapX(region.size(), CV_32F), mapY(region.size(), CV_32F), blend(region.size(), CV_32F);
    for (int y = 0; y < region.height; ++y) {
        const float fy = float(y) / kGridStep;
        const int y0 = std::min(int(fy), gh - 1), y1 = std::min(y0 + 1, gh - 1);
        const float ty = fy - float(y0);
        float *mx = mapX.ptr<float>(y), *my = mapY.ptr<float>(y), *mb = blend.ptr<float>(y);
        for (int x = 0; x < region.width; ++x) {
            const float fx = float(x) / kGridStep;
            const int x0 = std::min(int(fx), gw - 1), x1 = std::min(x0 + 1, gw - 1);
            const float tx = fx - float(x0);
            auto lerp = [&](const cv::Mat &g) {
                const float top = (1 - tx) * g.at<float>(y0, x0) + tx * g.at<float>(y0, x1);
                const float bottom = (1 - tx) * g.at<float>(y1, x0) + tx * g.at<float>(y1, x1);
                return (1 - ty) * top + ty * bottom;
            };
            const float keep = fadeAt(region.x + x, region.y + y, region, falloff);
            mx[x] = float(region.x + x) - keep * lerp(dx);
            my[x] = float(region.y + y) - keep * lerp(dy);
            mb[x] = std::min(1.0f, kResampleFade * keep);
        }
    }
    // Into a region-sized image first, so the input is read before any of it is written.
    // Lanczos: the moved skin keeps its fine structure (the mouth's Laplacian energy 0.975 of the
    // recording's on 200 GRID clips, 0.94 with cubic interpolation).
    cv::Mat warped;
    cv::remap(image, warped, mapX, mapY, cv::INTER_LANCZOS4, cv::BORDER_REPLICATE);
    // Where the displacement fades to a fraction of a pixel, the filter's own ringing on sharp
    // texture (a collar, stubble) would still change pixels by a few levels at the region's edge:
    // the resampled pixels fade in over the same band, reaching full weight where the
    // displacement is an eighth of its own (and so, near the edge, a fraction of a pixel: no
    // double image).
    cv::Mat target = image(region);
    cv::blendLinear(warped, target.clone(), blend, 1.0f - blend, target);
    return true;
}

} // namespace lipsync
