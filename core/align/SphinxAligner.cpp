#include "align/SphinxAligner.h"

#include "align/SphinxAdaptation.h"
#include "align/SphinxCodebooks.h"
#include "io/AudioDecoder.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <pocketsphinx.h>
#include <sphinxbase/err.h>
#include <sphinxbase/feat.h>

#include <QTemporaryFile>

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <filesystem>

// libpocketsphinx's acoustic model (senone scoring): exported by the library but declared only in
// its private acmod.h, which Debian does not install. These are pocketsphinx 0.8+5prealpha's
// signatures (the version scripts/setup installs, libpocketsphinx3); pinned here by hand.
extern "C" {
typedef struct acmod_s acmod_t;
acmod_t *acmod_init(cmd_ln_t *config, logmath_t *lmath, fe_t *fe, feat_t *fcb);
void acmod_free(acmod_t *acmod);
int acmod_set_grow(acmod_t *acmod, int grow_feat);
int acmod_start_utt(acmod_t *acmod);
int acmod_end_utt(acmod_t *acmod);
int acmod_process_raw(acmod_t *acmod, int16 const **inout_raw, size_t *inout_n_samps, int full_utt);
// The senone scores of frame *inout_frame_idx (absolute, with acmod_set_grow): costs, 0 for the
// frame's best senone, in the log base's units shifted right by 10 (SENSCR_SHIFT).
int16 const *acmod_score(acmod_t *acmod, int *inout_frame_idx);
// The feature vectors (one array per stream) of frame *inout_frame_idx.
mfcc_t **acmod_get_frame(acmod_t *acmod, int *inout_frame_idx);
// Transforms the model's Gaussians (ps_mllr_read's transform; the scorer takes ownership).
ps_mllr_t *acmod_update_mllr(acmod_t *acmod, ps_mllr_t *mllr);
// Empties the set of senones acmod_score computes when -compallsen is off.
void acmod_clear_active(acmod_t *acmod);
}

namespace {

// The start of 0.8+5prealpha's struct acmod_s, as far as its bit set of active senones (private
// too; acmod_activate_hmm would need pocketsphinx's HMM structs). Checked against the pointers
// acmod_init was given before it is used.
struct AcmodPrefix
{
    cmd_ln_t *config;
    logmath_t *lmath;
    void *strings, *fe, *fcb, *mdef, *tmat, *mgau, *mllr;
    int16 *senoneScores;
    uint32_t *senoneActiveVec; // sphinxbase bitvec_t: 32 senones per word
};

} // namespace

