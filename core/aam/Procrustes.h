#pragma once
// Similarity alignment of 2D shapes (flat interleaved vectors x0, y0, x1, y1, ...) and the
// generalised Procrustes analysis of a training set (Cootes, Edwards & Taylor 2001, §3; Cootes &
// Taylor, "Statistical models of appearance", §4.2: align, project into the tangent space).
#include <Eigen/Core>

#include <vector>

namespace lipsync {

// p -> [a -b; b a] p + t: a uniform scale and rotation plus a translation.
struct Similarity
{
    double a = 1.0;
    double b = 0.0;
    double tx = 0.0;
    double ty = 0.0;

    Eigen::VectorXd apply(const Eigen::VectorXd &shape) const;
    Eigen::Vector2d apply(const Eigen::Vector2d &p) const;
    Similarity inverse() const;
    // (this ∘ other)(p) = this(other(p))
    Similarity compose(const Similarity &other) const;
    double scale() const;
};

// Least-squares similarity T minimising sum_i w_i |T(from_i) - to_i|^2 (closed form). With
// weights empty, all points count equally. Returns identity for a degenerate `from`.
Similarity alignSimilarity(const Eigen::VectorXd &from, const Eigen::VectorXd &to,
                           const Eigen::VectorXd &weights = {});

Eigen::Vector2d shapeCentroid(const Eigen::VectorXd &shape);
// Root-sum-square distance of the points from their centroid (0 for a degenerate shape).
double shapeSize(const Eigen::VectorXd &shape);
// Centred, unit size.
Eigen::VectorXd normalisedShape(const Eigen::VectorXd &shape);
// Spread of the points across their main direction: the smaller singular value of the centred
// point cloud over sqrt(n), in the shape's units (0 when all points coincide or lie on a line).
// Used to reject degenerate training shapes.
double shapeSpread(const Eigen::VectorXd &shape);

struct ProcrustesResult
{
    Eigen::VectorXd mean;               // centred, unit size
    std::vector<Eigen::VectorXd> aligned; // each shape aligned to the mean, in its tangent space
    int iterations = 0;
};

// Generalised Procrustes analysis: iteratively align every shape to the current mean, re-estimate
// the mean (kept centred, unit size and in the orientation of the first shape), until the mean
// moves less than `tolerance`. Aligned shapes are projected into the tangent space of the mean
// (x / (x . mean)) so that the shape PCA is linear.
ProcrustesResult generalisedProcrustes(const std::vector<Eigen::VectorXd> &shapes,
                                       int maxIterations = 100, double tolerance = 1e-10);

} // namespace lipsync
