#pragma once
// A phone bigram P(q | p) over the 41 labels (docs/pipeline.md, "Live"): the language model of
// StreamingPhoneRecognizer's phone loop, counted from phone tiers — a project's forced
// alignments — and smoothed by adding one to every count (Laplace), so every phone may follow
// every other. A tier's consecutive intervals give its transitions; its first phone follows "sil".
//
// File (text, written atomically): "lipsync-phone-bigram 1", then 41 lines of 41 counts, row p
// holding the counts of p followed by each q in PhoneSet order. Counts, not probabilities, so
// that bigrams of several parts add up.
#include "annotation/Tier.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

class PhoneBigram
{
public:
    static constexpr int kFormatVersion = 1;

    PhoneBigram();
    // Counts the transitions of every tier (labels outside the phone set are an Error naming the
    // tier's index and the label).
    static PhoneBigram fromTiers(const std::vector<Tier> &phoneTiers);

    // log P(to | from), natural log.
    double logProbability(int from, int to) const { return m_log(from, to); }
    const Eigen::MatrixXd &counts() const { return m_counts; }
    double transitions() const { return m_counts.sum(); }

    // Throws lipsync::Error naming the file (and line) for I/O and malformed content.
    void save(const std::string &path) const;
    std::string text() const;
    static PhoneBigram load(const std::string &path);
    static PhoneBigram parse(const std::string &text, const std::string &pathForErrors = {});

private:
    explicit PhoneBigram(const Eigen::MatrixXd &counts);

    Eigen::MatrixXd m_counts;
    Eigen::MatrixXd m_log;
};

} // namespace lipsync
