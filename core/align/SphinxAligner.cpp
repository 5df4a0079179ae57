#include "align/SphinxAligner.h"

#include "align/AlignerUtterance.h"
#include "align/Realignment.h"
#include "align/LongAlignment.h"
#include "align/SphinxAdaptation.h"
#include "align/SphinxBackend.h"
#include "align/SphinxCodebooks.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "tasks/Feedback.h"
#include "util/Environment.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numeric>

namespace lipsync {

namespace {

// The model's CI phone name of a PhoneSet phone. Breath is the model's noise phone.
std::string sphinxPhone(int phone)
{
    if (phone == PhoneSet::kBreath)
        return "+NSN+";
    if (phone == PhoneSet::kSilence)
        return "SIL";
    std::string label = PhoneSet::label(phone);
    std::transform(label.begin(), label.end(), label.begin(), [](unsigned char c) { return char(std::toupper(c)); });
    return label;
}

// The options of the senone scorer: keep every frame (the default voice-activity detection drops
// silent frames and shifts all times), score only the senones the Viterbi needs in each frame
// (align() names them) with the 8 best Gaussians of each codebook (mfa-tests, BM_EvalMfaPhones/5:
// -topn 4 / 8 / 16 / 32 / 64 give 78.1 / 78.5 / 78.3 / 78.0 / 78.2 %, noise, at 0.13 x real time
// for 8 and 0.23 for 16 on one thread when all senones were scored).
const std::vector<std::pair<std::string, std::string>> &baseArguments()
{
    static const std::vector<std::pair<std::string, std::string>> args{
        {"-remove_silence", "no"}, {"-compallsen", "no"}, {"-topn", "8"},
    };
    return args;
}

// The transcript unrolled into HMMs (one per phone in context): a node is a phone of a word's
// pronunciation variant with one choice of cross-word context, or an optional silence.
struct Graph
{
    struct Node
    {
        int phone = 0;  // the mdef phone whose senones it uses
        int label = 0;  // PhoneSet index (kSilence for the optional silences)
        int word = -1;  // transcript word, -1 for silence
        std::vector<int> next;
    };
    std::vector<Node> nodes;
    std::vector<int> entries, finals;
};

Graph buildGraph(const SphinxModelDefinition &mdef, const std::vector<std::vector<Pronunciation>> &pronunciations,
                 const std::string &modelDir)
{
    using Position = SphinxModelDefinition::Position;
    const int sil = mdef.silence();
    // The model's CI phones of every variant; as a context, noise phones count as SIL.
    std::vector<std::vector<std::vector<int>>> ci(pronunciations.size());
    for (size_t w = 0; w < pronunciations.size(); ++w)
        for (const Pronunciation &variant : pronunciations[w]) {
            std::vector<int> phones;
            for (int p : variant) {
                const int id = mdef.ciPhone(sphinxPhone(p));
                if (id < 0)
                    throw Error("the CMU Sphinx model lacks the phone " + sphinxPhone(p), modelDir);
                phones.push_back(id);
            }
            ci[w].push_back(std::move(phones));
        }
    auto context = [&](int id) { return mdef.isFiller(id) ? sil : id; };
    Graph g;
    auto add = [&](int phone, int label, int word) {
        g.nodes.push_back({phone, label, word, {}});
        return int(g.nodes.size()) - 1;
    };
    struct Exit
    {
        int node, phone, right; // last phone node, its CI phone and its right context
    };
    const int startSil = add(sil, PhoneSet::kSilence, -1);
    g.entries.push_back(startSil);
    std::vector<Exit> exits;       // the previous word's last phones
    int silenceBefore = startSil; // the optional silence after it
    const size_t W = pronunciations.size();
    for (size_t w = 0; w < W; ++w) {
        // The contexts across the word's edges: the neighbours' edge phones, or SIL (a pause, or
        // the utterance's edge).
        std::vector<int> lefts{sil}, rights{sil};
        if (w > 0)
            for (const auto &v : ci[w - 1])
                if (std::find(lefts.begin(), lefts.end(), context(v.back())) == lefts.end())
                    lefts.push_back(context(v.back()));
        if (w + 1 < W)
            for (const auto &v : ci[w + 1])
                if (std::find(rights.begin(), rights.end(), context(v.front())) == rights.end())
                    rights.push_back(context(v.front()));
        std::vector<Exit> wordExits;
        for (size_t v = 0; v < ci[w].size(); ++v) {
            const std::vector<int> &phones = ci[w][v];
            const int n = int(phones.size());
            std::vector<int> previous; // the nodes of phone j - 1
            for (int j = 0; j < n; ++j) {
                const Position pos = n == 1 ? Position::Single : j == 0 ? Position::Begin : j == n - 1 ? Position::End : Position::Internal;
                const std::vector<int> ls = j == 0 ? lefts : std::vector<int>{context(phones[size_t(j) - 1])};
                const std::vector<int> rs = j == n - 1 ? rights : std::vector<int>{context(phones[size_t(j) + 1])};
                std::vector<int> current;
                for (int l : ls)
                    for (int r : rs) {
                        const int base = phones[size_t(j)];
                        const int phone = mdef.isFiller(base) ? base : mdef.nearestPhone(base, l, r, pos);
                        const int node = add(phone, pronunciations[w][v][size_t(j)], int(w));
                        current.push_back(node);
                        for (int p : previous)
                            g.nodes[size_t(p)].next.push_back(node);
                        if (j == 0) {
                            // Entered from the previous word's last phones whose right context is
                            // this phone and which are this node's left context; SIL-context
                            // nodes also from the optional silence.
                            for (const Exit &e : exits)
                                if ((e.right == context(phones[0]) && context(e.phone) == l) || (e.right == sil && l == sil))
                                    g.nodes[size_t(e.node)].next.push_back(node);
                            if (l == sil)
                                g.nodes[size_t(silenceBefore)].next.push_back(node);
                            if (w == 0 && l == sil)
                                g.entries.push_back(node);
                        }
                        if (j == n - 1) {
                            wordExits.push_back({node, phones[size_t(j)], r});
                            if (w + 1 == W && r == sil)
                                g.finals.push_back(node);
                        }
                    }
                previous = std::move(current);
            }
        }
        exits = std::move(wordExits);
        silenceBefore = add(sil, PhoneSet::kSilence, -1);
        for (const Exit &e : exits)
            if (e.right == sil)
                g.nodes[size_t(e.node)].next.push_back(silenceBefore);
        if (w + 1 == W)
            g.finals.push_back(silenceBefore);
    }
    return g;
}

} // namespace

std::string SphinxAligner::resolveModelDir(const std::string &modelDir)
{
    if (!modelDir.empty())
        return modelDir;
    if (std::string chosen = environment::value("LIPSYNC_SPHINX_MODEL"); !chosen.empty())
        return chosen;
    return kDefaultModelDir;
}

bool SphinxAligner::available(const std::string &modelDir)
{
    std::error_code ec;
    return std::filesystem::exists(std::filesystem::path(resolveModelDir(modelDir)) / "mdef", ec);
}

namespace {

SphinxModelDefinition readModelDefinition(const std::string &modelDir)
{
    if (!SphinxAligner::available(modelDir))
        throw Error(std::filesystem::exists(modelDir)
                        ? "not a CMU Sphinx acoustic model folder (no mdef file)"
                        : "the CMU Sphinx acoustic model folder does not exist (Debian package pocketsphinx-en-us)",
                    modelDir);
    return SphinxModelDefinition::read((std::filesystem::path(modelDir) / "mdef").string());
}

} // namespace

SphinxAligner::SphinxAligner(Options options)
    : m_modelDir(resolveModelDir(options.modelDir)), m_mdef(readModelDefinition(m_modelDir)),
      m_extra(std::move(options.extraArguments)), m_adaptationPasses(std::max(0, options.adaptationPasses)),
      m_measureFit(options.measureTranscriptFit), m_decoders([this] {
          std::vector<std::pair<std::string, std::string>> arguments = baseArguments();
          arguments.insert(arguments.end(), m_extra.begin(), m_extra.end());
          return std::make_unique<SphinxDecoder>(m_modelDir, arguments);
      })
{
    if (m_mdef.silence() < 0 || m_mdef.ciName(m_mdef.silence()) != "SIL")
        throw Error("the CMU Sphinx model definition has no SIL phone", m_modelDir + "/mdef");
}

SphinxAligner::~SphinxAligner() = default;

const SphinxCodebooks &SphinxAligner::codebooks(const SphinxDecoder &decoder) const
{
    std::call_once(m_codebooksOnce, [&] {
        m_codebooks = std::make_unique<SphinxCodebooks>(
            SphinxCodebooks::read(m_modelDir, m_mdef.senoneCount(), decoder.logBase(), decoder.varianceFloor()));
    });
    if (m_codebooks->codebooks() != m_mdef.ciPhoneCount())
        throw Error("not a phonetically-tied-mixture model (one codebook per CI phone): cannot adapt it", m_modelDir);
    return *m_codebooks;
}

namespace {

// A transcript token pronounced as silence only ("sil", "sp"): the graph's optional silences
// stand for it already.
bool silenceOnly(const std::vector<Pronunciation> &variants)
{
    return !variants.empty() && std::all_of(variants.begin(), variants.end(), [](const Pronunciation &v) {
        return !v.empty() && std::all_of(v.begin(), v.end(), [](int p) { return p == PhoneSet::kSilence; });
    });
}

// `samples` as pocketsphinx's 16-bit PCM. Throws for empty or silent audio (below -80 dBFS, as
// prepareUtterance: nothing to align words to).
std::vector<short> checkedPcm(const std::vector<float> &samples)
{
    if (samples.empty())
        throw Error("the audio is empty");
    float peak = 0;
    for (float v : samples)
        peak = std::max(peak, std::abs(v));
    if (peak < 1e-4f)
        throw Error("the audio is silent");
    return toPcm16(samples);
}

// Viterbi over the graph's states (node * E + emitting state), left to right with self-loops and
// no transition probabilities; costs are the senone scores (0 = the best senone scored in that
// frame: a per-frame constant, the same for every path). Only the senones of the states reached
// are scored in each frame: the Gaussian mixtures are nearly all of the time (all 5,126 senones
// per frame: 0.11 x real time on mfa-tests, one thread; these: 0.047, and 0.027 with the beam).
class GraphViterbi
{
public:
    static constexpr int32_t kInf = INT32_MAX / 2;

