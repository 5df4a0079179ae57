#pragma once
// How well a transcript fits its recording's sound, as the aligner that made the recording's tiers
// measured it (AlignerOutput::transcriptFit, kept in Sequence::transcriptFit): the forced path's
// log-likelihood per audio frame minus that of each frame's best-matching state on its own (a
// free recognition without a grammar), <= 0; CMU Sphinx's over the frames of speech only. Speech of other words pulls it far down; where a
// true transcript sits depends on the aligner's model, so each aligner gives the threshold it was
// calibrated at (docs/performance.md, "Transcripts that do not match the sound").
#include <cstdio>
#include <optional>
#include <string>

namespace lipsync {

// The transcript fit below which a transcript is taken not to be what the recording says, for an
// aligner of ours trained on the recording's speaker: chosen by cross-validation on GRID s1 with
// other clips' transcripts swapped in (docs/performance.md, "Transcripts that do not match the
// sound": 99.5 % of swaps below it, 1.25 % of true transcripts). With a model of another speaker
// true transcripts fall below it too (-2.4 to -13 measured): such speakers are aligned with CMU
// Sphinx's generic model, whose fit has its own threshold (kSphinxTranscriptFitThreshold).
constexpr double kTranscriptFitThreshold = -2.2;
// The same for CMU Sphinx's generic model adapted to the recording (`--aligner sphinx --adapt`,
// the default for a speaker other than the shipped model's), chosen the same way on GRID s1
// (thresholds -4.50 to -4.34 in the five folds: 1.25 % of true transcripts below, 82.8 % of
// GRID's swaps, which share half their words or more; on GRID s4, never tuned on, no true
// transcript and 80 % of swaps below).
constexpr double kSphinxTranscriptFitThreshold = -4.4;

struct TranscriptFit
{
    double value = 0.0;     // nats per audio frame
    double threshold = 0.0; // the measuring aligner's: below it the words are likely not the recording's

    bool misfit() const { return value < threshold; }
    // What a misfit means, with both figures, for messages naming the transcript.
    std::string reason() const
    {
        char text[160];
        std::snprintf(text, sizeof text,
                      "the transcript does not seem to be what the recording says (fit %.2f nats per frame, "
                      "below %.2f)",
                      value, threshold);
        return text;
    }
    bool operator==(const TranscriptFit &) const = default;
};

// A measured fit below its threshold: the words are likely not the recording's.
inline bool transcriptMisfit(const std::optional<TranscriptFit> &fit)
{
    return fit && fit->misfit();
}

} // namespace lipsync
