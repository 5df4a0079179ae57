#include "align/SphinxBackend.h"

#include "util/Error.h"

#include <pocketsphinx.h>
#include <sphinxbase/err.h>
#include <sphinxbase/feat.h>

#include <QTemporaryFile>

#include <algorithm>
#include <cmath>

#include <mutex>
#include <type_traits>

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

static_assert(std::is_same_v<int16, short> && std::is_same_v<mfcc_t, float>,
              "SphinxBackend.h speaks pocketsphinx's int16 and floating-point mfcc_t");

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

std::vector<short> toPcm16(const float *samples, size_t count)
{
    std::vector<short> pcm(count);
    for (size_t i = 0; i < count; ++i)
        pcm[i] = short(std::lround(std::clamp(samples[i], -1.0f, 1.0f) * 32767.0f));
    return pcm;
}

std::vector<short> toPcm16(const std::vector<float> &samples)
{
    return toPcm16(samples.data(), samples.size());
}

struct SphinxDecoder::Impl
{
    ps_decoder_t *ps = nullptr;
    ~Impl() { ps_free(ps); }
};

SphinxDecoder::SphinxDecoder(const std::string &modelDir,
                             const std::vector<std::pair<std::string, std::string>> &arguments)
    : m_impl(std::make_unique<Impl>())
{
    std::vector<std::string> args{"lipsync", "-hmm", modelDir};
    for (const auto &[name, value] : arguments)
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
        throw Error("invalid pocketsphinx options", modelDir);
    // The decoder expands the model folder into the model's files and feature options (the
    // senone scorers are made from its configuration).
    m_impl->ps = ps_init(config);
    cmd_ln_free_r(config); // the decoder keeps its own reference
    if (!m_impl->ps)
        throw Error("cannot load the CMU Sphinx acoustic model", modelDir);
}

SphinxDecoder::~SphinxDecoder() = default;

double SphinxDecoder::logBase() const
{
    return logmath_get_base(ps_get_logmath(m_impl->ps));
}

float SphinxDecoder::varianceFloor() const
{
    return cmd_ln_float32_r(ps_get_config(m_impl->ps), "-varfloor");
}

std::vector<SphinxDecoder::Word> SphinxDecoder::recognize(const std::vector<short> &pcm) const
{
    ps_decoder_t *ps = m_impl->ps;
    if (ps_start_utt(ps) < 0)
        throw Error("pocketsphinx could not start the utterance");
    if (ps_process_raw(ps, pcm.data(), pcm.size(), FALSE, TRUE) < 0) {
        ps_end_utt(ps);
        throw Error("pocketsphinx could not decode the audio");
    }
    ps_end_utt(ps);
    // The lattice's posteriors (ps_get_prob runs forward-backward over it); each segment of the
    // best path then carries its word's posterior (ps_seg_prob, log base of the decoder's logmath).
    const bool posteriors = ps_get_lattice(ps) != nullptr;
    if (posteriors)
        ps_get_prob(ps);
    logmath_t *lmath = ps_get_logmath(ps);
    std::vector<Word> words;
    for (ps_seg_t *seg = ps_seg_iter(ps); seg; seg = ps_seg_next(seg)) {
        const std::string word = ps_seg_word(seg);
        if (word.empty() || word.front() == '<' || word.front() == '[')
            continue; // sentence marks, silence, noise
        Word w;
        // Alternative pronunciations are spelt "word(2)".
        w.word = word.substr(0, word.find('('));
        ps_seg_frames(seg, &w.first, &w.last);
        if (posteriors) {
            int32 acoustic = 0, language = 0, backoff = 0;
            w.confidence = std::clamp(logmath_exp(lmath, ps_seg_prob(seg, &acoustic, &language, &backoff)), 0.0, 1.0);
        }
        words.push_back(std::move(w));
    }
    return words;
}

struct SphinxUtterance::Impl
{
    std::unique_ptr<acmod_t, void (*)(acmod_t *)> acmod{nullptr, &acmod_free};
    uint32_t *active = nullptr; // the acmod's bit set of senones to score
};

SphinxUtterance::SphinxUtterance(const SphinxDecoder &decoder, const std::vector<short> &pcm)
    : m_impl(std::make_unique<Impl>())
{
    ps_decoder_t *ps = decoder.m_impl->ps;
    m_impl->acmod.reset(acmod_init(ps_get_config(ps), ps_get_logmath(ps), nullptr, nullptr));
    acmod_t *acmod = m_impl->acmod.get();
    if (!acmod)
        throw Error("pocketsphinx could not load the acoustic model's senones");
    const AcmodPrefix *fields = reinterpret_cast<const AcmodPrefix *>(acmod);
    if (fields->config != ps_get_config(ps) || fields->lmath != ps_get_logmath(ps) || !fields->senoneActiveVec)
        throw Error("unsupported libpocketsphinx version (its acoustic model differs from 0.8+5prealpha's)");
    m_impl->active = fields->senoneActiveVec;
    // Every frame's features stay, so that any frame can be scored after the whole utterance.
    acmod_set_grow(acmod, TRUE);
    if (acmod_start_utt(acmod) < 0)
        throw Error("pocketsphinx could not start the utterance");
    const int16 *raw = pcm.data();
    size_t remaining = pcm.size();
    const int processed = acmod_process_raw(acmod, &raw, &remaining, TRUE);
    acmod_end_utt(acmod);
    if (processed <= 0)
        throw Error("the audio is too short to align");
    m_frames = processed;
}