    GraphViterbi(const Graph &graph, const SphinxModelDefinition &mdef, SphinxUtterance &utterance)
        : m_graph(graph), m_utterance(utterance), m_E(mdef.statesPerPhone()),
          m_S(graph.nodes.size() * size_t(m_E)), m_T(utterance.frames()), m_cur(m_S), m_next(m_S),
          m_back(size_t(m_T) * m_S)
    {
        for (const Graph::Node &n : graph.nodes)
            m_senones.push_back(mdef.senones(n.phone));
    }

    int statesPerPhone() const { return m_E; }
    int senoneOf(size_t s) const { return int(m_senones[s / size_t(m_E)][s % size_t(m_E)]); }
    int32_t cost(int state) const { return m_cur[size_t(state)]; }

    // One pass; states costlier than the frame's best by more than `beam` (0: none) are dropped.
    // `progress(share of the frames)` is called every 50 frames. Returns the best final state,
    // or -1 when no path survived.
    template<class Progress>
    int run(int32_t beam, const Progress &progress)
    {
        std::fill(m_cur.begin(), m_cur.end(), kInf);
        for (int e : m_graph.entries)
            m_cur[size_t(e) * size_t(m_E)] = 0;
        for (int t = 0; t < m_T; ++t) {
            if (t % 50 == 0)
                progress(double(t) / double(m_T));
            if (t > 0)
                step(t);
            score(t, beam);
        }
        int best = -1;
        for (int f : m_graph.finals) {
            const size_t s = size_t(f) * size_t(m_E) + size_t(m_E) - 1;
            if (m_cur[s] < kInf && (best < 0 || m_cur[s] < m_cur[size_t(best)]))
                best = int(s);
        }
        return best;
    }

