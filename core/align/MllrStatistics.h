#pragma once
// The sufficient statistics of an MLLR mean transform (Leggetter & Woodland 1995) for one block
// of n coefficients with diagonal covariances, and its closed-form solution row by row: per row
// i, G_i = sum_m gamma_m / var_mi xi_m xi_m^T and k_i = sum_m sum_t gamma_m(t) o_ti / var_mi xi_m,
// with the extended mean xi_m = (1, mu_m); w_i = G_i^-1 k_i, so that mu' = W (1, mu).
// SpeakerAdaptation (our monophone GMMs) and SphinxAdaptation (CMU Sphinx's codebooks) share it.
#include <Eigen/Core>

#include <vector>

namespace lipsync {

class MllrStatistics
{
public:
    explicit MllrStatistics(int n);

    int size() const { return int(m_g.size()); }
    // One Gaussian's statistics: its occupancy (sum_t gamma(t)), the occupancy-weighted sum of
    // its observations, its mean and its variances (block coefficients only).
    void add(double occupancy, const Eigen::Ref<const Eigen::VectorXd> &sum, const Eigen::Ref<const Eigen::VectorXd> &mean,
             const Eigen::Ref<const Eigen::VectorXd> &variances);
    void add(const MllrStatistics &other);
    double frames() const { return m_frames; }

    // W (n x n+1), mu' = W (1, mu). A small ridge towards the identity keeps rows with little
    // data well posed; rows whose statistics are still singular stay the identity.
    Eigen::MatrixXd solve() const;

private:
    std::vector<Eigen::MatrixXd> m_g;
    std::vector<Eigen::VectorXd> m_k;
    double m_frames = 0;
};

} // namespace lipsync
