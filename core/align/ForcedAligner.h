#pragma once
// Viterbi forced alignment (the paper's "HMM unrolled with the transcript"; HTK's HVite -a):
// the best state path through the utterance's graph gives word and phone boundaries.
// Times follow HTK: a segment covering 100 Hz frames a..b spans [a * shift, (b + 1) * shift);
// the last segment is stretched to the end of the audio.
#include "align/AcousticModel.h"
#include "align/Lexicon.h"
#include "align/UtteranceGraph.h"
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

// A boundary the alignment must keep exactly (a user's fix on the timeline): word `word` (index
// into the aligned word list) starts, or ends, at `time` seconds. Whatever lies before it (an
// optional silence included) ends there; whatever follows starts there.
struct FixedBoundary
{
    enum class Side { Start, End };
    int word = 0;
    Side side = Side::Start;
    double time = 0.0;
};

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
    // The same Viterbi search with `fixed` boundaries as hard constraints (HTK's HVite with a
    // partially labelled network): every state before a fixed boundary is confined to the frames
    // before it and every state after it to the frames after it, so the best path is the best of
    // those that keep the boundaries. Fixed times land on the 10 ms frame grid and are reported
    // exactly as given; all other boundaries are free. Where the constraints agree with the
    // unconstrained best path, the result is that path. Throws lipsync::Error when no path keeps
    // them (e.g. too little time for the phones between two fixed boundaries).
    AlignmentResult align(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                          const std::vector<std::vector<Pronunciation>> &pronunciations, double audioDuration,
                          const std::vector<FixedBoundary> &fixed) const;
    // Convenience: pronunciations from `lexicon` (throws naming unknown words).
    AlignmentResult align(const Eigen::MatrixXf &features, const std::string &transcript,
                          const Lexicon &lexicon, double audioDuration = 0.0) const;

private:
    AlignmentResult alignWithBeam(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                                  const std::vector<std::vector<Pronunciation>> &pronunciations,
                                  double audioDuration, const std::vector<FixedBoundary> &fixed,
                                  double beam) const;

    const AcousticModel &m_model;
    Options m_options;
};

} // namespace lipsync
