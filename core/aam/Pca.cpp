#include "aam/Pca.h"

#include <Eigen/Eigenvalues>

#include <algorithm>

namespace lipsync {

const char *pcaLimitName(PcaLimit limit)
{
    switch (limit) {
    case PcaLimit::Variance:
        return "variance";
    case PcaLimit::Cap:
        return "cap";
    case PcaLimit::Samples:
        return "samples";
    case PcaLimit::Rank:
        break;
    }
    return "rank";
}

Pca computePca(const Eigen::MatrixXd &samples, double fraction, int maxModes, bool centre)
{
    Pca pca;
    const Eigen::Index d = samples.rows();
    const Eigen::Index n = samples.cols();
    pca.mean = centre && n > 0 ? Eigen::VectorXd(samples.rowwise().mean()) : Eigen::VectorXd::Zero(d);
    if (n < 2 || d == 0) {
        pca.basis.resize(d, 0);
        return pca;
    }
    const Eigen::MatrixXd x = samples.colwise() - pca.mean;
    const double denom = double(centre ? n - 1 : n);
    Eigen::MatrixXd vectors;
    Eigen::VectorXd values;
    if (n < d) {
        // Eigenvectors of X^T X (n x n) map to those of X X^T through X.
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(x.transpose() * x / denom);
        values = eig.eigenvalues().reverse();
        const Eigen::MatrixXd v = eig.eigenvectors().rowwise().reverse();
        vectors = x * v;
        for (Eigen::Index j = 0; j < vectors.cols(); ++j) {
            const double norm = vectors.col(j).norm();
            if (norm > 0)
                vectors.col(j) /= norm;
        }
    } else {
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(x * x.transpose() / denom);
        values = eig.eigenvalues().reverse();
        vectors = eig.eigenvectors().rowwise().reverse();
    }
    values = values.cwiseMax(0.0);
    pca.totalVariance = values.sum();
    const Eigen::Index sampleLimit = centre ? n - 1 : n;
    const Eigen::Index available = std::min<Eigen::Index>(values.size(), sampleLimit);
    const Eigen::Index limit = maxModes > 0 ? std::min<Eigen::Index>(available, maxModes) : available;
    // Drop numerically-zero modes.
    const double eps = 1e-12 * std::max(1.0, values.size() ? values[0] : 0.0);
    Eigen::Index keep = 0;
    double acc = 0.0;
    while (true) {
        if (keep > 0 && fraction < 1.0 && acc >= fraction * pca.totalVariance) {
            pca.limit = PcaLimit::Variance;
            break;
        }
        if (keep >= limit) {
            pca.limit = limit < available ? PcaLimit::Cap
                        : keep >= sampleLimit ? PcaLimit::Samples
                                              : PcaLimit::Rank;
            break;
        }
        if (values[keep] <= eps) {
            pca.limit = PcaLimit::Rank;
            break;
        }
        acc += values[keep];
        ++keep;
    }
    pca.basis = vectors.leftCols(keep);
    pca.variances = values.head(keep);
    return pca;
}

} // namespace lipsync
