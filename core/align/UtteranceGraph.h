#pragma once
// The HMM of one utterance "unrolled" from its transcript (the paper's forced alignment; HTK's
// HERest/HVite word networks): optional silence, word 1 (its pronunciation variants in
// parallel), optional silence, word 2, ..., optional silence. Each phone instance is the 3
// emitting states of its monophone. States are numbered so that every edge goes from a lower to
// a higher index (or is a self-loop), which lets forward, backward and Viterbi passes run as
// single sweeps over the state list.
#include "align/PronunciationDictionary.h"

#include <cmath>
#include <string>
#include <vector>

namespace lipsync {

class AcousticModel;

struct GraphEdge
{
    int from;     // predecessor state, or -1 for the entry
    double extra; // log weight of the route taken (optional silence, variant choice)
};

struct GraphState
{
    int modelState;   // AcousticModel state index (phone * 3 + position)
    int phone;        // PhoneSet index
    int position;     // 0..2 within the phone
    int word;         // index into the word list, -1 for inter-word silence
    int phoneInstance;
    std::vector<GraphEdge> in; // predecessors other than the self-loop
    double exitExtra = -INFINITY; // log weight of ending the utterance here (last states only)
};

class UtteranceGraph
{
public:
    struct Options
    {
        double silenceProbability = 0.5; // of an optional silence between words
        bool optionalEdgeSilence = true;  // leading/trailing silence may be skipped
        // Any state may end the utterance: for a window cut out of a longer recording, whose
        // last frame can fall anywhere in the words (LongAlignment).
        bool openEnd = false;
    };

    // `pronunciations[w]` holds the variants of word w (at least one each).
    UtteranceGraph(const std::vector<std::vector<Pronunciation>> &pronunciations, const Options &options);
    UtteranceGraph(const std::vector<std::vector<Pronunciation>> &pronunciations)
        : UtteranceGraph(pronunciations, Options{}) {}

    const std::vector<GraphState> &states() const { return m_states; }
    int size() const { return int(m_states.size()); }
    // Fewest frames any path needs (3 per phone on the shortest route).
    int minimumFrames() const { return m_minimumFrames; }

    // Log transition weights under `model`: self-loop, and from predecessor p into state s
    // (log(1 - a_p) + extra, or just extra from the entry), ending at s (log(1 - a_s) + exitExtra).
    double logSelf(const AcousticModel &model, int s) const;
    double logEdge(const AcousticModel &model, const GraphEdge &edge) const;
    double logExit(const AcousticModel &model, int s) const;

private:
    std::vector<GraphState> m_states;
    int m_minimumFrames = 0;
};

} // namespace lipsync
