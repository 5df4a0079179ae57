#pragma once
// Re-aligning stretches of an existing alignment while keeping everything else (the timeline's
// "re-align selection"): the words of the whole word tier are aligned once more with every
// boundary outside the stretches — and the stretches' own edges — as fixed boundaries
// (ForcedAligner's constrained Viterbi), and only the result inside the stretches replaces the
// tiers. So the re-aligned words meet the kept ones exactly, and the Viterbi path still sees the
// whole utterance.
#include "align/ForcedAligner.h"
#include "align/SphinxAligner.h"

#include <utility>
#include <vector>

namespace lipsync {

class Realignment
{
public:
    using Stretch = std::pair<double, double>; // [start, end) in seconds

    // The stretches of the tiers to re-align for a selection [a, b): runs of consecutive word
    // intervals overlapping it that hold a spoken word and that the user has not edited (a
    // userEdited word, or a word over a userEdited phone, stays as it is and splits the run).
    static std::vector<Stretch> freeStretches(const Tier &words, const Tier &phones, double a, double b);

    // `words` and `phones`: the current, contiguous tiers. Silence labels ("sil", "sp", "") are
    // not words; a breath "br" is the noise word "[br]".
    Realignment(const Tier &words, const Tier &phones, std::vector<Stretch> stretches);

    // The words the aligner gets (pronounce these), and the boundaries kept.
    const std::vector<std::string> &words() const { return m_words; }
    const std::vector<FixedBoundary> &fixed() const { return m_fixed; }

    // Aligns `features` (the whole recording) with the fixed boundaries and returns the tiers
    // with the stretches replaced by the new alignment; logLikelihood is the constrained path's.
    // Throws lipsync::Error from the aligner.
    AlignmentResult run(const ForcedAligner &aligner, const Eigen::MatrixXf &features,
                        const std::vector<std::vector<Pronunciation>> &pronunciations, double audioDuration) const;

    // The CMU Sphinx aligner takes no fixed boundaries: each stretch's own audio (of `samples`,
    // mono at SphinxAligner::kSampleRate, the whole recording) is aligned with the stretch's own
    // words, so the stretch edges stay exactly where they were. `pronunciations` are those of
    // words(). Throws lipsync::Error from the aligner (and Canceled through `feedback`).
    AlignmentResult runPiecewise(const SphinxAligner &aligner, const std::vector<float> &samples,
                                 const std::vector<std::vector<Pronunciation>> &pronunciations,
                                 Feedback &feedback = Feedback::none()) const;

private:
    Tier m_wordTier, m_phoneTier;
    std::vector<Stretch> m_stretches;
    std::vector<std::string> m_words;
    std::vector<FixedBoundary> m_fixed;
    std::vector<std::pair<double, double>> m_wordSpans; // of words()[i]: its word-tier interval
};

} // namespace lipsync
