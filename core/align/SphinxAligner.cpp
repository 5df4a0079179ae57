#include "align/SphinxAligner.h"

#include "io/AudioDecoder.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <pocketsphinx.h>
#include <sphinxbase/cmn.h>
#include <sphinxbase/err.h>
#include <sphinxbase/feat.h>
#include <sphinxbase/jsgf.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <functional>

namespace lipsync {

struct SphinxAligner::Decoder
{
    ps_decoder_t *ps = nullptr;
    std::vector<mfcc_t> initialMean; // -cmninit, restored before each utterance
    ~Decoder() { ps_free(ps); }
};

namespace {

// The grammar's phone-words: ph_<label> -> the model's phone. Breath is the model's noise phone.
std::string phoneWord(int phone)
{
    if (phone == PhoneSet::kSilence)
        return "silw";
    return "ph_" + PhoneSet::label(phone);
}

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

// The options that make pocketsphinx a forced aligner (the lead's feasibility test, issue 4):
// keep every frame (its default voice-activity detection drops silent frames and shifts all
// times), search without pruning, no second pass.
const std::vector<std::pair<std::string, std::string>> &baseArguments()
{
    static const std::vector<std::pair<std::string, std::string>> args{
        {"-remove_silence", "no"}, {"-beam", "1e-100"}, {"-pbeam", "1e-100"}, {"-wbeam", "1e-80"},
        {"-lpbeam", "1e-100"},     {"-maxhmmpf", "-1"}, {"-maxwpf", "-1"},    {"-topn", "64"},
        {"-bestpath", "no"},       {"-fwdflat", "no"},  {"-fsgusefiller", "no"}, {"-logfn", "/dev/null"},
    };
    return args;
}

// Word i of the transcript covers phone-words [start, end) of the decoded sequence: the parse of
// the phone sequence into the words' variants (a memoised search; the grammar guarantees one).
std::vector<std::pair<size_t, size_t>> parseWords(const std::vector<int> &phones,
                                                  const std::vector<std::vector<Pronunciation>> &pronunciations)
{
    const size_t W = pronunciations.size(), P = phones.size();
    std::vector<std::vector<signed char>> memo(W + 1, std::vector<signed char>(P + 1, -1));
    std::vector<std::vector<size_t>> choice(W + 1, std::vector<size_t>(P + 1, 0));
    std::function<bool(size_t, size_t)> fits = [&](size_t w, size_t p) -> bool {
        if (w == W)
            return p == P;
        if (memo[w][p] >= 0)
            return memo[w][p] == 1;
        bool ok = false;
        for (const Pronunciation &v : pronunciations[w]) {
            if (p + v.size() > P || !std::equal(v.begin(), v.end(), phones.begin() + long(p)))
                continue;
            if (fits(w + 1, p + v.size())) {
                choice[w][p] = v.size();
                ok = true;
                break;
            }
        }
        memo[w][p] = ok ? 1 : 0;
        return ok;
    };
    if (!fits(0, 0))
        throw Error("the aligned phones do not spell the transcript (internal error)");
    std::vector<std::pair<size_t, size_t>> spans;
    for (size_t w = 0, p = 0; w < W; ++w) {
        spans.emplace_back(p, p + choice[w][p]);
        p += choice[w][p];
    }
    return spans;
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

SphinxAligner::SphinxAligner(Options options)
    : m_modelDir(resolveModelDir(options.modelDir)), m_extra(std::move(options.extraArguments))
{
    if (!available(m_modelDir))
        throw Error(std::filesystem::exists(m_modelDir)
                        ? "not a CMU Sphinx acoustic model folder (no mdef file)"
                        : "the CMU Sphinx acoustic model folder does not exist (Debian package pocketsphinx-en-us)",
                    m_modelDir);
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
    // pocketsphinx logs to stderr until -logfn takes effect: silence it from the start.
    err_set_logfp(nullptr);
    cmd_ln_t *config = cmd_ln_parse_r(nullptr, ps_args(), int(argv.size()), argv.data(), FALSE);
    if (!config)
        throw Error("invalid pocketsphinx options", m_modelDir);
    ps_decoder_t *decoder = ps_init(config);
    cmd_ln_free_r(config); // the decoder keeps its own reference
    if (!decoder)
        throw Error("cannot load the CMU Sphinx acoustic model", m_modelDir);
    // The phone-words, once per decoder.
    bool ok = true;
    for (int p = 0; p < PhoneSet::kCount; ++p)
        ok = ok && ps_add_word(decoder, phoneWord(p).c_str(), sphinxPhone(p).c_str(), p + 1 == PhoneSet::kCount) >= 0;
    if (!ok) {
        ps_free(decoder);
        throw Error("the CMU Sphinx model lacks a phone of the ARPAbet set", m_modelDir);
    }
    auto owned = std::make_unique<Decoder>();
    owned->ps = decoder;
    const cmn_t *cmn = ps_get_feat(decoder)->cmn_struct;
    owned->initialMean.assign(cmn->cmn_mean, cmn->cmn_mean + cmn->veclen);
    const std::lock_guard lock(m_mutex);
    m_all.push_back(std::move(owned));
    return m_all.back().get();
}

void SphinxAligner::release(Decoder *decoder) const
{
    const std::lock_guard lock(m_mutex);
    m_free.push_back(decoder);
}

AlignmentResult SphinxAligner::align(const std::vector<float> &samples, const std::vector<std::string> &words,
                                     const std::vector<std::vector<Pronunciation>> &pronunciations,
                                     double audioDuration, Feedback *feedback) const
{
    if (words.empty() || pronunciations.size() != words.size())
        throw Error("the transcript has no words to align");
    // Silence tokens of a transcript ("sil", "sp": pronounced as silence) are the grammar's
    // optional silences already, and the result's word tier marks every silence "sil".
    auto silenceOnly = [](const std::vector<Pronunciation> &variants) {
        return !variants.empty() && std::all_of(variants.begin(), variants.end(), [](const Pronunciation &v) {
            return std::all_of(v.begin(), v.end(), [](int p) { return p == PhoneSet::kSilence; });
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
        if (pronunciations[w].empty() || pronunciations[w].front().empty())
            throw Error("no pronunciation for \"" + words[w] + "\"");
    if (samples.empty())
        throw Error("the audio is empty");
    float peak = 0;
    for (float v : samples)
        peak = std::max(peak, std::abs(v));
    // -80 dBFS (as prepareUtterance): nothing to align words to.
    if (peak < 1e-4f)
        throw Error("the audio is silent");

    // The grammar: [silw] word0 [silw] word1 ... [silw], a word being its variants in parallel.
    std::string jsgf = "#JSGF V1.0;\ngrammar align;\npublic <utterance> = [silw]";
    for (const std::vector<Pronunciation> &variants : pronunciations) {
        jsgf += " (";
        for (size_t v = 0; v < variants.size(); ++v) {
            jsgf += v ? " |" : "";
            for (int p : variants[v])
                jsgf += " " + phoneWord(p);
        }
        jsgf += " ) [silw]";
    }
    jsgf += ";\n";

    std::vector<int16_t> pcm(samples.size());
    for (size_t i = 0; i < samples.size(); ++i)
        pcm[i] = int16_t(std::lround(std::clamp(samples[i], -1.0f, 1.0f) * 32767.0f));

    Decoder *decoder = acquire();
    struct Lease
    {
        const SphinxAligner *owner;
        Decoder *decoder;
        ~Lease() { owner->release(decoder); }
    } lease{this, decoder};
    ps_decoder_t *ps = decoder->ps;
    // Live CMN carries its mean over from the decoder's previous utterances: start each one
    // from the model's -cmninit, so that the result does not depend on what was aligned before.
    cmn_live_set(ps_get_feat(ps)->cmn_struct, decoder->initialMean.data());

    // The grammar through sphinxbase's JSGF parser, freed here: libpocketsphinx 5prealpha's
    // ps_set_jsgf_string never frees the parsed grammar (a leak per utterance, found by LSan).
    {
        jsgf_t *grammar = jsgf_parse_string(jsgf.c_str(), nullptr);
        jsgf_rule_t *rule = grammar ? jsgf_get_public_rule(grammar) : nullptr;
        fsg_model_t *fsg = rule ? jsgf_build_fsg(grammar, rule, ps_get_logmath(ps),
                                                 float32(cmd_ln_float32_r(ps_get_config(ps), "-lw")))
                                : nullptr;
        const bool set = fsg && ps_set_fsg(ps, "align", fsg) >= 0 && ps_set_search(ps, "align") >= 0;
        if (fsg)
            fsg_model_free(fsg);
        if (grammar)
            jsgf_grammar_free(grammar);
        if (!set)
            throw Error("pocketsphinx rejected the alignment grammar");
    }
    if (ps_start_utt(ps) < 0)
        throw Error("pocketsphinx could not start the utterance");
    // One second at a time, for progress and cancel.
    const size_t chunk = kSampleRate;
    for (size_t at = 0; at < pcm.size(); at += chunk) {
        if (feedback) {
            if (feedback->isCanceled()) {
                ps_end_utt(ps);
                throw Canceled();
            }
            feedback->setProgress(0.95 * double(at) / double(pcm.size()));
        }
        if (ps_process_raw(ps, pcm.data() + at, std::min(chunk, pcm.size() - at), FALSE, FALSE) < 0) {
            ps_end_utt(ps);
            throw Error("pocketsphinx failed to process the audio");
        }
    }
    ps_end_utt(ps);
    int32 score = 0;
    if (!ps_get_hyp(ps, &score))
        throw Error("the transcript does not fit the audio (no alignment path reaches the end of the transcript)");

    struct Segment
    {
        int phone; // PhoneSet index
        int start; // first frame
    };
    std::vector<Segment> segments;
    // A reused decoder numbers the frames of its FSG search on from the previous utterances
    // (libpocketsphinx 5prealpha), but the path of a forced alignment starts at the utterance's
    // first frame: count from there.
    int offset = -1, frames = 0;
    for (ps_seg_t *seg = ps_seg_iter(ps); seg; seg = ps_seg_next(seg)) {
        int sf = 0, ef = 0;
        ps_seg_frames(seg, &sf, &ef);
        if (offset < 0)
            offset = sf;
        sf -= offset;
        ef -= offset;
        frames = std::max(frames, ef + 1);
        const std::string name = ps_seg_word(seg);
        if (ef < sf || name == "(NULL)")
            continue;
        int phone = PhoneSet::kSilence;
        if (name.rfind("ph_", 0) == 0)
            phone = PhoneSet::index(name.substr(3));
        if (phone == PhoneSet::kSilence && !segments.empty() && segments.back().phone == PhoneSet::kSilence)
            continue; // adjacent silences are one segment
        segments.push_back({phone, sf});
    }
    std::vector<int> spoken; // the phone-words in order, and their segment indices
    std::vector<size_t> segmentOf;
    for (size_t i = 0; i < segments.size(); ++i)
        if (segments[i].phone != PhoneSet::kSilence) {
            spoken.push_back(segments[i].phone);
            segmentOf.push_back(i);
        }
    if (spoken.empty())
        throw Error("the transcript does not fit the audio (the alignment holds no phones)");
    const auto spans = parseWords(spoken, pronunciations);

    AlignmentResult result;
    result.frames = frames;
    result.logLikelihood = logmath_log_to_ln(ps_get_logmath(ps), score);
    const double shift = 0.01; // pocketsphinx's frame rate, 100 Hz
    const double end = std::max({audioDuration, double(samples.size()) / kSampleRate, frames * shift});
    // Segment i spans [its first frame, the next segment's); the first starts at 0, the last
    // ends with the audio (as ForcedAligner's HTK convention).
    auto startOf = [&](size_t i) { return i == 0 ? 0.0 : segments[i].start * shift; };
    auto endOf = [&](size_t i) { return i + 1 < segments.size() ? segments[i + 1].start * shift : end; };
    for (size_t i = 0; i < segments.size(); ++i)
        result.phones.intervals.push_back(Interval{startOf(i), endOf(i), PhoneSet::label(segments[i].phone), false});
    double cursor = 0;
    for (size_t w = 0; w < words.size(); ++w) {
        const double a = startOf(segmentOf[spans[w].first]), b = endOf(segmentOf[spans[w].second - 1]);
        if (a > cursor + 1e-9)
            result.words.intervals.push_back(Interval{cursor, a, "sil", false});
        result.words.intervals.push_back(Interval{a, b, words[w], false});
        cursor = b;
    }
    if (cursor < end - 1e-9)
        result.words.intervals.push_back(Interval{cursor, end, "sil", false});
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