namespace lipsync {

struct SphinxAligner::Decoder
{
    ps_decoder_t *ps = nullptr; // the expanded configuration and the log table
    ~Decoder() { ps_free(ps); }
};

namespace {

constexpr int kSenoneShift = 10; // pocketsphinx's SENSCR_SHIFT

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
    if (const char *env = std::getenv("LIPSYNC_SPHINX_MODEL"); env && *env)
        return env;
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
      m_extra(std::move(options.extraArguments)), m_adaptationPasses(std::max(0, options.adaptationPasses))
{
    if (m_mdef.silence() < 0 || m_mdef.ciName(m_mdef.silence()) != "SIL")
        throw Error("the CMU Sphinx model definition has no SIL phone", m_modelDir + "/mdef");
}

SphinxAligner::~SphinxAligner() = default;

SphinxAligner::Decoder *SphinxAligner::acquire() const
{
    {
        const std::lock_guard lock(m_mutex);
        if (!m_free.empty()) {
            Decoder *d = m_free.back();
            m_free.pop_back();
            return d;
        }
    }
    std::vector<std::string> args{"lipsync", "-hmm", m_modelDir};
    for (const auto &[name, value] : baseArguments())
        args.insert(args.end(), {name, value});
    for (const auto &[name, value] : m_extra)
        args.insert(args.end(), {name, value});
    std::vector<char *> argv;
    for (std::string &a : args)
        argv.push_back(a.data());
    // pocketsphinx's log is one process-wide FILE: silenced once, before the first decoder, and
    // never touched again. Not per decoder (-logfn /dev/null, or an err_set_logfp of its own):
    // err_set_logfp fcloses the FILE it replaces, so one thread could close the log another
    // thread's ps_init has just opened and is writing to, and concurrent decoders hang.
    static std::once_flag silenced;
    std::call_once(silenced, [] { err_set_logfp(nullptr); });
    cmd_ln_t *config = cmd_ln_parse_r(nullptr, ps_args(), int(argv.size()), argv.data(), FALSE);
    if (!config)
        throw Error("invalid pocketsphinx options", m_modelDir);
    // The decoder expands the model folder into the model's files and feature options (the
    // senone scorers are made from its configuration).
    ps_decoder_t *decoder = ps_init(config);
    cmd_ln_free_r(config); // the decoder keeps its own reference
    if (!decoder)
        throw Error("cannot load the CMU Sphinx acoustic model", m_modelDir);
    auto owned = std::make_unique<Decoder>();
    owned->ps = decoder;
    const std::lock_guard lock(m_mutex);
    m_all.push_back(std::move(owned));
    return m_all.back().get();
}

void SphinxAligner::release(Decoder *decoder) const
{
    const std::lock_guard lock(m_mutex);
    m_free.push_back(decoder);
}

const SphinxCodebooks &SphinxAligner::codebooks(Decoder *decoder) const
{
    std::call_once(m_codebooksOnce, [&] {
        m_codebooks = std::make_unique<SphinxCodebooks>(
            SphinxCodebooks::read(m_modelDir, m_mdef.senoneCount(), logmath_get_base(ps_get_logmath(decoder->ps)),
                                  cmd_ln_float32_r(ps_get_config(decoder->ps), "-varfloor")));
    });
    if (m_codebooks->codebooks() != m_mdef.ciPhoneCount())
        throw Error("not a phonetically-tied-mixture model (one codebook per CI phone): cannot adapt it", m_modelDir);
    return *m_codebooks;
}

AlignmentResult SphinxAligner::align(const std::vector<float> &samples, const std::vector<std::string> &words,
                                     const std::vector<std::vector<Pronunciation>> &pronunciations,
                                     double audioDuration, Feedback *feedback) const
{
    if (words.empty() || pronunciations.size() != words.size())
        throw Error("the transcript has no words to align");
    // Silence tokens of a transcript ("sil", "sp": pronounced as silence) are the graph's
    // optional silences already, and the result's word tier marks every silence "sil".
    auto silenceOnly = [](const std::vector<Pronunciation> &variants) {
        return !variants.empty() && std::all_of(variants.begin(), variants.end(), [](const Pronunciation &v) {
            return !v.empty() && std::all_of(v.begin(), v.end(), [](int p) { return p == PhoneSet::kSilence; });
        });
    };
    if (std::any_of(pronunciations.begin(), pronunciations.end(), silenceOnly)) {
        std::vector<std::string> spokenWords;
        std::vector<std::vector<Pronunciation>> spokenPronunciations;
        for (size_t w = 0; w < words.size(); ++w)
            if (!silenceOnly(pronunciations[w])) {
                spokenWords.push_back(words[w]);
                spokenPronunciations.push_back(pronunciations[w]);
            }
        return align(samples, spokenWords, spokenPronunciations, audioDuration, feedback);
    }
    for (size_t w = 0; w < words.size(); ++w)
        if (pronunciations[w].empty() ||
            std::any_of(pronunciations[w].begin(), pronunciations[w].end(), [](const Pronunciation &p) { return p.empty(); }))
            throw Error("no pronunciation for \"" + words[w] + "\"");
    if (samples.empty())
        throw Error("the audio is empty");
    float peak = 0;
    for (float v : samples)
        peak = std::max(peak, std::abs(v));
    // -80 dBFS (as prepareUtterance): nothing to align words to.
    if (peak < 1e-4f)
        throw Error("the audio is silent");

    const Graph graph = buildGraph(m_mdef, pronunciations, m_modelDir);
    std::vector<int16_t> pcm(samples.size());
    for (size_t i = 0; i < samples.size(); ++i)
        pcm[i] = int16_t(std::lround(std::clamp(samples[i], -1.0f, 1.0f) * 32767.0f));
    if (feedback && feedback->isCanceled())
        throw Canceled();

    Decoder *decoder = acquire();
    struct Lease
    {
        const SphinxAligner *owner;
        Decoder *decoder;
        ~Lease() { owner->release(decoder); }
    } lease{this, decoder};
    // A scorer with a front end of its own for each utterance: the front end's noise estimate
    // (-remove_noise), the cepstral mean and the Gaussian selection (-topn, started from the
    // previous frame's best) all carry over between utterances, so a reused one would give
    // results depending on what it aligned before (a 10 ms shift in the tests).
    const std::unique_ptr<acmod_t, void (*)(acmod_t *)> scorer(
        acmod_init(ps_get_config(decoder->ps), ps_get_logmath(decoder->ps), nullptr, nullptr), &acmod_free);
    acmod_t *acmod = scorer.get();
    if (!acmod)
        throw Error("cannot load the CMU Sphinx acoustic model's senones", m_modelDir);
    // Every frame's features stay, so that any frame can be scored after the whole utterance.
    acmod_set_grow(acmod, TRUE);
    const AcmodPrefix *acmodFields = reinterpret_cast<const AcmodPrefix *>(acmod);
    if (acmodFields->config != ps_get_config(decoder->ps) || acmodFields->lmath != ps_get_logmath(decoder->ps) ||
        !acmodFields->senoneActiveVec)
        throw Error("unsupported libpocketsphinx version (its acoustic model differs from 0.8+5prealpha's)");
    if (acmod_start_utt(acmod) < 0)
        throw Error("pocketsphinx could not start the utterance");
    const int16 *raw = pcm.data();
    size_t remaining = pcm.size();
    // The whole utterance at once (full_utt), as the batch front end of a forced aligner.
    const int processed = acmod_process_raw(acmod, &raw, &remaining, TRUE);
    acmod_end_utt(acmod);
    if (processed <= 0)
        throw Error("the audio is too short to align");
    const int T = processed;

    // Viterbi over the graph's states (node * E + emitting state), left to right with self-loops
    // and no transition probabilities; costs are the senone scores (0 = the best senone scored
    // in that frame: a per-frame constant, the same for every path).
    const int E = m_mdef.statesPerPhone();
    const size_t S = graph.nodes.size() * size_t(E);
    constexpr int32_t kInf = INT32_MAX / 2;
    std::vector<int32_t> cur(S), nxt(S);
    std::vector<int32_t> back(size_t(T) * S);
    std::vector<const uint16_t *> senones(graph.nodes.size());
    for (size_t n = 0; n < graph.nodes.size(); ++n)
        senones[n] = m_mdef.senones(graph.nodes[n].phone);
    auto senoneOf = [&](size_t s) { return int(senones[s / size_t(E)][s % size_t(E)]); };
    // Scores frame t's senones of the states reached (next[s] < kInf) only: the Gaussian
    // mixtures are nearly all of the time (all 5,126 senones per frame: 0.11 x real time on
    // mfa-tests, one thread; these: 0.047, and 0.027 with the beam).
    auto scores = [&](int t, const std::vector<int32_t> &next) {
        acmod_clear_active(acmod);
        for (size_t s = 0; s < S; ++s)
            if (next[s] < kInf) {
                const int senone = senoneOf(s);
                acmodFields->senoneActiveVec[senone / 32] |= uint32_t(1) << (senone % 32);
            }
        int frame = t;
        const int16 *sc = acmod_score(acmod, &frame);
        if (!sc || frame != t)
            throw Error("pocketsphinx could not score frame " + std::to_string(t));
        return sc;
    };
    // One pass; states costlier than the frame's best by more than `beam` (0: none) are dropped.
    // Returns the best final state, or -1 when no path survived.
    int passesDone = 0; // alignment passes before this one (adaptation)
    auto viterbi = [&](int32_t beam) {
        std::fill(cur.begin(), cur.end(), kInf);
        for (int e : graph.entries)
            cur[size_t(e) * size_t(E)] = 0;
        for (int t = 0; t < T; ++t) {
            if (feedback && t % 50 == 0) {
                if (feedback->isCanceled())
                    throw Canceled();
                feedback->setProgress(0.95 * (double(passesDone) + double(t) / double(T)) / double(m_adaptationPasses + 1));
            }
            if (t > 0) {
                std::fill(nxt.begin(), nxt.end(), kInf);
                int32_t *b = &back[size_t(t) * S];
                auto relax = [&](size_t to, int32_t cost, size_t from) {
                    if (cost < nxt[to]) {
                        nxt[to] = cost;
                        b[to] = int32_t(from);
                    }
                };
                for (size_t s = 0; s < S; ++s) {
                    const int32_t c = cur[s];
                    if (c >= kInf)
                        continue;
                    relax(s, c, s);
                    const size_t node = s / size_t(E), k = s % size_t(E);
                    if (k + 1 < size_t(E))
                        relax(s + 1, c, s);
                    else
                        for (int m : graph.nodes[node].next)
                            relax(size_t(m) * size_t(E), c, s);
                }
                std::swap(cur, nxt);
            }
            const int16 *sc = scores(t, cur);
            int32_t frameBest = kInf;
            for (size_t s = 0; s < S; ++s)
                if (cur[s] < kInf) {
                    cur[s] += sc[senoneOf(s)];
                    frameBest = std::min(frameBest, cur[s]);
                }
            if (beam > 0)
                for (int32_t &c : cur)
                    if (c > frameBest + beam)
                        c = kInf;
        }
        int best = -1;
        for (int f : graph.finals) {
            const size_t s = size_t(f) * size_t(E) + size_t(E) - 1;
            if (cur[s] < kInf && (best < 0 || cur[s] < cur[size_t(best)]))
                best = int(s);
        }
        return best;
    };
    // The beam (3,000 units of 1024 log-base steps, about 300 nats) halves the time and changes
    // nothing on mfa-tests, where 1,500 still found the same path and 800 lost it on a long
    // recording; a lost path is searched again without it.
    constexpr int32_t kBeam = 3000;
    std::vector<int> path(static_cast<size_t>(T));
    int best = -1;
    auto align = [&] {
        best = viterbi(kBeam);
        if (best < 0)
            best = viterbi(0);
        if (best < 0)
            throw Error("the transcript does not fit the audio (no alignment path reaches the end of the transcript)");
        path[size_t(T) - 1] = best;
        for (int t = T - 1; t > 0; --t)
            path[size_t(t) - 1] = back[size_t(t) * S + size_t(path[size_t(t)])];
    };
    align();
    for (int adaptation = 0; adaptation < m_adaptationPasses; ++adaptation) {
        // Align, adapt, re-align (SphinxAdaptation): the statistics of the last path, the model's
        // Gaussians transformed (pocketsphinx reloads them from the model files and applies the
        // transform; it reads transforms from files only), and every frame scored again. An
        // identity transform reproduces the unadapted alignment exactly (checked on mfa-tests).
        // mfa-tests: 78.5 % -> 80.7 % of phone boundaries within 25 ms of MFA with one pass;
        // 79.5 % with two, 79.4 % with three (BM_EvalMfaPhones/6; docs/performance.md).
        SphinxAdaptation statistics(codebooks(decoder));
        for (int t = 0; t < T; ++t) {
            int frame = t;
            mfcc_t **features = acmod_get_frame(acmod, &frame);
            if (!features || frame != t)
                throw Error("pocketsphinx lost the features of frame " + std::to_string(t));
            const Graph::Node &n = graph.nodes[size_t(path[size_t(t)] / E)];
            statistics.addFrame(features, senoneOf(size_t(path[size_t(t)])), m_mdef.ciPhone(sphinxPhone(n.label)));
        }
        QTemporaryFile file;
        if (!file.open())
            throw Error("cannot write the speaker adaptation transform to " + file.fileName().toStdString());
        const std::string text = SphinxAdaptation::pocketsphinxText(statistics.transforms());
        file.write(text.data(), qint64(text.size()));
        file.close();
        ps_mllr_t *mllr = ps_mllr_read(file.fileName().toLocal8Bit().constData());
        if (!mllr)
            throw Error("pocketsphinx could not read the speaker adaptation transform");
        acmod_update_mllr(acmod, mllr);
        ++passesDone;
        align();
    }

    struct Segment
    {
        int label; // PhoneSet index
        int word;  // transcript word, -1 for silence
        int start; // first frame
    };
    std::vector<Segment> segments;
    for (int t = 0, previous = -1; t < T; ++t) {
        const int node = path[size_t(t)] / E;
        const Graph::Node &n = graph.nodes[size_t(node)];
        const bool enters = node != previous && path[size_t(t)] % E == 0;
        previous = node;
        if (!enters)
            continue;
        if (n.word < 0 && !segments.empty() && segments.back().word < 0)
            continue; // adjacent silences are one segment
        segments.push_back({n.label, n.word, t});
    }

    AlignmentResult result;
    result.frames = T;
    // Back to natural-log likelihood (costs are in the log base's units >> 10), relative to the
    // best senone scored in each frame.
    result.logLikelihood = -double(cur[size_t(best)]) * double(1 << kSenoneShift) *
                           std::log(logmath_get_base(ps_get_logmath(decoder->ps)));
    const double shift = 0.01; // pocketsphinx's frame rate, 100 Hz
    const double end = std::max({audioDuration, double(samples.size()) / kSampleRate, T * shift});
    // Segment i spans [its first frame, the next segment's); the first starts at 0, the last
    // ends with the audio (as ForcedAligner's HTK convention).
    auto startOf = [&](size_t i) { return i == 0 ? 0.0 : segments[i].start * shift; };
    auto endOf = [&](size_t i) { return i + 1 < segments.size() ? segments[i + 1].start * shift : end; };
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
    if (feedback)
        feedback->setProgress(1.0);
    return result;
}

AlignmentResult SphinxAligner::align(const std::string &mediaPath, const std::vector<std::string> &words,
                                     const Lexicon &lexicon, Feedback *feedback) const
{
    try {
        const auto pronunciations = lexicon.pronounceAll(words);
        const AudioBuffer audio = AudioDecoder::decode(mediaPath, kSampleRate);
        return align(audio.samples, words, pronunciations, audio.duration(), feedback);
    } catch (const Error &e) {
        throw Error(e.reason(), mediaPath, e.field());
    }
}

} // namespace lipsync
