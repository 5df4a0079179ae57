#pragma once
// Small statistics for the evaluation protocol (models.md §6.3, §6.4): Student-t quantiles for
// 95 % intervals over folds, paired t-tests, the two-sided sign test.
#include <vector>

namespace lipsync::stats {

// Regularised incomplete beta I_x(a, b) (continued fraction, Numerical Recipes §6.4).
double incompleteBeta(double a, double b, double x);
// P(T <= t) for Student's t with dof degrees of freedom.
double studentTCdf(double t, double dof);
// The p-quantile of Student's t (bisection on the CDF), p in (0, 1).
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

// Two-sided sign test ignoring ties (§6.4): p = min(1, 2 min(P(X <= nA), P(X >= nA))),
// X ~ Bin(nA + nB, 1/2).
double signTestPValue(int nA, int nB);
// Holm step-down adjustment of p-values (same order as the input).
std::vector<double> holmAdjust(const std::vector<double> &p);

} // namespace lipsync::stats
