#pragma once
// Small numeric helpers shared by the models.
#include <Eigen/Core>

#include <cmath>
#include <numbers>

namespace lipsync {

constexpr double kLog2Pi = 1.8378770664093454835606594728112; // log(2 pi)

// sum_k log N(z_k; m_k, c_k) for a diagonal covariance.
inline double diagonalGaussianLogPdf(const Eigen::Ref<const Eigen::VectorXd> &z,
                                     const Eigen::Ref<const Eigen::VectorXd> &mean,
                                     const Eigen::Ref<const Eigen::VectorXd> &variance)
{
    return -0.5 * (double(z.size()) * kLog2Pi + variance.array().log().sum()
                   + ((z - mean).array().square() / variance.array()).sum());
}

} // namespace lipsync
