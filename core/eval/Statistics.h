#pragma once
// Small statistics for the evaluation protocol (docs/models.md §6.3, §6.4): Student-t quantiles for
// 95 % intervals over folds, paired t-tests, the two-sided sign test. The distributions are
// Boost.Math's (Debian libboost-dev, header-only), not our own special functions.
#include <vector>

namespace lipsync::stats {

// P(T <= t) for Student's t with dof degrees of freedom; NaN for a NaN t or dof <= 0.
double studentTCdf(double t, double dof);
// The p-quantile of Student's t, p in (0, 1).
double studentTQuantile(double p, double dof);

struct MeanInterval
{
    double mean = 0.0;
    double halfWidth = 0.0; // t_{0.975, n-1} s / sqrt(n); 0 for n < 2
    double sd = 0.0;        // sample s.d. (n - 1 denominator)
};
MeanInterval meanWithCi95(const std::vector<double> &values);

struct TTest
{
    double meanDifference = 0.0;
    double t = 0.0;
    double p = 1.0; // two-sided
};
// Paired t-test on a_f - b_f (§6.3).
TTest pairedTTest(const std::vector<double> &a, const std::vector<double> &b);

// Two-sided exact sign test (§6.4): k of n decided answers (ties removed beforehand) for one
// side; p = min(1, 2 P(X <= min(k, n - k))), X ~ Bin(n, 1/2). 1 when n = 0.
double signTestPValue(int k, int n);

// Holm's step-down adjustment (Holm 1979, Scand. J. Statist. 6:65) of m p-values for a family of
// m tests (§6.4 "correct for 6 comparisons"): with p_(1) <= ... <= p_(m),
// adjusted p_(i) = min(1, max_{j <= i} (m - j + 1) p_(j)), returned in the input order. Rejecting
// where the adjusted p < alpha controls the family-wise error rate at alpha. NaN stays NaN.
std::vector<double> holmAdjusted(const std::vector<double> &p);

} // namespace lipsync::stats
