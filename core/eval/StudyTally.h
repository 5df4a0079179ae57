#pragma once
// Tally of a forced-choice study in the form of the paper's Table 1: for every pair of methods
// (A, B), how often A was judged real, how often the participant could not decide, how often B
// was judged real; with
//  - a two-sided exact sign test per pair (H0: A and B are equally often judged real). The
//    undecided answers are ties and are excluded, as is usual for the sign test: n = preferA +
//    preferB, p = min(1, 2 P[X <= min(preferA, preferB)]) with X ~ Binomial(n, 1/2); n = 0 gives 1.
//    Alongside, the p-value adjusted by Holm's step-down procedure over all pairs
//    (docs/models.md §6.4: the pairs are tested together, so the family-wise error is what alpha
//    must bound).
//  - a Bradley-Terry ranking (P[i judged real over j] = g_i / (g_i + g_j)), fitted by maximum
//    likelihood with the MM algorithm of Hunter (2004, Ann. Statist. 32:384, eq. 3); undecided
//    answers are again left out. Strengths are normalised to sum to 1. A method never judged real
//    gets strength 0 (the maximum-likelihood limit).
//  - per method, the share of its decided trials in which it was judged real with a 95 % Wilson
//    score interval, so that a ranking from few answers shows how little it says;
//  - the paper's one-line summary ("DPDS ≈ reality ≻ Brand ≻ SLDS"): methods by strength, "≻"
//    between neighbours whose direct comparison is significant at alpha after Holm's adjustment,
//    else "≈"; and a caution when a pair has fewer than kFewAnswers decided answers.
#include "project/ForcedChoiceStudy.h"

#include <Eigen/Core>
#include <QJsonObject>

#include <functional>
#include <string>
#include <vector>

namespace lipsync {

// Bradley-Terry strengths from wins(i, j) = times i beat j (diagonal ignored), by Hunter's MM
// iteration until the largest change is below `tolerance`. Sum to 1.
Eigen::VectorXd bradleyTerry(const Eigen::MatrixXd &wins, int maxIterations = 10000,
                             double tolerance = 1e-12, int *iterations = nullptr);

struct PairTally
{
    int a = 0; // method indices, a < b
    int b = 0;
    int preferA = 0; // A judged real
    int undecided = 0;
    int preferB = 0; // B judged real
    double pValue = 1.0;
    double holmPValue = 1.0; // pValue adjusted over all pairs (Holm-Bonferroni)

    int decided() const { return preferA + preferB; }
    int total() const { return preferA + undecided + preferB; }
};

struct MethodScore
{
    int method = 0;
    double strength = 0; // Bradley-Terry, sums to 1 over methods
    int wins = 0;        // judged real
    int losses = 0;      // the other side judged real
    int undecided = 0;
    // wins / (wins + losses) and its 95 % Wilson score interval ([0, 1] with no decided trial).
    double realShare = 0, realShareLow = 0, realShareHigh = 1;
};

class StudyTally
{
public:
    // Decided answers a pair needs before its ranking is more than anecdote: with 10, a sign
    // test can reach p < 0.05 only at 9:1 or better.
    static constexpr int kFewAnswers = 10;

    // Counts the answered trials of every session (unanswered ones are skipped).
    static StudyTally fromStudy(const ForcedChoiceStudy &study);
    // From raw counts (e.g. the paper's Table 1). Pairs may name methods in either order and may
    // repeat (counts add up); throws lipsync::Error for an out-of-range index or a self-pair.
    static StudyTally fromCounts(const std::vector<std::string> &methods,
                                 const std::vector<PairTally> &counts);

    std::vector<std::string> methods;
    std::vector<PairTally> pairs;     // every unordered pair once, (0,1), (0,2), ... (a < b)
    std::vector<MethodScore> ranking; // strongest first
    int participants = 0;
    int answered = 0;
    int unanswered = 0;

    const PairTally &pair(int i, int j) const; // either order; a of the result is min(i, j)
    // `methodName` (optional) gives each method id the name shown, e.g. a translated one.
    std::string summary(double alpha = 0.05,
                        const std::function<std::string(const std::string &)> &methodName = {}) const;
    // The fewest decided answers of any pair.
    int fewestDecided() const;
    // A sentence warning that the ranking rests on few answers (some pair below kFewAnswers), or
    // empty.
    std::string caution() const;
    // CSV, one row per pair: method_a,method_b,prefer_a,undecided,prefer_b,n_decided,p_value,p_holm
    std::string pairsCsv() const;
    // CSV, one row per method: rank,method,strength,judged_real,judged_not_real,undecided,
    // real_share,real_share_low,real_share_high
    std::string rankingCsv() const;
    QJsonObject toJson() const;

private:
    void finalise();
};

} // namespace lipsync
