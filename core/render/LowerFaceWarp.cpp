#include "render/LowerFaceWarp.h"

#include "aam/LandmarkScheme.h"
#include "render/ThinPlateWarp.h"

#include <cmath>

namespace lipsync {

namespace {

constexpr int kRingPoints = 16;
// The smallest Jacobian determinant of the backward map (output pixel -> where it reads the
// frame): at or below 0 the image folds over itself; near 0 a small part of the frame is stretched
// over a large one, as lips pulled apart stretch the thin line between them, over which the
// mouth's inside is drawn (FaceRenderer::mouthInteriorAlpha). So: never a fold, stretches up to
// 50 times. [choice: with 0.25, a quarter, a closed mouth asked to open read 62 % of the opening
// asked of it (dlib, 40 development GRID clips), 68 % with 0.02.]
constexpr double kMinJacobian = 0.02;

Eigen::Vector2d point(const Eigen::VectorXd &shape, int i)
{
    return shape.segment<2>(2 * i);
}

// The eyes' midpoint of a 23-point shape.
Eigen::Vector2d eyesCentre(const Eigen::VectorXd &shape)
{
    using namespace scheme23;
    Eigen::Vector2d eyes = Eigen::Vector2d::Zero();
    for (int i : landmarkIndices(LandmarkFeature::Eyes))
        eyes += point(shape, i);
    return eyes / double(landmarkIndices(LandmarkFeature::Eyes).size());
}

} // namespace

Eigen::VectorXd LowerFaceWarp::speechShape(const Eigen::VectorXd &tracked, const Eigen::VectorXd &generated)
{
    using namespace scheme23;
    if (tracked.size() != 2 * kPointCount || generated.size() != tracked.size())
        return generated;
    constexpr int kUpperLip[] = {kUpperLipLeft, kUpperLipCentre, kUpperLipRight, kInnerLipTop};
    constexpr int kLowerLip[] = {kLowerLipRight, kLowerLipCentre, kLowerLipLeft, kInnerLipBottom};
    constexpr int kJawBeside[] = {kJawLeft + 1, kJawRight - 1}; // either side of the chin
    const Eigen::Vector2d down = (point(tracked, kChin) - eyesCentre(tracked)).normalized();
    const Eigen::Vector2d across = (point(tracked, kMouthRight) - point(tracked, kMouthLeft)).normalized();
    // Each lip's move along the face, as far as its generated inner-lip centre is from the tracked one.
    const Eigen::Vector2d upper = (point(generated, kInnerLipTop) - point(tracked, kInnerLipTop)).dot(down) * down;
    const Eigen::Vector2d lower = (point(generated, kInnerLipBottom) - point(tracked, kInnerLipBottom)).dot(down) * down;
    const double widen = 0.5 * (mouthWidth(generated) - mouthWidth(tracked));
    Eigen::VectorXd out = tracked;
    auto move = [&out, &tracked](int i, const Eigen::Vector2d &by) { out.segment<2>(2 * i) = point(tracked, i) + by; };
    for (int i : kUpperLip)
        move(i, upper);
    for (int i : kLowerLip)
        move(i, lower);
    move(kChin, lower);
    for (int i : kJawBeside)
        move(i, 0.5 * lower);
    move(kMouthLeft, 0.5 * (upper + lower) - widen * across);
    move(kMouthRight, 0.5 * (upper + lower) + widen * across);
    return out;
}

void LowerFaceWarp::controlPoints(const Eigen::VectorXd &tracked, const Eigen::VectorXd &generated,
                                  Eigen::VectorXd &sources, Eigen::VectorXd &targets, cv::Rect2d &region)
{
    using namespace scheme23;
    std::vector<Eigen::Vector2d> from, to;
    for (int i = 0; i < kPointCount; ++i) {
        // The mouth and the lower jaw move; the eyes and the jaw's upper ends, level with the
        // nose, where speech hardly moves the face, stay.
        const bool moves = landmarkDefinitions()[size_t(i)].feature == LandmarkFeature::Mouth
                           || (i > kJawLeft && i < kJawRight);
        from.push_back(point(tracked, i));
        to.push_back(moves ? point(generated, i) : point(tracked, i));
    }
    // The face's frame from the tracked shape: the eyes' midpoint, the axis down to the chin and
    // the eyes' span across.
    const Eigen::Vector2d eyes = eyesCentre(tracked);
    const Eigen::Vector2d down = point(tracked, kChin) - eyes;
    const double length = std::max(1.0, down.norm());
    const Eigen::Vector2d axis = down / length, across(-axis.y(), axis.x());
    const double span = std::max(1.0, (point(tracked, kRightEyeOuter) - point(tracked, kLeftEyeOuter)).norm());
    // Lips that a closure or a model pulled through each other meet instead (half a pixel apart:
    // the spline needs distinct points).
    if ((to[size_t(kInnerLipBottom)] - to[size_t(kInnerLipTop)]).dot(axis) < 0.5) {
        const Eigen::Vector2d mid = 0.5 * (to[size_t(kInnerLipBottom)] + to[size_t(kInnerLipTop)]);
        to[size_t(kInnerLipTop)] = mid - 0.25 * axis;
        to[size_t(kInnerLipBottom)] = mid + 0.25 * axis;
    }
    // The brows and forehead held too: every eye point's copy a quarter of the face length up.
    for (int i : landmarkIndices(LandmarkFeature::Eyes)) {
        from.push_back(point(tracked, i) - 0.25 * down);
        to.push_back(from.back());
    }
    // Anchors on an ellipse from just above the eyes to 0.4 face lengths below the chin and 1.4
    // times the eyes' span either side (beyond the cheeks): fixed, so the warp dies out before it
    // and moves the neck with the chin (and the collar below hardly at all).
    const Eigen::Vector2d centre = eyes + 0.65 * down;
    const double along = 0.75 * length, side = 1.4 * span;
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (int k = 0; k < kRingPoints; ++k) {
        const double a = 2.0 * M_PI * k / kRingPoints;
        const Eigen::Vector2d p = centre + std::cos(a) * side * across + std::sin(a) * along * axis;
        from.push_back(p);
        to.push_back(p);
        x0 = std::min(x0, p.x());
        y0 = std::min(y0, p.y());
        x1 = std::max(x1, p.x());
        y1 = std::max(y1, p.y());
    }
    sources.resize(Eigen::Index(2 * from.size()));
    targets.resize(Eigen::Index(2 * to.size()));
    for (size_t i = 0; i < from.size(); ++i) {
        sources.segment<2>(Eigen::Index(2 * i)) = from[i];
        targets.segment<2>(Eigen::Index(2 * i)) = to[i];
    }
    region = cv::Rect2d(x0, y0, x1 - x0, y1 - y0);
}

cv::Rect LowerFaceWarp::apply(cv::Mat &frame, const Eigen::VectorXd &tracked, const Eigen::VectorXd &generated)
{
    if (tracked.size() != 2 * scheme23::kPointCount || generated.size() != tracked.size()
        || !tracked.allFinite() || !generated.allFinite())
        return {};
    Eigen::VectorXd sources, targets;
    cv::Rect2d ring;
    controlPoints(tracked, generated, sources, targets, ring);
    if ((sources - targets).cwiseAbs().maxCoeff() < 0.05)
        return {}; // the recorded shape itself: nothing to move
    // The region: the ring's box with a margin; the displacement fades over that margin.
    const double margin = 0.08 * std::max(ring.width, ring.height);
    const cv::Rect region = cv::Rect(cv::Point(int(std::floor(ring.x - margin)), int(std::floor(ring.y - margin))),
                                     cv::Point(int(std::ceil(ring.x + ring.width + margin)),
                                               int(std::ceil(ring.y + ring.height + margin))))
                            & cv::Rect(0, 0, frame.cols, frame.rows);
    // A warp that would fold the face over itself (lips pulled through each other when a closed
    // mouth is asked of an open one, a loop at a corner) is smoothed, then moved less: never a fold.
    const Eigen::VectorXd moves = targets - sources;
    for (double share : {1.0, 0.75, 0.5, 0.25}) {
        for (double smoothing : {0.0, 1e3, 1e4, 1e5}) {
            const ThinPlateWarp warp(sources, sources + share * moves, smoothing);
            if (warp.apply(frame, region, margin, kMinJacobian))
                return region;
        }
    }
    return {};
}

std::vector<cv::Point2f> LowerFaceWarp::mouthInterior(const Eigen::VectorXd &shape)
{
    using namespace scheme23;
    const Eigen::Vector2d left = point(shape, kMouthLeft), right = point(shape, kMouthRight);
    const Eigen::Vector2d top = point(shape, kInnerLipTop), bottom = point(shape, kInnerLipBottom);
    // The quadratic Bézier through the corners whose midpoint is the inner-lip point: control
    // point 2 m - (l + r) / 2.
    auto curve = [&](const Eigen::Vector2d &mid, bool forward, std::vector<cv::Point2f> &out) {
        const Eigen::Vector2d control = 2.0 * mid - 0.5 * (left + right);
        constexpr int kSteps = 12;
        for (int s = 0; s <= kSteps; ++s) {
            const double t = forward ? double(s) / kSteps : 1.0 - double(s) / kSteps;
            const Eigen::Vector2d p = (1 - t) * (1 - t) * left + 2 * (1 - t) * t * control + t * t * right;
            out.emplace_back(float(p.x()), float(p.y()));
        }
    };
    std::vector<cv::Point2f> lens;
    curve(top, true, lens);
    curve(bottom, false, lens);
    return lens;
}

double LowerFaceWarp::opening(const Eigen::VectorXd &shape)
{
    return (point(shape, scheme23::kInnerLipBottom) - point(shape, scheme23::kInnerLipTop)).norm();
}

std::vector<cv::Point2f> LowerFaceWarp::outerLips(const Eigen::VectorXd &shape, double margin)
{
    using namespace scheme23;
    // Around the mouth: the left corner, the upper lip left to right, the right corner, the lower
    // lip right to left (the scheme's order, aam/LandmarkScheme.cpp).
    constexpr int kOutline[] = {kMouthLeft,  kUpperLipLeft,   kUpperLipCentre, kUpperLipRight,
                                kMouthRight, kLowerLipRight, kLowerLipCentre, kLowerLipLeft};
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int i : kOutline)
        centre += point(shape, i);
    centre /= double(std::size(kOutline));
    std::vector<cv::Point2f> out;
    for (int i : kOutline) {
        const Eigen::Vector2d p = point(shape, i);
        const Eigen::Vector2d away = (p - centre).normalized();
        const Eigen::Vector2d q = p + margin * away;
        out.emplace_back(float(q.x()), float(q.y()));
    }
    return out;
}

double LowerFaceWarp::mouthWidth(const Eigen::VectorXd &shape)
{
    return (point(shape, scheme23::kMouthRight) - point(shape, scheme23::kMouthLeft)).norm();
}

} // namespace lipsync

