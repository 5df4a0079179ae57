#pragma once
// The psychophysical forced-choice tally of models.md §6.4: per unordered pair of methods the
// counts (prefer A, undecided, prefer B), two-sided sign tests with Holm correction, and a
// Bradley-Terry ranking by Hunter's MM iteration.
#include <string>
#include <vector>

namespace lipsync {

struct PairTally
{
    std::string a, b;
    int preferA = 0, undecided = 0, preferB = 0;
};

struct PairTest
{
    double p = 1.0;         // two-sided sign test, undecided ignored
    double pHolm = 1.0;     // Holm-adjusted over all pairs
};
std::vector<PairTest> signTests(const std::vector<PairTally> &pairs);

// log pi_i (normalised so that sum log pi = 0) for the methods, in the given order. Undecided
// answers are dropped, or counted as half a win each when tiesAsHalf.
std::vector<double> bradleyTerryLogScores(const std::vector<PairTally> &pairs,
                                          const std::vector<std::string> &methods,
                                          bool tiesAsHalf = false, int iterations = 10000);

} // namespace lipsync
