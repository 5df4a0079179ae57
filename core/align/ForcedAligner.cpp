#include "align/ForcedAligner.h"

#include "align/EmissionCache.h"
#include "util/PhoneSet.h"
#include "util/Error.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace lipsync {

namespace {

// The phone and word tiers of a Viterbi state path (one graph state per frame); timeOf(f) is the
// time of the boundary before frame f (T: the end).
template <typename TimeOf>
void tiersOfPath(const std::vector<int> &path, const std::vector<GraphState> &states,
                 const std::vector<std::string> &words, const TimeOf &timeOf, Tier &phoneTier, Tier &wordTier)
{
    auto pushOrExtend = [](Tier &tier, double start, double stop, const std::string &label, bool merge) {
        if (merge && !tier.intervals.empty() && tier.intervals.back().label == label)
            tier.intervals.back().end = stop;
        else
            tier.intervals.push_back(Interval{start, stop, label, false});
    };
    int segmentStart = 0;
    int lastWord = -2;
    const int T = int(path.size());
    for (int t = 1; t <= T; ++t) {
        if (t < T && states[size_t(path[size_t(t)])].phoneInstance == states[size_t(path[size_t(t - 1)])].phoneInstance)
            continue;
        const GraphState &st = states[size_t(path[size_t(t - 1)])];
        const double start = timeOf(segmentStart);
        const double stop = timeOf(t);
        const std::string phone = PhoneSet::label(st.phone);
        // Adjacent silences (a word-final sil variant next to an optional sil) are one segment.
        pushOrExtend(phoneTier, start, stop, phone, st.phone == PhoneSet::kSilence);
        const std::string word = st.word < 0 ? std::string(PhoneSet::kSilenceLabel) : words[size_t(st.word)];
        if (st.word >= 0 && st.word == lastWord)
            wordTier.intervals.back().end = stop;
        else
            pushOrExtend(wordTier, start, stop, word, st.word < 0);
        lastWord = st.word;
        segmentStart = t;
    }
}

} // namespace

AlignmentResult ForcedAligner::align(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                                     const std::vector<std::vector<Pronunciation>> &pronunciations,
                                     double audioDuration) const
{
    return align(features, words, pronunciations, audioDuration, {});
}

AlignmentResult ForcedAligner::align(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                                     const std::vector<std::vector<Pronunciation>> &pronunciations,
                                     double audioDuration, const std::vector<FixedBoundary> &fixed) const
{
    try {
        return alignWithBeam(features, words, pronunciations, audioDuration, fixed, m_options.beam);
    } catch (const Error &) {
        // Every path pruned: retry without pruning before declaring that the transcript does not fit.
        if (!std::isfinite(m_options.beam))
            throw;
        return alignWithBeam(features, words, pronunciations, audioDuration, fixed, INFINITY);
    }
}

