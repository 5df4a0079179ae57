#include "aam/PiecewiseAffineWarp.h"

#include "aam/CubicInterpolation.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace lipsync {

std::vector<Triangle> delaunayTriangles(const Eigen::VectorXd &shape)
{
    const int n = int(shape.size() / 2);
    if (n < 3)
        throw Error("a triangulation needs at least 3 points");
    double minX = shape[0], maxX = shape[0], minY = shape[1], maxY = shape[1];
    for (int i = 0; i < n; ++i) {
        minX = std::min(minX, shape[2 * i]);
        maxX = std::max(maxX, shape[2 * i]);
        minY = std::min(minY, shape[2 * i + 1]);
        maxY = std::max(maxY, shape[2 * i + 1]);
    }
    if (maxX - minX <= 1e-9 || maxY - minY <= 1e-9)
        throw Error("cannot triangulate a degenerate shape (all points on a line)");
    const double margin = std::max(maxX - minX, maxY - minY);
    cv::Subdiv2D subdiv(cv::Rect(int(std::floor(minX - margin)), int(std::floor(minY - margin)),
                                 int(std::ceil(maxX - minX + 2 * margin)),
                                 int(std::ceil(maxY - minY + 2 * margin))));
    for (int i = 0; i < n; ++i)
        subdiv.insert(cv::Point2f(float(shape[2 * i]), float(shape[2 * i + 1])));
    std::vector<cv::Vec6f> list;
    subdiv.getTriangleList(list);
    auto indexOf = [&](float x, float y) {
        for (int i = 0; i < n; ++i)
            if (std::abs(shape[2 * i] - x) < 1e-3 && std::abs(shape[2 * i + 1] - y) < 1e-3)
                return i;
        return -1;
    };
    std::vector<Triangle> triangles;
    std::set<std::array<int, 3>> seen;
    for (const auto &t : list) {
        Triangle tri{indexOf(t[0], t[1]), indexOf(t[2], t[3]), indexOf(t[4], t[5])};
        if (tri[0] < 0 || tri[1] < 0 || tri[2] < 0)
            continue; // touches Subdiv2D's virtual outer vertices
        std::array<int, 3> key = tri;
        std::sort(key.begin(), key.end());
        if (!seen.insert(key).second)
            continue;
        // Drop slivers (collinear hull points).
        const Eigen::Vector2d a = shape.segment<2>(2 * tri[0]), b = shape.segment<2>(2 * tri[1]),
                              c = shape.segment<2>(2 * tri[2]);
        const double area = std::abs((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
        if (area < 1e-6 * margin * margin)
            continue;
        triangles.push_back(tri);
    }
    if (triangles.empty())
        throw Error("the triangulation of the shape is empty");
    return triangles;
}

PiecewiseAffineWarp::PiecewiseAffineWarp(const Eigen::VectorXd &referenceShape,
                                         std::vector<Triangle> triangles)
    : m_reference(referenceShape), m_triangles(std::move(triangles))
{
    const int n = int(referenceShape.size() / 2);
    m_vertexTriangles.assign(size_t(n), {});
    for (int t = 0; t < int(m_triangles.size()); ++t)
        for (int v : m_triangles[size_t(t)])
            m_vertexTriangles[size_t(v)].push_back(t);
    double maxX = 0, maxY = 0;
    for (int i = 0; i < n; ++i) {
        maxX = std::max(maxX, referenceShape[2 * i]);
        maxY = std::max(maxY, referenceShape[2 * i + 1]);
    }
    m_width = int(std::ceil(maxX)) + 2;
    m_height = int(std::ceil(maxY)) + 2;
    // Each pixel belongs to the first triangle (in list order) whose barycentric coordinates are
    // all >= -1e-9. Testing every triangle at every pixel cost width x height x triangles (0.7 s
    // for the demo model under ASan, 80% of a load); instead each triangle visits, row by row, only
    // the span of pixels its edges cross, widened by one pixel (the tolerance reaches less than
    // 1e-5 pixel past an edge). Same answer, same pixel order, and a cost that grows with the
    // triangles' pixels, not with the frame (which a damaged model file can make 1024 x 1024).
    // Per triangle: vertex a, edges b - a and c - a, and their determinant (0: degenerate, skipped).
    struct Edges
    {
        double ax, ay, bx, by, cx, cy, det;
    };
    std::vector<Edges> edges;
    edges.reserve(m_triangles.size());
    for (const auto &tri : m_triangles) {
        const double ax = referenceShape[2 * tri[0]], ay = referenceShape[2 * tri[0] + 1];
        const double bx = referenceShape[2 * tri[1]] - ax, by = referenceShape[2 * tri[1] + 1] - ay;
        const double cx = referenceShape[2 * tri[2]] - ax, cy = referenceShape[2 * tri[2] + 1] - ay;
        const double det = bx * cy - by * cx;
        edges.push_back({ax, ay, bx, by, cx, cy, std::abs(det) < 1e-12 ? 0.0 : det});
    }
    const auto barycentric = [&](int t, int x, int y, double &alpha, double &beta, double &gamma) {
        const Edges &e = edges[size_t(t)];
        if (e.det == 0.0)
            return false;
        const double px = x - e.ax, py = y - e.ay;
        beta = (px * e.cy - py * e.cx) / e.det;
        gamma = (e.bx * py - e.by * px) / e.det;
        alpha = 1.0 - beta - gamma;
        const double eps = -1e-9;
        return alpha >= eps && beta >= eps && gamma >= eps;
    };
    // Pass 1: the triangle of every pixel (kept in the index map for now).
    m_indexMap = cv::Mat(m_height, m_width, CV_32S, cv::Scalar(-1));
    for (int t = 0; t < int(m_triangles.size()); ++t) {
        if (edges[size_t(t)].det == 0.0)
            continue;
        double vx[3], vy[3]; // plain doubles: this loop runs per row of every triangle
        for (int k = 0; k < 3; ++k) {
            vx[k] = referenceShape[2 * m_triangles[size_t(t)][size_t(k)]];
            vy[k] = referenceShape[2 * m_triangles[size_t(t)][size_t(k)] + 1];
        }
        const double yMin = std::min({vy[0], vy[1], vy[2]});
        const double yMax = std::max({vy[0], vy[1], vy[2]});
        const int yFrom = std::max(0, int(std::floor(yMin)) - 1);
        const int yTo = std::min(m_height - 1, int(std::ceil(yMax)) + 1);
        for (int y = yFrom; y <= yTo; ++y) {
            // The triangle's x-extent within the band y +- 1e-5 (wider than the tolerance reaches,
            // so a nearly horizontal edge just above or below the row is not missed): on each edge,
            // the x at both ends of its part inside the band.
            const double lo = y - 1e-5, hi = y + 1e-5;
            double xLeft = 1e300, xRight = -1e300;
            for (int k = 0; k < 3; ++k) {
                const int l = (k + 1) % 3;
                const double from = std::max(lo, std::min(vy[k], vy[l])), to = std::min(hi, std::max(vy[k], vy[l]));
                if (from > to)
                    continue;
                if (vy[k] == vy[l]) {
                    xLeft = std::min({xLeft, vx[k], vx[l]});
                    xRight = std::max({xRight, vx[k], vx[l]});
                    continue;
                }
                const double slope = (vx[l] - vx[k]) / (vy[l] - vy[k]);
                const double x0 = vx[k] + (from - vy[k]) * slope, x1 = vx[k] + (to - vy[k]) * slope;
                xLeft = std::min({xLeft, x0, x1});
                xRight = std::max({xRight, x0, x1});
            }
            if (xLeft > xRight)
                continue;
            const int xFrom = std::max(0, int(std::floor(xLeft)) - 1);
            const int xTo = std::min(m_width - 1, int(std::ceil(xRight)) + 1);
            int *owner = m_indexMap.ptr<int>(y);
            double alpha, beta, gamma;
            for (int x = xFrom; x <= xTo; ++x)
                if (owner[x] < 0 && barycentric(t, x, y, alpha, beta, gamma))
                    owner[x] = t;
        }
    }
    // Pass 2: pixel indices in raster order, as the fitter and the texture vectors expect.
    for (int y = 0; y < m_height; ++y) {
        int *index = m_indexMap.ptr<int>(y);
        for (int x = 0; x < m_width; ++x) {
            const int t = index[x];
            if (t < 0)
                continue;
            double alpha = 0, beta = 0, gamma = 0;
            barycentric(t, x, y, alpha, beta, gamma);
            index[x] = int(m_pixelX.size());
            m_pixelX.push_back(x);
            m_pixelY.push_back(y);
            m_triangle.push_back(t);
            m_bary.push_back(float(alpha));
            m_bary.push_back(float(beta));
            m_bary.push_back(float(gamma));
        }
    }
}

void PiecewiseAffineWarp::pixelPositions(const Eigen::VectorXd &shape, float *out) const
{
    const int count = pixelCount();
    for (int i = 0; i < count; ++i) {
        const auto &tri = m_triangles[size_t(m_triangle[size_t(i)])];
        const float *w = &m_bary[size_t(3 * i)];
        out[2 * i] = float(w[0] * shape[2 * tri[0]] + w[1] * shape[2 * tri[1]]
                           + w[2] * shape[2 * tri[2]]);
        out[2 * i + 1] = float(w[0] * shape[2 * tri[0] + 1] + w[1] * shape[2 * tri[1] + 1]
                               + w[2] * shape[2 * tri[2] + 1]);
    }
}

namespace {

// Per-triangle affine map reference pixel -> image, so each pixel costs 4 multiply-adds.
struct Affine
{
    float m00, m01, m02, m10, m11, m12;
};

std::vector<Affine> triangleAffines(const Eigen::VectorXd &ref, const std::vector<Triangle> &tris,
                                    const Eigen::VectorXd &shape)
{
    std::vector<Affine> out(tris.size());
    for (size_t t = 0; t < tris.size(); ++t) {
        const auto &tri = tris[t];
        cv::Point2f src[3], dst[3];
        for (int k = 0; k < 3; ++k) {
            src[k] = cv::Point2f(float(ref[2 * tri[size_t(k)]]), float(ref[2 * tri[size_t(k)] + 1]));
            dst[k] = cv::Point2f(float(shape[2 * tri[size_t(k)]]),
                                 float(shape[2 * tri[size_t(k)] + 1]));
        }
        // Solve in double to stay accurate for thin triangles.
        const double x0 = src[0].x, y0 = src[0].y;
        const double ux = src[1].x - x0, uy = src[1].y - y0, vx = src[2].x - x0, vy = src[2].y - y0;
        const double det = ux * vy - uy * vx;
        if (std::abs(det) < 1e-12) {
            out[t] = {0, 0, dst[0].x, 0, 0, dst[0].y};
            continue;
        }
        // bary (beta, gamma) = inv([u v]) (p - p0); image = d0 + beta (d1-d0) + gamma (d2-d0)
        const double i00 = vy / det, i01 = -vx / det, i10 = -uy / det, i11 = ux / det;
        const double dx1 = dst[1].x - dst[0].x, dy1 = dst[1].y - dst[0].y;
        const double dx2 = dst[2].x - dst[0].x, dy2 = dst[2].y - dst[0].y;
        const double a00 = dx1 * i00 + dx2 * i10, a01 = dx1 * i01 + dx2 * i11;
        const double a10 = dy1 * i00 + dy2 * i10, a11 = dy1 * i01 + dy2 * i11;
        out[t] = {float(a00), float(a01), float(dst[0].x - a00 * x0 - a01 * y0), float(a10),
                  float(a11), float(dst[0].y - a10 * x0 - a11 * y0)};
    }
    return out;
}

} // namespace

void PiecewiseAffineWarp::sampleGrey(const cv::Mat &image, const Eigen::VectorXd &shape,
                                     float *out) const
{
    CV_Assert(image.type() == CV_32F);
    const std::vector<Affine> aff = triangleAffines(m_reference, m_triangles, shape);
    const int w = image.cols, h = image.rows;
    const float maxX = float(w - 1) - 1e-3f, maxY = float(h - 1) - 1e-3f;
    const size_t step = image.step1();
    const float *data = image.ptr<float>();
    const int count = pixelCount();
    for (int i = 0; i < count; ++i) {
        const Affine &A = aff[size_t(m_triangle[size_t(i)])];
        const float px = float(m_pixelX[size_t(i)]), py = float(m_pixelY[size_t(i)]);
        float x = A.m00 * px + A.m01 * py + A.m02;
        float y = A.m10 * px + A.m11 * py + A.m12;
        x = std::clamp(x, 0.f, maxX);
        y = std::clamp(y, 0.f, maxY);
        const int x0 = int(x), y0 = int(y);
        const float fx = x - float(x0), fy = y - float(y0);
        const float *r0 = data + size_t(y0) * step + x0;
        const float *r1 = r0 + step;
        out[i] = (1 - fy) * ((1 - fx) * r0[0] + fx * r0[1]) + fy * ((1 - fx) * r1[0] + fx * r1[1]);
    }
}

void PiecewiseAffineWarp::sampleColour(const cv::Mat &image, const Eigen::VectorXd &shape,
                                       float *out) const
{
    CV_Assert(image.type() == CV_8UC3);
    const std::vector<Affine> aff = triangleAffines(m_reference, m_triangles, shape);
    const int w = image.cols, h = image.rows;
    const float maxX = float(w - 1) - 1e-3f, maxY = float(h - 1) - 1e-3f;
    const int count = pixelCount();
    for (int i = 0; i < count; ++i) {
        const Affine &A = aff[size_t(m_triangle[size_t(i)])];
        const float px = float(m_pixelX[size_t(i)]), py = float(m_pixelY[size_t(i)]);
        float x = std::clamp(A.m00 * px + A.m01 * py + A.m02, 0.f, maxX);
        float y = std::clamp(A.m10 * px + A.m11 * py + A.m12, 0.f, maxY);
        const int x0 = int(x), y0 = int(y);
        sampleCatmullRom<3>(image.data, w, h, int(image.step), x0, y0, x - float(x0), y - float(y0), out + 3 * i);
    }
}

cv::Mat PiecewiseAffineWarp::toImage(const float *values, int channels, float fill) const
{
    cv::Mat out(m_height, m_width, CV_32FC(channels), cv::Scalar::all(fill));
    for (int i = 0; i < pixelCount(); ++i) {
        float *p = out.ptr<float>(m_pixelY[size_t(i)]) + channels * m_pixelX[size_t(i)];
        for (int c = 0; c < channels; ++c)
            p[c] = values[channels * i + c];
    }
    return out;
}

Eigen::VectorXd PiecewiseAffineWarp::warpVertices(const Eigen::VectorXd &referencePoints,
                                                  const Eigen::VectorXd &shape) const
{
    const int n = int(referencePoints.size() / 2);
    Eigen::VectorXd out(referencePoints.size());
    for (int v = 0; v < n; ++v) {
        const Eigen::Vector2d p = referencePoints.segment<2>(2 * v);
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        int used = 0;
        for (int t : m_vertexTriangles[size_t(v)]) {
            const auto &tri = m_triangles[size_t(t)];
            const Eigen::Vector2d a = m_reference.segment<2>(2 * tri[0]);
            const Eigen::Vector2d b = m_reference.segment<2>(2 * tri[1]);
            const Eigen::Vector2d c = m_reference.segment<2>(2 * tri[2]);
            const double det = (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
            if (std::abs(det) < 1e-12)
                continue;
            const double beta = ((p - a).x() * (c - a).y() - (p - a).y() * (c - a).x()) / det;
            const double gamma = ((b - a).x() * (p - a).y() - (b - a).y() * (p - a).x()) / det;
            const double alpha = 1.0 - beta - gamma;
            sum += alpha * shape.segment<2>(2 * tri[0]) + beta * shape.segment<2>(2 * tri[1])
                   + gamma * shape.segment<2>(2 * tri[2]);
            ++used;
        }
        out.segment<2>(2 * v) = used ? Eigen::Vector2d(sum / used) : Eigen::Vector2d(shape.segment<2>(2 * v));
    }
    return out;
}

} // namespace lipsync
