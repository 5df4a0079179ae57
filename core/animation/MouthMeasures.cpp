#include "animation/MouthMeasures.h"

#include "aam/LandmarkScheme.h"
#include "render/LowerFaceWarp.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <cmath>

namespace lipsync {

namespace {

using namespace scheme23;
constexpr int kEyePoints = 8;

Eigen::Vector2d point(const Eigen::VectorXd &shape, int i)
{
    return {shape[2 * i], shape[2 * i + 1]};
}

} // namespace

std::array<double, MouthMeasures::kCount> MouthMeasures::values() const
{
    return {opening, width, leftCorner, rightCorner, rounding, jaw, upperLeft, upperRight, lowerLeft, lowerRight,
            teeth};
}

MouthMeasures MouthMeasures::fromValues(const std::array<double, kCount> &v)
{
    MouthMeasures m;
    m.opening = v[0], m.width = v[1], m.leftCorner = v[2], m.rightCorner = v[3], m.rounding = v[4], m.jaw = v[5];
    m.upperLeft = v[6], m.upperRight = v[7], m.lowerLeft = v[8], m.lowerRight = v[9], m.teeth = v[10];
    return m;
}

MouthMeasurer::MouthMeasurer(const AamModel &aam) : m_synth(aam)
{
    if (aam.pointCount() != scheme23::kPointCount)
        throw Error("the AAM has " + std::to_string(aam.pointCount()) + " points, not the 23 of the scheme");
    // The inner mouth in the reference frame: the corners and the inner-lip centres of the mean
    // shape; whatever the frame showed between the lips is warped into it.
    const PiecewiseAffineWarp &warp = aam.warp(0);
    const Eigen::VectorXd &ref = warp.referenceShape();
    std::vector<cv::Point2f> outline;
    for (int i : {kMouthLeft, kInnerLipTop, kMouthRight, kInnerLipBottom})
        outline.emplace_back(float(ref[2 * i]), float(ref[2 * i + 1]));
    std::vector<int> mouth;
    for (int p = 0; p < warp.pixelCount(); ++p)
        if (cv::pointPolygonTest(outline, cv::Point2f(float(warp.pixelX(p)), float(warp.pixelY(p))), false) > 0)
            mouth.push_back(p);
    const int nc = aam.combinedModes();
    m_teethGain = Eigen::RowVectorXd::Zero(nc);
    if (mouth.empty())
        return;
    auto contrast = [&mouth](const Eigen::VectorXf &g) {
        double inside = 0;
        for (int p : mouth)
            inside += double(g[3 * p]) + g[3 * p + 1] + g[3 * p + 2];
        return inside / (3.0 * double(mouth.size())) - double(g.sum()) / double(g.size());
    };
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(nc);
    m_teethBase = contrast(m_synth.texture(zero));
    for (int k = 0; k < nc; ++k)
        m_teethGain[k] = contrast(m_synth.texture(Eigen::VectorXd::Unit(nc, k))) - m_teethBase;
}

MouthMeasures MouthMeasurer::measure(const Eigen::VectorXd &combined, Eigen::VectorXd *shape) const
{
    const Eigen::VectorXd s = m_synth.shape(combined);
    if (shape)
        *shape = s;
    Eigen::Vector2d eyes = Eigen::Vector2d::Zero();
    for (int i = 0; i < kEyePoints; ++i)
        eyes += point(s, i);
    eyes /= kEyePoints;
    const Eigen::Vector2d left = point(s, kMouthLeft), right = point(s, kMouthRight);
    const Eigen::Vector2d corners = 0.5 * (left + right);
    MouthMeasures m;
    m.opening = LowerFaceWarp::opening(s);
    m.width = (right - left).norm();
    m.leftCorner = eyes.x() - left.x();
    m.rightCorner = right.x() - eyes.x();
    m.rounding = (point(s, kLowerLipCentre) - point(s, kUpperLipCentre)).norm() / std::max(m.width, 1e-9);
    m.jaw = point(s, kChin).y() - eyes.y();
    // Image y grows downwards: above the corners' line is a smaller y.
    m.upperLeft = corners.y() - s[2 * kUpperLipLeft + 1];
    m.upperRight = corners.y() - s[2 * kUpperLipRight + 1];
    m.lowerLeft = s[2 * kLowerLipLeft + 1] - corners.y();
    m.lowerRight = s[2 * kLowerLipRight + 1] - corners.y();
    m.teeth = m_teethBase + m_teethGain.dot(combined);
    return m;
}

} // namespace lipsync
