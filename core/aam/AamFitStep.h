#pragma once
// The fitting algorithms of AamFitter, as the one thing in which they differ: how an iteration of
// the inverse compositional fit computes its Gauss-Newton step dp from the texture error at the
// current shape. The iteration around it (sampling, compositional update, projection onto the
// shape model, backtracking) is AamFitter's and the same for all.
//  - ProjectOutStep (AamFitAlgorithm::ProjectOut): dp = U e with U the update matrix precomputed
//    from the mean texture's steepest-descent images (Matthews & Baker, IJCV 2004, §4.2): a
//    product with a (params x pixels) matrix, for person-specific models.
//  - WibergStep (AamFitAlgorithm::Wiberg): the steepest-descent images of the appearance instance
//    that best explains the current sample, appearance projected out, and a Gaussian prior on the
//    shape parameters weighed against the texture residual (Tzimiropoulos & Pantic, ICCV 2013,
//    §4; the MAP form of their eq. 15): a (params x params) solve per iteration, for generic
//    models.
#include "aam/AamFitLevel.h"
#include "aam/AamFitter.h"

#include <memory>

namespace lipsync {

class AamFitStep
{
public:
    virtual ~AamFitStep() = default;
    // The full step dp (level parameters) at a shape whose normalised sample minus A0 is `error`,
    // with texture residual `residual` (per pixel, appearance projected out) and shape
    // parameters `shapeParams`.
    virtual Eigen::VectorXd step(const AamFitLevel &level, const PiecewiseAffineWarp &warp,
                                 const Eigen::VectorXf &error, double residual,
                                 const Eigen::VectorXd &shapeParams) const = 0;
};

class ProjectOutStep final : public AamFitStep
{
public:
    Eigen::VectorXd step(const AamFitLevel &level, const PiecewiseAffineWarp &warp, const Eigen::VectorXf &error,
                         double residual, const Eigen::VectorXd &shapeParams) const override;
};

class WibergStep final : public AamFitStep
{
public:
    // `shapeVariances`: the shape model's (the prior); `priorWeight`: AamFitOptions::shapePriorWeight.
    WibergStep(Eigen::VectorXd shapeVariances, double priorWeight);
    Eigen::VectorXd step(const AamFitLevel &level, const PiecewiseAffineWarp &warp, const Eigen::VectorXf &error,
                         double residual, const Eigen::VectorXd &shapeParams) const override;

private:
    Eigen::VectorXd m_inverseVariance;
    double m_priorWeight;
};

// The step of `options.algorithm` for `model`.
std::unique_ptr<AamFitStep> makeAamFitStep(const AamModel &model, const AamFitOptions &options);

} // namespace lipsync
