#include "dynamics/BrandSolver.h"

#include "util/Error.h"

#include <Eigen/Cholesky>

namespace lipsync::brand {

TridiagonalSystem buildTridiagonal(const Eigen::VectorXd &p, const Eigen::VectorXd &mbar,
                                   const Eigen::VectorXd &q, const Eigen::VectorXd &deltabar)
{
    const Eigen::Index T = p.size();
    TridiagonalSystem s;
    s.alpha.resize(T);
    s.beta.resize(std::max<Eigen::Index>(T - 1, 0));
    s.b.resize(T);
    for (Eigen::Index t = 0; t < T; ++t) {
        const double qt = t > 0 ? q[t] : 0.0;
        const double dt = t > 0 ? deltabar[t] : 0.0;
        const double qn = t + 1 < T ? q[t + 1] : 0.0;
        const double dn = t + 1 < T ? deltabar[t + 1] : 0.0;
        s.alpha[t] = p[t] + qt + qn;
        if (t + 1 < T)
            s.beta[t] = -qn;
        s.b[t] = p[t] * mbar[t] + qt * dt - qn * dn;
    }
    return s;
}

Eigen::VectorXd solveTridiagonal(const TridiagonalSystem &s, Eigen::VectorXd *pivots,
                                 Eigen::VectorXd *multipliers)
{
    const Eigen::Index T = s.alpha.size();
    Eigen::VectorXd d(T), l = Eigen::VectorXd::Zero(T), z(T), y(T);
    d[0] = s.alpha[0];
    z[0] = s.b[0];
    for (Eigen::Index t = 1; t < T; ++t) {
        l[t] = s.beta[t - 1] / d[t - 1];
        d[t] = s.alpha[t] - l[t] * s.beta[t - 1];
        z[t] = s.b[t] - l[t] * z[t - 1];
    }
    y[T - 1] = z[T - 1] / d[T - 1];
    for (Eigen::Index t = T - 2; t >= 0; --t)
        y[t] = z[t] / d[t] - l[t + 1] * y[t + 1];
    if (pivots)
        *pivots = d;
    if (multipliers)
        *multipliers = l;
    return y;
}

Eigen::MatrixXd solveBlockTridiagonal(const BlockTridiagonalSystem &s)
{
    const size_t T = s.diagonal.size();
    const Eigen::Index d = s.rhs.rows();
    std::vector<Eigen::LLT<Eigen::MatrixXd>> pivots(T);
    std::vector<Eigen::MatrixXd> L(T);
    Eigen::MatrixXd z(d, Eigen::Index(T)), y(d, Eigen::Index(T));
    pivots[0].compute(s.diagonal[0]);
    z.col(0) = s.rhs.col(0);
    for (size_t t = 0; t < T; ++t) {
        if (t > 0) {
            // L_t = H_{t,t-1} D_{t-1}^{-1}; D_{t-1} symmetric, so L_t^T = D_{t-1}^{-1} H_{t,t-1}^T.
            L[t] = pivots[t - 1].solve(s.lower[t - 1].transpose()).transpose();
            pivots[t].compute(s.diagonal[t] - L[t] * s.lower[t - 1].transpose());
            z.col(Eigen::Index(t)) = s.rhs.col(Eigen::Index(t)) - L[t] * z.col(Eigen::Index(t - 1));
        }
        if (pivots[t].info() != Eigen::Success)
            throw Error("block pivot " + std::to_string(t) + " is not positive definite");
    }
    y.col(Eigen::Index(T - 1)) = pivots[T - 1].solve(z.col(Eigen::Index(T - 1)));
    for (size_t t = T - 1; t-- > 0;)
        y.col(Eigen::Index(t)) = pivots[t].solve(z.col(Eigen::Index(t)))
                                 - L[t + 1].transpose() * y.col(Eigen::Index(t + 1));
    return y;
}

Eigen::MatrixXd denseMatrix(const BlockTridiagonalSystem &s)
{
    const Eigen::Index T = Eigen::Index(s.diagonal.size());
    const Eigen::Index d = s.rhs.rows();
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(d * T, d * T);
    for (Eigen::Index t = 0; t < T; ++t) {
        H.block(t * d, t * d, d, d) = s.diagonal[size_t(t)];
        if (t + 1 < T) {
            H.block((t + 1) * d, t * d, d, d) = s.lower[size_t(t)];
            H.block(t * d, (t + 1) * d, d, d) = s.lower[size_t(t)].transpose();
        }
    }
    return H;
}

Eigen::VectorXd denseRhs(const BlockTridiagonalSystem &s)
{
    return Eigen::Map<const Eigen::VectorXd>(s.rhs.data(), s.rhs.size());
}

Eigen::MatrixXd solveDense(const BlockTridiagonalSystem &s)
{
    const Eigen::LLT<Eigen::MatrixXd> llt(denseMatrix(s));
    if (llt.info() != Eigen::Success)
        throw Error("dense MLPG matrix is not positive definite");
    const Eigen::VectorXd y = llt.solve(denseRhs(s));
    return Eigen::Map<const Eigen::MatrixXd>(y.data(), s.rhs.rows(), s.rhs.cols());
}

} // namespace lipsync::brand