SphinxUtterance::~SphinxUtterance() = default;

const short *SphinxUtterance::score(int t, const std::vector<int> &senones)
{
    acmod_clear_active(m_impl->acmod.get());
    for (int senone : senones)
        m_impl->active[senone / 32] |= uint32_t(1) << (senone % 32);
    int frame = t;
    const int16 *scores = acmod_score(m_impl->acmod.get(), &frame);
    if (!scores || frame != t)
        throw Error("pocketsphinx could not score frame " + std::to_string(t));
    return scores;
}

const float *const *SphinxUtterance::features(int t)
{
    int frame = t;
    mfcc_t **f = acmod_get_frame(m_impl->acmod.get(), &frame);
    if (!f || frame != t)
        throw Error("pocketsphinx lost the features of frame " + std::to_string(t));
    return f;
}

void SphinxUtterance::applyTransform(const std::string &pocketsphinxText)
{
    // pocketsphinx reads transforms from files only; it reloads the model's Gaussians from the
    // model files and applies the transform.
    QTemporaryFile file;
    if (!file.open())
        throw Error("cannot write the speaker adaptation transform to " + file.fileName().toStdString());
    file.write(pocketsphinxText.data(), qint64(pocketsphinxText.size()));
    file.close();
    ps_mllr_t *mllr = ps_mllr_read(file.fileName().toLocal8Bit().constData());
    if (!mllr)
        throw Error("pocketsphinx could not read the speaker adaptation transform");
    acmod_update_mllr(m_impl->acmod.get(), mllr);
}

struct SphinxPhoneLoop::Impl
{
    ps_decoder_t *ps = nullptr;
    bool running = false;
    ~Impl()
    {
        if (running)
            ps_end_utt(ps);
        ps_free(ps);
    }
};

SphinxPhoneLoop::SphinxPhoneLoop(const std::string &modelDir, const std::string &phoneLm,
                                 const std::vector<std::pair<std::string, std::string>> &arguments)
    : m_impl(std::make_unique<Impl>())
{
    std::vector<std::pair<std::string, std::string>> all{
        {"-allphone", phoneLm}, {"-allphone_ci", "yes"}, {"-remove_silence", "no"}, {"-remove_noise", "no"},
        {"-cmn", "prior"}};
    all.insert(all.end(), arguments.begin(), arguments.end());
    // The same configuration as SphinxDecoder's (log silenced once, the model folder expanded).
    SphinxDecoder probe(modelDir, all);
    std::swap(m_impl->ps, probe.m_impl->ps);
}

SphinxPhoneLoop::~SphinxPhoneLoop() = default;

void SphinxPhoneLoop::start()
{
    if (m_impl->running)
        ps_end_utt(m_impl->ps);
    m_impl->running = ps_start_utt(m_impl->ps) >= 0;
    if (!m_impl->running)
        throw Error("pocketsphinx could not start the utterance");
}

void SphinxPhoneLoop::process(const short *pcm, size_t count)
{
    if (!m_impl->running)
        start();
    if (count > 0 && ps_process_raw(m_impl->ps, pcm, count, FALSE, FALSE) < 0)
        throw Error("pocketsphinx could not decode the audio");
}

void SphinxPhoneLoop::end()
{
    if (m_impl->running)
        ps_end_utt(m_impl->ps);
    m_impl->running = false;
}

int SphinxPhoneLoop::frames() const
{
    return ps_get_n_frames(m_impl->ps);
}

std::vector<SphinxPhoneLoop::Segment> SphinxPhoneLoop::segments() const
{
    std::vector<Segment> out;
    for (ps_seg_t *seg = ps_seg_iter(m_impl->ps); seg; seg = ps_seg_next(seg)) {
        Segment s;
        s.phone = ps_seg_word(seg);
        ps_seg_frames(seg, &s.first, &s.last);
        out.push_back(std::move(s));
    }
    // Debian's pocketsphinx (5prealpha) numbers an utterance's frames on from the decoder's
    // earlier utterances; the path starts at the utterance's first frame.
    if (!out.empty() && out.front().first != 0) {
        const int offset = out.front().first;
        for (Segment &s : out) {
            s.first -= offset;
            s.last -= offset;
        }
    }
    return out;
}

} // namespace lipsync

