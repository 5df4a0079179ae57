#include "align/MllrStatistics.h"

#include <Eigen/Cholesky>

namespace lipsync {

MllrStatistics::MllrStatistics(int n)
    : m_g(size_t(n), Eigen::MatrixXd::Zero(n + 1, n + 1)), m_k(size_t(n), Eigen::VectorXd::Zero(n + 1))
{
}

void MllrStatistics::add(double occupancy, const Eigen::Ref<const Eigen::VectorXd> &sum,
                         const Eigen::Ref<const Eigen::VectorXd> &mean, const Eigen::Ref<const Eigen::VectorXd> &variances)
{
    const int n = size();
    Eigen::VectorXd xi(n + 1);
    xi[0] = 1.0;
    xi.tail(n) = mean;
    const Eigen::MatrixXd outer = xi * xi.transpose();
    for (int i = 0; i < n; ++i) {
        const double precision = 1.0 / variances[i];
        m_g[size_t(i)] += (occupancy * precision) * outer;
        m_k[size_t(i)] += (sum[i] * precision) * xi;
    }
    m_frames += occupancy;
}

void MllrStatistics::add(const MllrStatistics &other)
{
    for (size_t i = 0; i < m_g.size(); ++i) {
        m_g[i] += other.m_g[i];
        m_k[i] += other.m_k[i];
    }
    m_frames += other.m_frames;
}

Eigen::MatrixXd MllrStatistics::solve() const
{
    const int n = size();
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, n + 1);
    for (int i = 0; i < n; ++i) {
        Eigen::VectorXd identity = Eigen::VectorXd::Zero(n + 1);
        identity[i + 1] = 1.0;
        const double ridge = 1e-4 * m_g[size_t(i)].diagonal().mean() + 1e-8;
        const Eigen::MatrixXd g = m_g[size_t(i)] + ridge * Eigen::MatrixXd::Identity(n + 1, n + 1);
        const Eigen::VectorXd k = m_k[size_t(i)] + ridge * identity;
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(g);
        const Eigen::VectorXd row = ldlt.solve(k);
        const bool solved = ldlt.info() == Eigen::Success && row.allFinite();
        w.row(i) = (solved ? row : identity).transpose();
    }
    return w;
}

} // namespace lipsync
