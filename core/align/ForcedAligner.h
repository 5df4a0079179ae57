#pragma once
// Viterbi forced alignment (the paper's "HMM unrolled with the transcript"; HTK's HVite -a):
// the best state path through the utterance's graph gives word and phone boundaries.
// Times follow HTK: a segment covering 100 Hz frames a..b spans [a * shift, (b + 1) * shift);
// the last segment is stretched to the end of the audio.
#include "align/AcousticModel.h"
#include "align/Lexicon.h"
#include "align/UtteranceGraph.h"
#include "project/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

struct AlignmentResult
{
    Tier words{"words", {}};   // transcript words, "sil" for silences
    Tier phones{"phones", {}}; // PhoneSet labels
    double logLikelihood = 0;  // of the best path
    int frames = 0;
};

class ForcedAligner
{
public:
    struct Options
    {
        double beam = 400.0;
        UtteranceGraph::Options graph;
    };

    explicit ForcedAligner(const AcousticModel &model) : ForcedAligner(model, Options{}) {}
    ForcedAligner(const AcousticModel &model, const Options &options) : m_model(model), m_options(options) {}

    // Aligns `words` (their pronunciations, variants in parallel) to `features`.
    // Throws lipsync::Error if the transcript cannot fit the audio (too short for its phones).
    AlignmentResult align(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                          const std::vector<std::vector<Pronunciation>> &pronunciations,
                          double audioDuration = 0.0) const;
    // Convenience: pronunciations from `lexicon` (throws naming unknown words).
    AlignmentResult align(const Eigen::MatrixXf &features, const std::string &transcript,
                          const Lexicon &lexicon, double audioDuration = 0.0) const;

private:
    AlignmentResult alignWithBeam(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                                  const std::vector<std::vector<Pronunciation>> &pronunciations,
                                  double audioDuration, double beam) const;

    const AcousticModel &m_model;
    Options m_options;
};

} // namespace lipsync
