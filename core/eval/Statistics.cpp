#include "eval/Statistics.h"

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lipsync::stats {

namespace {

// NaN for arguments outside the domain (a NaN t from folds with a non-finite metric, say)
// rather than Boost's default std::domain_error: one bad comparison must not abort an evaluation.
using Policy = boost::math::policies::policy<boost::math::policies::domain_error<boost::math::policies::ignore_error>>;
using StudentT = boost::math::students_t_distribution<double, Policy>;

} // namespace

double studentTCdf(double t, double dof)
{
    return boost::math::cdf(StudentT(dof), t); // 0 and 1 at -inf and +inf
}

double studentTQuantile(double p, double dof)
{
    return boost::math::quantile(StudentT(dof), p);
}

MeanInterval meanWithCi95(const std::vector<double> &values)
{
    MeanInterval out;
    const size_t n = values.size();
    if (n == 0)
        return out;
    out.mean = std::accumulate(values.begin(), values.end(), 0.0) / double(n);
    if (n < 2)
        return out;
    double ss = 0.0;
    for (double v : values)
        ss += (v - out.mean) * (v - out.mean);
    out.sd = std::sqrt(ss / double(n - 1));
    out.halfWidth = studentTQuantile(0.975, double(n - 1)) * out.sd / std::sqrt(double(n));
    return out;
}

TTest pairedTTest(const std::vector<double> &a, const std::vector<double> &b)
{
    TTest out;
    std::vector<double> diff;
    for (size_t i = 0; i < std::min(a.size(), b.size()); ++i)
        diff.push_back(a[i] - b[i]);
    const MeanInterval m = meanWithCi95(diff);
    out.meanDifference = m.mean;
    if (diff.size() < 2)
        return out;
    if (m.sd == 0.0) {
        out.t = m.mean == 0.0 ? 0.0 : std::copysign(INFINITY, m.mean);
        out.p = m.mean == 0.0 ? 1.0 : 0.0;
        return out;
    }
    out.t = m.mean / (m.sd / std::sqrt(double(diff.size())));
    // The upper tail directly (cdf of -|t|), not 1 - cdf: no cancellation for large |t|.
    out.p = 2.0 * studentTCdf(-std::abs(out.t), double(diff.size() - 1));
    return out;
}

double signTestPValue(int k, int n)
{
    if (n <= 0)
        return 1.0;
    k = std::clamp(k, 0, n);
    const int tail = std::min(k, n - k);
    return std::min(1.0, 2.0 * boost::math::cdf(boost::math::binomial_distribution<double, Policy>(double(n), 0.5), double(tail)));
}

std::vector<double> holmAdjusted(const std::vector<double> &p)
{
    const size_t m = p.size();
    std::vector<size_t> order;
    for (size_t i = 0; i < m; ++i)
        if (!std::isnan(p[i]))
            order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return p[a] < p[b]; });
    std::vector<double> adjusted(p);
    double running = 0.0;
    for (size_t rank = 0; rank < order.size(); ++rank) {
        running = std::max(running, std::min(1.0, double(m - rank) * p[order[rank]]));
        adjusted[order[rank]] = running;
    }
    return adjusted;
}

} // namespace lipsync::stats
