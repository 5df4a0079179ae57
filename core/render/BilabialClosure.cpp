#include "render/BilabialClosure.h"

#include "aam/LandmarkScheme.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

std::optional<BilabialClosure> BilabialClosure::forAam(const AamModel &aam)
{
    try {
        return BilabialClosure(aam);
    } catch (const Error &) {
        return std::nullopt;
    }
}

BilabialClosure::BilabialClosure(const AamModel &aam)
{
    const int nc = aam.combinedModes();
    if (aam.pointCount() != scheme23::kPointCount || nc == 0)
        throw Error("lip closure needs an AAM of the 23-point scheme with a combined model");
    const Eigen::VectorXd &mean = aam.meanShape;
    const Eigen::Vector2d eyes = mean.segment<2>(2 * scheme23::kRightEyeOuter)
                                 - mean.segment<2>(2 * scheme23::kLeftEyeOuter);
    const double interocular = eyes.norm();
    if (!(interocular > 0))
        throw Error("lip closure: the AAM's mean shape has no eye-corner distance");
    // The face's vertical: perpendicular to the eye line, pointing down the image.
    const Eigen::Vector2d down(-eyes.y() / interocular, eyes.x() / interocular);
    auto openingOfShape = [&](const Eigen::VectorXd &shape) {
        return (shape.segment<2>(2 * scheme23::kInnerLipBottom) - shape.segment<2>(2 * scheme23::kInnerLipTop)).dot(down) / interocular;
    };
    // o(c) is linear: its value at 0 and its change along each combined mode.
    auto shapeOf = [&](const Eigen::VectorXd &c) {
        Eigen::VectorXd bs, bg;
        aam.partsFromCombined(c, bs, bg);
        return Eigen::VectorXd(mean + aam.shapeBasis * bs);
    };
    const Eigen::VectorXd zero = Eigen::VectorXd::Zero(nc);
    m_offset = openingOfShape(shapeOf(zero));
    m_gradient.resize(nc);
    for (int i = 0; i < nc; ++i)
        m_gradient[i] = openingOfShape(shapeOf(Eigen::VectorXd::Unit(nc, i))) - m_offset;
    const Eigen::VectorXd lambdaA = aam.combinedVariances.cwiseMax(0.0).cwiseProduct(m_gradient);
    const double aLambdaA = m_gradient.dot(lambdaA);
    if (!(aLambdaA > 0))
        throw Error("lip closure: the AAM's combined modes do not move the inner lips");
    m_step = lambdaA / aLambdaA;
}

double BilabialClosure::opening(const Eigen::VectorXd &c) const
{
    return m_offset + m_gradient.dot(c);
}

std::vector<double> BilabialClosure::weights(const Tier &phones, const FrameClock &frames)
{
    const int count = frames.count();
    std::vector<double> w(size_t(count), 0.0);
    if (!(frames.rate() > 0) || count == 0)
        return w;
    for (const Interval &i : phones.intervals) {
        if (!PhoneSet::isBilabial(i.label) || !(i.end > i.start))
            continue;
        if (i.end <= frames.startTime() || i.start >= frames.endTime())
            continue;
        const int first = frames.frameAt(i.start);
        const int last = frames.frameAt(std::nextafter(i.end, -INFINITY));
        int most = -1;
        double mostShare = 0.0;
        for (int t = first; t <= last; ++t) {
            const double length = frames.endTime(t) - frames.time(t);
            const double inside = std::min(i.end, frames.endTime(t)) - std::max(i.start, frames.time(t));
            const double share = length > 0 ? std::clamp(inside / length, 0.0, 1.0) : 0.0;
            w[size_t(t)] = std::max(w[size_t(t)], share);
            if (share > mostShare) {
                mostShare = share;
                most = t;
            }
        }
        // A phone shorter than a frame still closes the lips once.
        if (most >= 0)
            w[size_t(most)] = 1.0;
    }
    return w;
}

std::vector<double> BilabialClosure::weights(const std::vector<int> &labels)
{
    std::vector<double> w(labels.size(), 0.0);
    for (size_t t = 0; t < labels.size(); ++t)
        if (PhoneSet::isBilabial(labels[t]))
            w[t] = 1.0;
    return w;
}

Eigen::MatrixXd BilabialClosure::apply(const Eigen::MatrixXd &trajectory, const std::vector<double> &weights) const
{
    Eigen::MatrixXd out = trajectory;
    if (trajectory.cols() != m_gradient.size())
        throw Error("lip closure: the trajectory has " + std::to_string(trajectory.cols())
                    + " parameters, the AAM's combined model " + std::to_string(m_gradient.size()));
    const Eigen::Index rows = std::min<Eigen::Index>(out.rows(), Eigen::Index(weights.size()));
    for (Eigen::Index t = 0; t < rows; ++t) {
        const double w = std::clamp(weights[size_t(t)], 0.0, 1.0);
        if (w <= 0.0 || !out.row(t).allFinite())
            continue;
        const double o = opening(out.row(t).transpose());
        if (o > 0.0)
            out.row(t) -= (w * o) * m_step.transpose();
    }
    return out;
}

Eigen::MatrixXd BilabialClosure::closeOnPhones(const AamModel &aam, const Eigen::MatrixXd &trajectory,
                                               const Tier &phones, const FrameClock &frames)
{
    const std::optional<BilabialClosure> closure = forAam(aam);
    return closure ? closure->apply(trajectory, weights(phones, frames)) : trajectory;
}

} // namespace lipsync