    // The state of every frame on the last pass's path to `best`.
    std::vector<int> path(int best) const
    {
        std::vector<int> out(static_cast<size_t>(m_T));
        out[size_t(m_T) - 1] = best;
        for (int t = m_T - 1; t > 0; --t)
            out[size_t(t) - 1] = m_back[size_t(t) * m_S + size_t(out[size_t(t)])];
        return out;
    }

private:
    // Frame t's costs from frame t - 1's: stay, the next state of the phone, or from a phone's
    // last state into the first of each successor node.
    void step(int t)
    {
        std::fill(m_next.begin(), m_next.end(), kInf);
        int32_t *b = &m_back[size_t(t) * m_S];
        auto relax = [&](size_t to, int32_t cost, size_t from) {
            if (cost < m_next[to]) {
                m_next[to] = cost;
                b[to] = int32_t(from);
            }
        };
        for (size_t s = 0; s < m_S; ++s) {
            const int32_t c = m_cur[s];
            if (c >= kInf)
                continue;
            relax(s, c, s);
            if (s % size_t(m_E) + 1 < size_t(m_E))
                relax(s + 1, c, s);
            else
                for (int m : m_graph.nodes[s / size_t(m_E)].next)
                    relax(size_t(m) * size_t(m_E), c, s);
        }
        std::swap(m_cur, m_next);
    }

