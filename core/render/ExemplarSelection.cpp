#include "render/ExemplarSelection.h"

#include "util/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace lipsync {

ExemplarSelection::ExemplarSelection(const std::vector<Eigen::MatrixXd> &recordings, const Options &options)
    : m_options(options)
{
    Eigen::Index total = 0, d = -1;
    for (const Eigen::MatrixXd &r : recordings) {
        if (r.rows() == 0)
            continue;
        if (d >= 0 && r.cols() != d)
            throw Error("recorded trajectories of different dimensions to choose frames from");
        d = r.cols();
        total += r.rows();
    }
    if (total == 0)
        throw Error("no recorded frames to choose from");
    m_frames.resize(total, d);
    m_next.assign(size_t(total), -1);
    Eigen::Index at = 0;
    for (const Eigen::MatrixXd &r : recordings) {
        if (r.rows() == 0)
            continue;
        m_frames.middleRows(at, r.rows()) = r;
        for (Eigen::Index t = 0; t + 1 < r.rows(); ++t)
            m_next[size_t(at + t)] = int(at + t + 1);
        at += r.rows();
    }
    const Eigen::RowVectorXd mean = m_frames.colwise().mean();
    m_scale = ((m_frames.rowwise() - mean).array().square().colwise().sum() / double(std::max<Eigen::Index>(1, total - 1)))
                  .sqrt()
                  .transpose()
                  .cwiseMax(1e-9);
    m_frames = m_frames.array().rowwise() / m_scale.transpose().array();
    m_norms = m_frames.rowwise().squaredNorm();
}

std::vector<int> ExemplarSelection::choose(const Eigen::MatrixXd &generated) const
{
    const int T = int(generated.rows());
    if (T == 0)
        return {};
    if (generated.cols() != m_frames.cols())
        throw Error("a generated trajectory of " + std::to_string(generated.cols()) + " parameters, recorded frames of "
                    + std::to_string(m_frames.cols()));
    const Eigen::MatrixXd z = generated.array().rowwise() / m_scale.transpose().array();
    const int K = std::max(1, std::min(m_options.candidates, int(m_frames.rows())));
    // Each frame's candidates and their target costs; the distances to every recorded frame,
    // |z|² - 2 z·x + |x|², one generated frame at a time (memory O(N + T K) for any length).
    std::vector<std::vector<int>> candidates(static_cast<size_t>(T));
    std::vector<std::vector<double>> target(static_cast<size_t>(T));
    std::vector<int> order(static_cast<size_t>(m_frames.rows()));
    for (int t = 0; t < T; ++t) {
        const Eigen::VectorXd distance = (m_norms - 2.0 * m_frames * z.row(t).transpose()).array() + z.row(t).squaredNorm();
        std::iota(order.begin(), order.end(), 0);
        std::partial_sort(order.begin(), order.begin() + K, order.end(),
                          [&](int a, int b) { return distance[a] < distance[b]; });
        std::vector<int> &c = candidates[size_t(t)];
        c.assign(order.begin(), order.begin() + K);
        // The previous candidates' successors, its nearest first, up to 3K candidates in all.
        if (t > 0)
            for (int previous : candidates[size_t(t - 1)])
                if (const int next = m_next[size_t(previous)];
                    next >= 0 && c.size() < size_t(3 * K) && std::find(c.begin(), c.end(), next) == c.end())
                    c.push_back(next);
        for (int k : c)
            target[size_t(t)].push_back(std::max(0.0, distance[k]));
    }
    // Viterbi over the candidates.
    std::vector<std::vector<double>> cost(static_cast<size_t>(T));
    std::vector<std::vector<int>> from(static_cast<size_t>(T));
    cost[0] = target[0];
    for (int t = 1; t < T; ++t) {
        const std::vector<int> &now = candidates[size_t(t)], &before = candidates[size_t(t - 1)];
        const Eigen::RowVectorXd step = z.row(t) - z.row(t - 1);
        cost[size_t(t)].assign(now.size(), std::numeric_limits<double>::infinity());
        from[size_t(t)].assign(now.size(), 0);
        for (size_t i = 0; i < now.size(); ++i) {
            for (size_t j = 0; j < before.size(); ++j) {
                const bool follows = m_next[size_t(before[j])] == now[i];
                const double join = follows ? 0.0
                                            : m_options.cut
                                                  + m_options.join
                                                        * (m_frames.row(now[i]) - m_frames.row(before[j]) - step)
                                                              .squaredNorm();
                const double c = cost[size_t(t - 1)][j] + join;
                if (c < cost[size_t(t)][i]) {
                    cost[size_t(t)][i] = c;
                    from[size_t(t)][i] = int(j);
                }
            }
            cost[size_t(t)][i] += target[size_t(t)][i];
        }
    }
    std::vector<int> chosen(static_cast<size_t>(T));
    size_t best = size_t(std::min_element(cost[size_t(T - 1)].begin(), cost[size_t(T - 1)].end())
                         - cost[size_t(T - 1)].begin());
    for (int t = T - 1; t >= 0; --t) {
        chosen[size_t(t)] = candidates[size_t(t)][best];
        if (t > 0)
            best = size_t(from[size_t(t)][best]);
    }
    return chosen;
}

Eigen::MatrixXd ExemplarSelection::select(const Eigen::MatrixXd &generated) const
{
    const std::vector<int> chosen = choose(generated);
    Eigen::MatrixXd out(generated.rows(), generated.cols());
    for (size_t t = 0; t < chosen.size(); ++t)
        out.row(Eigen::Index(t)) = m_frames.row(chosen[t]).cwiseProduct(m_scale.transpose());
    return out;
}

} // namespace lipsync
