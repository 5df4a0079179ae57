#pragma once
// Principal component analysis with the number of modes chosen by the fraction of variance
// retained (Cootes et al. 2001, §3). Uses the Gram matrix when there are fewer samples than
// dimensions (textures: thousands of pixels, tens of images).
#include <Eigen/Core>

namespace lipsync {

struct Pca
{
    Eigen::VectorXd mean;      // d
    Eigen::MatrixXd basis;     // d x m, orthonormal columns
    Eigen::VectorXd variances; // m, descending
    double totalVariance = 0.0;

    int modes() const { return int(basis.cols()); }
    Eigen::VectorXd project(const Eigen::VectorXd &x) const { return basis.transpose() * (x - mean); }
    Eigen::VectorXd reconstruct(const Eigen::VectorXd &b) const { return mean + basis * b; }
};

// `samples`: one sample per column (d x n). Keeps the fewest modes whose variance reaches
// `fraction` of the total, at most `maxModes` (0: no cap) and at most n-1. A fraction >= 1 keeps
// every mode with non-zero variance. `centre` false treats the data as already zero-mean.
Pca computePca(const Eigen::MatrixXd &samples, double fraction, int maxModes = 0,
               bool centre = true);

} // namespace lipsync
