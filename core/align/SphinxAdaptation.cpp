#include "align/SphinxAdaptation.h"

#include <cmath>
#include <sstream>

namespace lipsync {

SphinxAdaptation::SphinxAdaptation(const SphinxCodebooks &codebooks) : m_codebooks(codebooks)
{
    for (int cb = 0; cb < codebooks.codebooks(); ++cb)
        for (int f = 0; f < codebooks.streams(); ++f) {
            m_occupancy.push_back(Eigen::VectorXd::Zero(codebooks.densities()));
            m_sum.push_back(Eigen::MatrixXd::Zero(codebooks.densities(), codebooks.streamLength(f)));
            m_logNorm.push_back(-0.5 * codebooks.variances(cb, f).cast<double>().array().log().rowwise().sum().matrix());
        }
}

void SphinxAdaptation::addFrame(const float *const *features, int senone, int codebook)
{
    const int D = m_codebooks.densities();
    Eigen::VectorXd logp(D);
    for (int f = 0; f < m_codebooks.streams(); ++f) {
        const size_t i = index(codebook, f);
        const int n = m_codebooks.streamLength(f);
        const Eigen::Map<const Eigen::RowVectorXf> o(features[f], n);
        const SphinxCodebooks::Matrix &mean = m_codebooks.means(codebook, f);
        const SphinxCodebooks::Matrix &var = m_codebooks.variances(codebook, f);
        for (int d = 0; d < D; ++d)
            logp[d] = m_codebooks.logWeight(f, d, senone) + m_logNorm[i][d] -
                      0.5 * double(((o - mean.row(d)).array().square() / var.row(d).array()).sum());
        const double best = logp.maxCoeff();
        const Eigen::VectorXd p = (logp.array() - best).exp();
        const Eigen::VectorXd gamma = p / p.sum();
        const Eigen::RowVectorXd od = o.cast<double>();
        for (int d = 0; d < D; ++d)
            if (gamma[d] > 1e-4) {
                m_occupancy[i][d] += gamma[d];
                m_sum[i].row(d) += gamma[d] * od;
            }
    }
    m_frames += 1;
}

std::vector<Eigen::MatrixXd> SphinxAdaptation::transforms() const
{
    std::vector<Eigen::MatrixXd> out;
    for (int f = 0; f < m_codebooks.streams(); ++f) {
        MllrStatistics statistics(m_codebooks.streamLength(f));
        for (int cb = 0; cb < m_codebooks.codebooks(); ++cb) {
            const size_t i = index(cb, f);
            for (int d = 0; d < m_codebooks.densities(); ++d)
                if (m_occupancy[i][d] > 1e-6)
                    statistics.add(m_occupancy[i][d], m_sum[i].row(d).transpose(),
                                   m_codebooks.means(cb, f).row(d).transpose().cast<double>(),
                                   m_codebooks.variances(cb, f).row(d).transpose().cast<double>());
        }
        out.push_back(statistics.solve());
    }
    return out;
}

std::string SphinxAdaptation::pocketsphinxText(const std::vector<Eigen::MatrixXd> &transforms)
{
    std::ostringstream s;
    s.precision(9);
    s << "1\n" << transforms.size() << "\n";
    for (const Eigen::MatrixXd &w : transforms) {
        const Eigen::Index n = w.rows();
        s << n << "\n";
        for (Eigen::Index r = 0; r < n; ++r) {
            for (Eigen::Index c = 0; c < n; ++c)
                s << w(r, c + 1) << ' ';
            s << "\n";
        }
        for (Eigen::Index r = 0; r < n; ++r)
            s << w(r, 0) << ' ';
        s << "\n";
        for (Eigen::Index r = 0; r < n; ++r)
            s << "1.0 ";
        s << "\n";
    }
    return s.str();
}

} // namespace lipsync
