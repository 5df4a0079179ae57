#pragma once
// Forced alignment with CMU Sphinx's generic US-English triphone model (Debian's
// pocketsphinx-en-us, BSD-2, CMU / Alpha Cephei) through libpocketsphinx's finite-state-grammar
// search: for speakers unlike the one our own monophone models were trained on (issue 4's
// mfa-tests target). pocketsphinx reports word segments only, so every phone is a "word" of the
// grammar (ph_dh -> DH), the transcript's words are sequences of them (pronunciation variants in
// parallel) with an optional silence between words, and the phone-word path is parsed back into
// the transcript's words. The price: pocketsphinx's FSG lexicon tree models a one-phone word
// context-independently, so the phone-words lose the triphones (README: 75.9 % of the mfa-tests
// phone boundaries within 25 ms; scoring the triphone senones in our own Viterbi is the next step).
// Returns the same AlignmentResult as ForcedAligner (TextGrid, frame labels and the timeline
// work unchanged); times are on pocketsphinx's 10 ms frame grid.
#include "align/ForcedAligner.h"
#include "align/Lexicon.h"

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;

class SphinxAligner
{
public:
    static constexpr const char *kDefaultModelDir = "/usr/share/pocketsphinx/model/en-us/en-us";
    static constexpr int kSampleRate = 16000;

    struct Options
    {
        // The acoustic model folder (mdef, means, ...); empty: $LIPSYNC_SPHINX_MODEL or kDefaultModelDir.
        std::string modelDir;
        // pocketsphinx options after the defaults (name, value), e.g. {"-topn", "32"}: for tuning.
        std::vector<std::pair<std::string, std::string>> extraArguments;
    };

    // Checks that the model folder exists (lipsync::Error naming it and the Debian package if
    // not). Decoders are created on first use.
    SphinxAligner() : SphinxAligner(Options{}) {}
    explicit SphinxAligner(Options options);
    ~SphinxAligner();
    SphinxAligner(const SphinxAligner &) = delete;
    SphinxAligner &operator=(const SphinxAligner &) = delete;

    const std::string &modelDir() const { return m_modelDir; }
    // Whether a model folder is installed at `modelDir` (empty: the default).
    static bool available(const std::string &modelDir = {});
    // The model folder `modelDir` stands for ($LIPSYNC_SPHINX_MODEL or the Debian path when empty).
    static std::string resolveModelDir(const std::string &modelDir);

    // Aligns `words` (their pronunciations, PhoneSet indices; breath becomes the model's noise
    // phone) to mono 16 kHz `samples`. Thread-safe: each concurrent call uses its own decoder
    // (a pool, one per thread in use). `feedback` gets progress and is polled for cancel once
    // per second of audio (throws Canceled). Throws lipsync::Error for an empty transcript or
    // audio and when no path through the transcript reaches the end of the audio.
    AlignmentResult align(const std::vector<float> &samples, const std::vector<std::string> &words,
                          const std::vector<std::vector<Pronunciation>> &pronunciations,
                          double audioDuration = 0.0, Feedback *feedback = nullptr) const;
    // Decodes `mediaPath` (AudioDecoder, resampled to 16 kHz) and pronounces `words` with
    // `lexicon`; errors name the file.
    AlignmentResult align(const std::string &mediaPath, const std::vector<std::string> &words,
                          const Lexicon &lexicon, Feedback *feedback = nullptr) const;

private:
    struct Decoder; // a ps_decoder_t and its initial cepstral mean
    Decoder *acquire() const;
    void release(Decoder *decoder) const;

    std::string m_modelDir;
    std::vector<std::pair<std::string, std::string>> m_extra;
    mutable std::mutex m_mutex;
    mutable std::vector<Decoder *> m_free;
    mutable std::vector<std::unique_ptr<Decoder>> m_all;
};

} // namespace lipsync
