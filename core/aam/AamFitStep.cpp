#include "aam/AamFitStep.h"

#include <Eigen/Cholesky>

namespace lipsync {

Eigen::VectorXd ProjectOutStep::step(const AamFitLevel &level, const PiecewiseAffineWarp &, const Eigen::VectorXf &error,
                                     double, const Eigen::VectorXd &) const
{
    return (level.update * error).cast<double>();
}

WibergStep::WibergStep(Eigen::VectorXd shapeVariances, double priorWeight)
    : m_inverseVariance(shapeVariances.cwiseMax(1e-12).cwiseInverse()), m_priorWeight(priorWeight)
{
}

Eigen::VectorXd WibergStep::step(const AamFitLevel &level, const PiecewiseAffineWarp &warp, const Eigen::VectorXf &error,
                                 double residual, const Eigen::VectorXd &shapeParams) const
{
    // Steepest descent from the appearance instance that best explains the current sample,
    // A0 + A A^T (i - A0), appearance projected out (Tzimiropoulos & Pantic 2013, §4); `error` is
    // i - A0, and its appearance part is orthogonal to the projected-out Jacobian, so it needs no
    // removing.
    const Eigen::VectorXf instance = level.templateMean + level.appearance * (level.appearance.transpose() * error);
    const Eigen::MatrixXf sd = steepestDescent(level, warp, instance);
    Eigen::MatrixXd hessian = (sd.transpose() * sd).cast<double>();
    Eigen::VectorXd gradient = (sd.transpose() * error).cast<double>();
    // Shape prior: minimise |e - J dp|^2 + s2 (b - M dp)^T L^-1 (b - M dp), with s2 the texture
    // noise per pixel (the current residual, weighted) and L the shape variances; b - M dp is the
    // shape after the inverse compositional update.
    const Eigen::MatrixXd &M = level.toShapeParams;
    const double s2 = m_priorWeight * residual;
    hessian += s2 * M.transpose() * m_inverseVariance.asDiagonal() * M;
    gradient += s2 * M.transpose() * (m_inverseVariance.asDiagonal() * shapeParams);
    hessian.diagonal().array() += 1e-6 * hessian.diagonal().mean();
    return hessian.ldlt().solve(gradient);
}

std::unique_ptr<AamFitStep> makeAamFitStep(const AamModel &model, const AamFitOptions &options)
{
    switch (options.algorithm) {
    case AamFitAlgorithm::ProjectOut:
        return std::make_unique<ProjectOutStep>();
    case AamFitAlgorithm::Wiberg:
        return std::make_unique<WibergStep>(model.shapeVariances, options.shapePriorWeight);
    }
    return std::make_unique<ProjectOutStep>();
}

} // namespace lipsync