    // Adds frame t's senone scores to the states reached, then prunes by the beam.
    void score(int t, int32_t beam)
    {
        m_active.clear();
        for (size_t s = 0; s < m_S; ++s)
            if (m_cur[s] < kInf)
                m_active.push_back(senoneOf(s));
        const short *sc = m_utterance.score(t, m_active);
        int32_t frameBest = kInf;
        for (size_t s = 0; s < m_S; ++s)
            if (m_cur[s] < kInf) {
                m_cur[s] += sc[senoneOf(s)];
                frameBest = std::min(frameBest, m_cur[s]);
            }
        if (beam > 0)
            for (int32_t &c : m_cur)
                if (c > frameBest + beam)
                    c = kInf;
    }

    const Graph &m_graph;
    SphinxUtterance &m_utterance;
    const int m_E;
    const size_t m_S;
    const int m_T;
    std::vector<const uint16_t *> m_senones; // of each node
    std::vector<int32_t> m_cur, m_next, m_back;
    std::vector<int> m_active;
};

// The phone and word tiers of a path (the state of every 10 ms frame) through `graph`: a phone
// spans [its first frame, the next phone's), the first starts at 0 and the last ends at `end`
// (ForcedAligner's HTK convention); adjacent silences are one; the word tier has the words with
// "sil" between them.
AlignmentResult tiersOfPath(const Graph &graph, int E, const std::vector<int> &path,
                            const std::vector<std::string> &words, double end)
{
    struct Segment
    {
        int label; // PhoneSet index
        int word;  // transcript word, -1 for silence
        int start; // first frame
    };
    std::vector<Segment> segments;
    for (int t = 0, previous = -1; t < int(path.size()); ++t) {
        const int node = path[size_t(t)] / E;
        const Graph::Node &n = graph.nodes[size_t(node)];
        const bool enters = node != previous && path[size_t(t)] % E == 0;
        previous = node;
        if (!enters || (n.word < 0 && !segments.empty() && segments.back().word < 0))
            continue;
        segments.push_back({n.label, n.word, t});
    }
    const double shift = SphinxDecoder::kFrameSeconds;
    auto startOf = [&](size_t i) { return i == 0 ? 0.0 : segments[i].start * shift; };
    auto endOf = [&](size_t i) { return i + 1 < segments.size() ? segments[i + 1].start * shift : end; };
    AlignmentResult result;
    for (size_t i = 0; i < segments.size(); ++i)
        result.phones.intervals.push_back(Interval{startOf(i), endOf(i), PhoneSet::label(segments[i].label), false});
    double cursor = 0;
    for (size_t i = 0; i < segments.size();) {
        const int word = segments[i].word;
        size_t j = i + 1;
        while (j < segments.size() && segments[j].word == word && word >= 0)
            ++j;
        if (word >= 0) {
            const double a = startOf(i), b = endOf(j - 1);
            if (a > cursor + 1e-9)
                result.words.intervals.push_back(Interval{cursor, a, std::string(PhoneSet::kSilenceLabel), false});
            result.words.intervals.push_back(Interval{a, b, words[size_t(word)], false});
            cursor = b;
        }
        i = j;
    }
    if (cursor < end - 1e-9)
        result.words.intervals.push_back(Interval{cursor, end, std::string(PhoneSet::kSilenceLabel), false});
    return result;
}

} // namespace

AlignmentResult SphinxAligner::align(const std::vector<float> &samples, const std::vector<std::string> &words,
                                     const std::vector<std::vector<Pronunciation>> &pronunciations,
                                     double audioDuration, Feedback &feedback, double *transcriptFit) const
{
    if (words.empty() || pronunciations.size() != words.size())
        throw Error("the transcript has no words to align");
    if (std::any_of(pronunciations.begin(), pronunciations.end(), silenceOnly)) {
        std::vector<std::string> spokenWords;
        std::vector<std::vector<Pronunciation>> spokenPronunciations;
        for (size_t w = 0; w < words.size(); ++w)
            if (!silenceOnly(pronunciations[w])) {
                spokenWords.push_back(words[w]);
                spokenPronunciations.push_back(pronunciations[w]);
            }
        return align(samples, spokenWords, spokenPronunciations, audioDuration, feedback, transcriptFit);
    }
    for (size_t w = 0; w < words.size(); ++w)
        if (pronunciations[w].empty() ||
            std::any_of(pronunciations[w].begin(), pronunciations[w].end(), [](const Pronunciation &p) { return p.empty(); }))
            throw Error("no pronunciation for \"" + words[w] + "\"");
    const std::vector<short> pcm = checkedPcm(samples);
    const Graph graph = buildGraph(m_mdef, pronunciations, m_modelDir);
    if (feedback.isCanceled())
        throw Canceled();

    const ObjectPool<SphinxDecoder>::Lease decoder(m_decoders);
    SphinxUtterance utterance(*decoder, pcm);
    GraphViterbi viterbi(graph, m_mdef, utterance);
    const int E = viterbi.statesPerPhone();
    // The beam (3,000 units of 1024 log-base steps, about 300 nats) halves the time and changes
    // nothing on mfa-tests, where 1,500 still found the same path and 800 lost it on a long
    // recording; a lost path is searched again without it.
    constexpr int32_t kBeam = 3000;
    const int passes = m_adaptationPasses + 1;
    auto alignPass = [&](int pass) {
        auto progress = [&](double share) {
            feedback.throwIfCanceled();
            feedback.setProgress(0.95 * (double(pass) + share) / double(passes));
        };
        int best = viterbi.run(kBeam, progress);
        if (best < 0)
            best = viterbi.run(0, progress);
        if (best < 0)
            throw Error("the transcript does not fit the audio (no alignment path reaches the end of the transcript)");
        return best;
    };
    int best = alignPass(0);
    std::vector<int> path = viterbi.path(best);
    for (int pass = 1; pass < passes; ++pass) {
        // Align, adapt, re-align (SphinxAdaptation): the statistics of the last path, the model's
        // Gaussians transformed, and every frame scored again. An identity transform reproduces
        // the unadapted alignment exactly (checked on mfa-tests). mfa-tests: 78.5 % -> 80.7 % of
        // phone boundaries within 25 ms of MFA with one pass; 79.5 % with two, 79.4 % with three
        // (BM_EvalMfaPhones/6; docs/performance.md).
        SphinxAdaptation statistics(codebooks(*decoder));
        for (int t = 0; t < utterance.frames(); ++t) {
            const int state = path[size_t(t)];
            const Graph::Node &n = graph.nodes[size_t(state / E)];
            statistics.addFrame(utterance.features(t), viterbi.senoneOf(size_t(state)), m_mdef.ciPhone(sphinxPhone(n.label)));
        }
        utterance.applyTransform(SphinxAdaptation::pocketsphinxText(statistics.transforms()));
        best = alignPass(pass);
        path = viterbi.path(best);
    }

    const double end = std::max({audioDuration, double(samples.size()) / kSampleRate, utterance.frames() * SphinxDecoder::kFrameSeconds});
    AlignmentResult result = tiersOfPath(graph, E, path, words, end);
    result.frames = utterance.frames();
    // Back to natural-log likelihood (costs are in the log base's units >> 10), relative to the
    // best senone scored in each frame.
    const double natsPerCost = double(1 << SphinxDecoder::kScoreShift) * std::log(decoder->logBase());
    result.logLikelihood = -double(viterbi.cost(best)) * natsPerCost;
    if (transcriptFit) {
        // As our aligner's fit (MonophoneAligner): the forced path against each frame's best
        // state alone, a free recognition without a grammar; here over the frames the path
        // speaks in, as the silences are the same whatever the words (on GRID s1 82.8 % of
        // swapped transcripts caught at 1.25 % of true ones, against 71 % over every frame).
        // Scored over every senone, a frame's costs are relative to the best of all, so the
        // path's own cost is the gap.
        std::vector<int> all(size_t(m_mdef.senoneCount()));
        std::iota(all.begin(), all.end(), 0);
        double gap = 0;
        int spoken = 0;
        for (int t = 0; t < utterance.frames(); ++t) {
            if (t % 100 == 0)
                feedback.throwIfCanceled();
            const int state = path[size_t(t)];
            if (graph.nodes[size_t(state / E)].label == PhoneSet::kSilence)
                continue;
            gap += double(utterance.score(t, all)[viterbi.senoneOf(size_t(state))]);
            ++spoken;
        }
        if (spoken > 0)
            *transcriptFit = -gap * natsPerCost / double(spoken);
    }
    feedback.setProgress(1.0);
    return result;
}

AlignerOutput SphinxAligner::align(const RecordingSound &sound, const std::vector<std::string> &words,
                                   const Lexicon &lexicon, Feedback &feedback, const std::string &transcriptPath) const
{
    const std::string &mediaPath = sound.path();
    std::vector<std::vector<Pronunciation>> pronunciations;
    AudioBuffer audio;
    try {
        // Its Viterbi holds the whole recording's trellis (20 minutes took 24 GB).
        if (const double seconds = MediaInfo::probe(mediaPath).audioDuration; seconds > kLongRecordingSeconds)
            throw Error("CMU Sphinx aligns recordings of up to " + std::to_string(int(kLongRecordingSeconds / 60))
                        + " min, this one has " + std::to_string(int(seconds / 60))
                        + " min: align it with our aligner (the default, any length), or split it into "
                          "utterances first (lipsync project import-long)");
        audio = *sound.at(kSampleRate);
        checkWordsFitAudio(words, audio.duration(), SphinxDecoder::kFrameSeconds, mediaPath, transcriptPath);
        pronunciations = lexicon.pronounceAll(words);
    } catch (const Error &e) {
        throw Error(e.reason(), mediaPath, e.field());
    }
    AlignerOutput out;
    out.duration = audio.duration();
    double fit = std::numeric_limits<double>::quiet_NaN();
    try {
        out.alignment = align(audio.samples, words, pronunciations, audio.duration(), feedback,
                              m_measureFit ? &fit : nullptr);
        if (std::isfinite(fit))
            out.transcriptFit = TranscriptFit{fit, kSphinxTranscriptFitThreshold};
    } catch (const Error &e) {
        throw Error(transcriptPath.empty() ? e.reason() : e.reason() + " (transcript " + transcriptPath + ")",
                    mediaPath, e.field());
    }
    return out;
}

AlignerOutput SphinxAligner::realign(const std::string &mediaPath, const Realignment &realignment,
                                     const Lexicon &lexicon, Feedback &feedback) const
{
    AlignerOutput out;
    try {
        const auto pronunciations = lexicon.pronounceAll(realignment.words());
        const AudioBuffer audio = AudioDecoder::decode(mediaPath, kSampleRate);
        out.alignment = realignment.runPiecewise(*this, audio.samples, pronunciations, feedback);
        out.duration = audio.duration();
    } catch (const Error &e) {
        throw Error(e.reason(), e.file().empty() ? mediaPath : e.file(), e.field());
    }
    return out;
}

} // namespace lipsync
