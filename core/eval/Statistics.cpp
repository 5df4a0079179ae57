#include "eval/Statistics.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace lipsync::stats {

namespace {
double betaContinuedFraction(double a, double b, double x)
{
    constexpr int maxIterations = 300;
    constexpr double eps = 1e-15, tiny = 1e-300;
    const double qab = a + b, qap = a + 1.0, qam = a - 1.0;
    double c = 1.0, d = 1.0 - qab * x / qap;
    if (std::abs(d) < tiny)
        d = tiny;
    d = 1.0 / d;
    double h = d;
    for (int m = 1; m <= maxIterations; ++m) {
        const int m2 = 2 * m;
        double aa = m * (b - m) * x / ((qam + m2) * (a + m2));
        d = 1.0 + aa * d;
        if (std::abs(d) < tiny)
            d = tiny;
        c = 1.0 + aa / c;
        if (std::abs(c) < tiny)
            c = tiny;
        d = 1.0 / d;
        h *= d * c;
        aa = -(a + m) * (qab + m) * x / ((a + m2) * (qap + m2));
        d = 1.0 + aa * d;
        if (std::abs(d) < tiny)
            d = tiny;
        c = 1.0 + aa / c;
        if (std::abs(c) < tiny)
            c = tiny;
        d = 1.0 / d;
        const double del = d * c;
        h *= del;
        if (std::abs(del - 1.0) < eps)
            break;
    }
    return h;
}
} // namespace

double incompleteBeta(double a, double b, double x)
{
    if (x <= 0.0)
        return 0.0;
    if (x >= 1.0)
        return 1.0;
    const double front = std::exp(std::lgamma(a + b) - std::lgamma(a) - std::lgamma(b)
                                  + a * std::log(x) + b * std::log1p(-x));
    if (x < (a + 1.0) / (a + b + 2.0))
        return front * betaContinuedFraction(a, b, x) / a;
    return 1.0 - front * betaContinuedFraction(b, a, 1.0 - x) / b;
}

double studentTCdf(double t, double dof)
{
    const double tail = 0.5 * incompleteBeta(dof / 2.0, 0.5, dof / (dof + t * t));
    return t >= 0 ? 1.0 - tail : tail;
}

double studentTQuantile(double p, double dof)
{
    double lo = -1e4, hi = 1e4;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (studentTCdf(mid, dof) < p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
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
    out.p = 2.0 * (1.0 - studentTCdf(std::abs(out.t), double(diff.size() - 1)));
    return out;
}

double signTestPValue(int nA, int nB)
{
    const int n = nA + nB;
    if (n == 0)
        return 1.0;
    // log-space binomial tails
    auto logPmf = [n](int k) {
        return std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) - n * std::log(2.0);
    };
    double lower = 0.0, upper = 0.0;
    for (int k = 0; k <= nA; ++k)
        lower += std::exp(logPmf(k));
    for (int k = nA; k <= n; ++k)
        upper += std::exp(logPmf(k));
    return std::min(1.0, 2.0 * std::min(lower, upper));
}

std::vector<double> holmAdjust(const std::vector<double> &p)
{
    const size_t m = p.size();
    std::vector<size_t> order(m);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](size_t i, size_t j) { return p[i] < p[j]; });
    std::vector<double> adjusted(m);
    double running = 0.0;
    for (size_t rank = 0; rank < m; ++rank) {
        running = std::max(running, std::min(1.0, double(m - rank) * p[order[rank]]));
        adjusted[order[rank]] = running;
    }
    return adjusted;
}

} // namespace lipsync::stats
