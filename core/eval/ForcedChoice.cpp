#include "eval/ForcedChoice.h"

#include "eval/Statistics.h"
#include "util/Error.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

std::vector<PairTest> signTests(const std::vector<PairTally> &pairs)
{
    std::vector<double> p;
    for (const PairTally &t : pairs)
        p.push_back(stats::signTestPValue(t.preferA, t.preferB));
    const std::vector<double> holm = stats::holmAdjust(p);
    std::vector<PairTest> out;
    for (size_t i = 0; i < p.size(); ++i)
        out.push_back({p[i], holm[i]});
    return out;
}

std::vector<double> bradleyTerryLogScores(const std::vector<PairTally> &pairs,
                                          const std::vector<std::string> &methods, bool tiesAsHalf,
                                          int iterations)
{
    const size_t m = methods.size();
    auto index = [&](const std::string &name) {
        const auto it = std::find(methods.begin(), methods.end(), name);
        if (it == methods.end())
            throw Error("unknown method '" + name + "' in the tally");
        return size_t(it - methods.begin());
    };
    std::vector<std::vector<double>> wins(m, std::vector<double>(m, 0.0));
    for (const PairTally &t : pairs) {
        const size_t a = index(t.a), b = index(t.b);
        const double tie = tiesAsHalf ? 0.5 * t.undecided : 0.0;
        wins[a][b] += t.preferA + tie;
        wins[b][a] += t.preferB + tie;
    }
    std::vector<double> pi(m, 1.0);
    for (int it = 0; it < iterations; ++it) {
        std::vector<double> next(m);
        double change = 0.0;
        for (size_t i = 0; i < m; ++i) {
            double W = 0.0, denominator = 0.0;
            for (size_t j = 0; j < m; ++j) {
                if (j == i)
                    continue;
                W += wins[i][j];
                const double n = wins[i][j] + wins[j][i];
                if (n > 0)
                    denominator += n / (pi[i] + pi[j]);
            }
            next[i] = denominator > 0 ? W / denominator : pi[i];
        }
        double logMean = 0.0;
        for (double v : next)
            logMean += std::log(v) / double(m);
        for (size_t i = 0; i < m; ++i) {
            next[i] /= std::exp(logMean); // prod pi = 1
            change = std::max(change, std::abs(std::log(next[i]) - std::log(pi[i])));
        }
        pi = next;
        if (change < 1e-13)
            break;
    }
    std::vector<double> out;
    for (double v : pi)
        out.push_back(std::log(v));
    return out;
}

} // namespace lipsync
