#pragma once
// Principal component analysis with the number of modes chosen by the fraction of variance
// retained (Cootes et al. 2001, §3). Uses the Gram matrix when there are fewer samples than
// dimensions (textures: thousands of pixels, tens of images).
#include <Eigen/Core>

namespace lipsync {

// What ended the choice of modes (reported by `aam build`, so a user knows whether more labelled
// images or a higher variance fraction would give more modes).
enum class PcaLimit {
    Variance, // the requested fraction of the variance was reached
    Cap,      // the mode cap (maxModes) was reached first
    Samples,  // n-1 modes (n samples) were kept and the fraction still not reached
    Rank,     // the remaining modes have numerically zero variance
};

// "variance", "cap", "samples" or "rank".
const char *pcaLimitName(PcaLimit limit);

struct Pca
{
    Eigen::VectorXd mean;      // d
    Eigen::MatrixXd basis;     // d x m, orthonormal columns
    Eigen::VectorXd variances; // m, descending
    double totalVariance = 0.0;
    PcaLimit limit = PcaLimit::Rank;
    // Fraction of totalVariance the kept modes explain.
    double retainedFraction() const
    {
        return totalVariance > 0 ? variances.sum() / totalVariance : 1.0;
    }

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
