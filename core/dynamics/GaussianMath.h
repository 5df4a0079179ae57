#pragma once
// Small numeric helpers shared by the models.
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
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

// f of a symmetric matrix: V f(L) V^T from its eigendecomposition a = V L V^T.
template<class F>
Eigen::MatrixXd symmetricMatrixFunction(const Eigen::MatrixXd &a, F f)
{
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(a);
    return eigen.eigenvectors() * eigen.eigenvalues().unaryExpr(f).asDiagonal() * eigen.eigenvectors().transpose();
}

// The symmetric part of C with its eigenvalues floored at `minimum`: a full covariance kept
// positive definite (the variance floor of docs/models.md §0).
inline Eigen::MatrixXd floorEigenvalues(const Eigen::MatrixXd &C, double minimum)
{
    return symmetricMatrixFunction(0.5 * (C + C.transpose()), [minimum](double l) { return std::max(l, minimum); });
}

// Sum of logarithms of positive values with one std::log per block of 8: the running product is
// renormalised by frexp (exact) after each block, so it neither overflows nor underflows for
// values within 2^+-120. A log per frame and dimension would be the costliest operation of the
// scalar Kalman filter in the SLDS E-step.
class LogSum
{
public:
    void add(double value)
    {
        m_product *= value;
        if (++m_count == 8)
            normalise();
    }
    double value() const { return std::log(m_product) + double(m_exponent) * std::numbers::ln2; }

private:
    void normalise()
    {
        int exponent = 0;
        m_product = std::frexp(m_product, &exponent);
        m_exponent += exponent;
        m_count = 0;
    }
    double m_product = 1.0;
    long long m_exponent = 0;
    int m_count = 0;
};

} // namespace lipsync