AlignmentResult ForcedAligner::alignWithBeam(const Eigen::MatrixXf &features, const std::vector<std::string> &words,
                                             const std::vector<std::vector<Pronunciation>> &pronunciations,
                                             double audioDuration, const std::vector<FixedBoundary> &fixed,
                                             double beam) const
{
    const UtteranceGraph graph(pronunciations, m_options.graph);
    const int T = int(features.rows());
    const int S = graph.size();
    const double shift = m_model.featureOptions().shiftSeconds;
    if (T < graph.minimumFrames())
        throw Error("the transcript does not fit the audio: " + std::to_string(graph.minimumFrames() / 3)
                    + " phones need at least " + std::to_string(graph.minimumFrames() * shift)
                    + " s, the audio has " + std::to_string(T * shift) + " s");
    // Back pointers take T x S ints: about 10 minutes of continuous speech in one pass at most.
    if (double(T) * double(S) > 3e8)
        throw Error("the recording is too long to align in one piece (" + std::to_string(T * shift)
                    + " s with " + std::to_string(S / 3) + " phones): split it into shorter utterances");
    if (features.cols() != m_model.dimension())
        throw Error("features do not match the aligner model's dimension");
    const auto &states = graph.states();
    // Fixed boundaries as cuts of the graph: the graph's states are ordered along the utterance
    // (leading silence, word 0 with its variants, silence, word 1, ...), so "word w starts at
    // frame f" means states below word w's first state only before f and the others from f on;
    // "ends" cuts after its last state. Each state gets the frame range it may occupy.
    std::vector<int> firstOf(words.size(), S), lastOf(words.size(), -1);
    for (int s = 0; s < S; ++s)
        if (const int w = states[size_t(s)].word; w >= 0) {
            firstOf[size_t(w)] = std::min(firstOf[size_t(w)], s);
            lastOf[size_t(w)] = std::max(lastOf[size_t(w)], s);
        }
    std::vector<int> earliest(size_t(S), 0), latest(size_t(S), T - 1);
    std::map<int, double> fixedTimes; // frame -> the time given for a boundary there
    for (const FixedBoundary &b : fixed) {
        if (b.word < 0 || b.word >= int(words.size()) || lastOf[size_t(b.word)] < 0)
            throw Error("a fixed boundary refers to word " + std::to_string(b.word) + ", which is not aligned");
        const int cut = b.side == FixedBoundary::Side::Start ? firstOf[size_t(b.word)] : lastOf[size_t(b.word)] + 1;
        const int f = std::clamp(int(std::lround(b.time / shift)), 0, T);
        for (int s = 0; s < cut; ++s)
            latest[size_t(s)] = std::min(latest[size_t(s)], f - 1);
        for (int s = cut; s < S; ++s)
            earliest[size_t(s)] = std::max(earliest[size_t(s)], f);
        fixedTimes[f] = b.time;
    }
    EmissionCache emission(m_model, features);
    std::vector<double> logSelf(static_cast<size_t>(S)), logExit(static_cast<size_t>(S));
    std::vector<std::vector<double>> logIn(static_cast<size_t>(S));
    for (int s = 0; s < S; ++s) {
        logSelf[size_t(s)] = graph.logSelf(m_model, s);
        logExit[size_t(s)] = graph.logExit(m_model, s);
        for (const GraphEdge &e : states[size_t(s)].in)
            logIn[size_t(s)].push_back(graph.logEdge(m_model, e));
    }
    // delta[s] at t, and back pointers (predecessor state, -1 = entry) for every (t, s).
    std::vector<double> delta(static_cast<size_t>(S), -INFINITY), previous(size_t(S), -INFINITY);
    std::vector<int> back(static_cast<size_t>(T) * size_t(S), -2);
    for (int t = 0; t < T; ++t) {
        std::swap(delta, previous);
        double best = -INFINITY;
        for (int s = 0; s < S; ++s) {
            double v = -INFINITY;
            int from = -2;
            const GraphState &st = states[size_t(s)];
            if (t > 0 && previous[size_t(s)] > -INFINITY) {
                v = previous[size_t(s)] + logSelf[size_t(s)];
                from = s;
            }
            for (size_t e = 0; e < st.in.size(); ++e) {
                const int p = st.in[e].from;
                const double score = p < 0 ? (t == 0 ? logIn[size_t(s)][e] : -INFINITY)
                                           : (t > 0 ? previous[size_t(p)] + logIn[size_t(s)][e] : -INFINITY);
                if (score > v) {
                    v = score;
                    from = p;
                }
            }
            if (t < earliest[size_t(s)] || t > latest[size_t(s)])
                v = -INFINITY;
            if (v > -INFINITY) {
                v += emission(t, st.modelState);
                best = std::max(best, v);
            }
            delta[size_t(s)] = v;
            back[size_t(t) * size_t(S) + size_t(s)] = from;
        }
        if (best == -INFINITY)
            throw Error(fixed.empty() ? "no alignment path survives (the transcript does not fit the audio)"
                                      : "no alignment keeps the fixed boundaries (too little time for the "
                                        "phones between them)");
        for (int s = 0; s < S; ++s)
            if (delta[size_t(s)] < best - beam)
                delta[size_t(s)] = -INFINITY;
    }
    int last = -1;
    double bestFinal = -INFINITY;
    for (int s = 0; s < S; ++s) {
        const double v = delta[size_t(s)] + logExit[size_t(s)];
        if (v > bestFinal) {
            bestFinal = v;
            last = s;
        }
    }
    if (last < 0)
        throw Error("no alignment path reaches the end of the transcript (the transcript does not fit the audio)");

    std::vector<int> path(static_cast<size_t>(T));
    for (int t = T - 1, s = last; t >= 0; --t) {
        path[size_t(t)] = s;
        s = back[size_t(t) * size_t(S) + size_t(s)];
    }

    AlignmentResult result;
    result.logLikelihood = bestFinal;
    result.frames = T;
    const double end = std::max(audioDuration, T * shift);
    auto timeOf = [&](int frame) {
        if (frame == 0 || frame == T)
            return frame == 0 ? 0.0 : end;
        if (const auto it = fixedTimes.find(frame); it != fixedTimes.end())
            return it->second;
        return frame * shift;
    };
    tiersOfPath(path, states, words, timeOf, result.phones, result.words);
    return result;
}

AlignmentResult ForcedAligner::align(const Eigen::MatrixXf &features, const std::string &transcript,
                                     const Lexicon &lexicon, double audioDuration) const
{
    const std::vector<std::string> words = Lexicon::splitWords(transcript);
    return align(features, words, lexicon.pronounceAll(words), audioDuration);
}

} // namespace lipsync
