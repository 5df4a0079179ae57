#pragma once
// What the fitter precomputes for one resolution level of an AamModel (AamFitter): the mean shape
// in the level's reference frame, the normalised template and the appearance subspace to project
// out, the orthonormal basis of similarity + shape displacements, the warp Jacobian at every
// pixel, and the project-out update matrix (Matthews & Baker, IJCV 2004, §4).
#include "aam/PiecewiseAffineWarp.h"

#include <Eigen/Core>

namespace lipsync {

struct AamFitLevel
{
    Eigen::VectorXd reference;     // s0 in reference pixels
    Eigen::VectorXf templateMean;  // A0
    Eigen::MatrixXf appearance;    // A (pixels x m)
    Eigen::MatrixXd basis;         // B (2k x P), orthonormal: similarity + shape
    Eigen::MatrixXf update;        // (SD^T SD)^-1 SD^T  (P x pixels)
    Eigen::MatrixXf warpX, warpY;  // dW/dp per pixel, x and y components (pixels x P)
    Eigen::MatrixXd toShapeParams; // M: change of the shape parameters b per unit of p (ns x P)
};

// Steepest-descent images (pixels x P) of a texture on the level's frame, with the appearance
// subspace projected out (Matthews & Baker §4.2, eq. 40).
Eigen::MatrixXf steepestDescent(const AamFitLevel &level, const PiecewiseAffineWarp &warp,
                                const Eigen::VectorXf &texture);

} // namespace lipsync
