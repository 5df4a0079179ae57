#pragma once
// Forced alignment with CMU Sphinx's generic US-English triphone model (Debian's
// pocketsphinx-en-us, BSD-2, CMU / Alpha Cephei): for speakers unlike the one our own monophone
// models were trained on (mfa-tests, docs/performance.md). libpocketsphinx scores the senones (tied
// triphone HMM states) that our own Viterbi reaches in each 10 ms frame (within a beam); the Viterbi runs over the transcript unrolled
// into TRIPHONE senone sequences (each phone's base, left and right context and word position
// looked up in the model's mdef, falling back to the CI phone): cross-word contexts as variants
// (a word's last phone with the next word's first phone or SIL on its right, the next word's
// first phone with the previous last phone or SIL on its left), pronunciation variants in
// parallel, an optional silence between words and silence context at the utterance's edges.
// Transition probabilities are left out (a self-loop penalty changed nothing on mfa-tests).
// pocketsphinx's own FSG search cannot do this: its one-phone grammar "words" are context
// independent in its lexicon tree (75.9 % of mfa-tests phone boundaries within 25 ms of MFA).
// Optionally adapted to the recording's speaker (Options::adaptationPasses, align --adapt):
// aligned, an MLLR transform of the model's Gaussians estimated from that alignment
// (SphinxAdaptation) applied through pocketsphinx, aligned again.
// Returns the same AlignmentResult as ForcedAligner (TextGrid, frame labels and the timeline
// work unchanged); times are on pocketsphinx's 10 ms frame grid. Everything of libpocketsphinx
// itself is behind SphinxBackend.
#include "align/Aligner.h"
#include "align/Lexicon.h"
#include "align/SphinxModelDefinition.h"
#include "tasks/Feedback.h"
#include "util/ObjectPool.h"
#include "util/SystemPaths.h"

#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace lipsync {

class SphinxCodebooks;
class SphinxDecoder;

class SphinxAligner : public Aligner
{
public:
    static constexpr const char *kDefaultModelDir = systempaths::kSphinxModelDir;
    static constexpr int kSampleRate = 16000;

    struct Options
    {
        // The acoustic model folder (mdef, means, ...); empty: $LIPSYNC_SPHINX_MODEL or kDefaultModelDir.
        std::string modelDir;
        // pocketsphinx options after the defaults (name, value), e.g. {"-topn", "32"}: for tuning.
        std::vector<std::pair<std::string, std::string>> extraArguments;
        // Speaker adaptation: after the first alignment, `adaptationPasses` times an MLLR mean
        // transform of the model's Gaussians estimated from the last alignment
        // (SphinxAdaptation), then the alignment again under the adapted model. 0: none.
        int adaptationPasses = 0;
        // Measure AlignerOutput::transcriptFit: every senone scored in every frame once more
        // after the alignment (as long again as the alignment: 49 clips of GRID s4 in 8.1 s
        // without it, 18.0 s with it, one thread).
        bool measureTranscriptFit = false;
    };

    // Checks that the model folder exists (lipsync::Error naming it and the Debian package if
    // not) and reads its mdef (errors name the file). Decoders are created on first use.
    SphinxAligner() : SphinxAligner(Options{}) {}
    explicit SphinxAligner(Options options);
    ~SphinxAligner() override;
    SphinxAligner(const SphinxAligner &) = delete;
    SphinxAligner &operator=(const SphinxAligner &) = delete;

    const std::string &modelDir() const { return m_modelDir; }
    // Whether a model folder is installed at `modelDir` (empty: the default).
    static bool available(const std::string &modelDir = {});
    // The model folder `modelDir` stands for ($LIPSYNC_SPHINX_MODEL or the Debian path when empty).
    static std::string resolveModelDir(const std::string &modelDir);

    // Aligns `words` (their pronunciations, PhoneSet indices; breath becomes the model's noise
    // phone) to mono 16 kHz `samples`. Thread-safe: each concurrent call uses its own decoder
    // (a pool, one per thread in use). `feedback` gets progress and is polled for cancel every
    // half second of audio (throws Canceled). Throws lipsync::Error for an empty transcript or
    // audio and when no path through the transcript reaches the end of the audio. With
    // `transcriptFit`, stores there the fit of the words to the sound (AlignerOutput::transcriptFit:
    // the path's senone against the best of all senones in each frame of speech, nats per 10 ms
    // frame; none when the path holds no speech).
    AlignmentResult align(const std::vector<float> &samples, const std::vector<std::string> &words,
                          const std::vector<std::vector<Pronunciation>> &pronunciations,
                          double audioDuration = 0.0, Feedback &feedback = Feedback::none(),
                          double *transcriptFit = nullptr) const;

    // Aligner: "sphinx:DIR"; the media decoded (AudioDecoder, resampled to 16 kHz) and `words`
    // pronounced with `lexicon`; errors name the file. Re-alignment aligns each stretch's own
    // audio with its own words (Realignment::runPiecewise).
    std::string name() const override { return "sphinx:" + m_modelDir; }
    using Aligner::align;
    AlignerOutput align(const RecordingSound &sound, const std::vector<std::string> &words, const Lexicon &lexicon,
                        Feedback &feedback = Feedback::none(), const std::string &transcriptPath = {}) const override;
    AlignerOutput realign(const std::string &mediaPath, const Realignment &realignment, const Lexicon &lexicon,
                          Feedback &feedback = Feedback::none()) const override;

private:
    const SphinxCodebooks &codebooks(const SphinxDecoder &decoder) const;

    std::string m_modelDir;
    SphinxModelDefinition m_mdef;
    std::vector<std::pair<std::string, std::string>> m_extra;
    int m_adaptationPasses = 0;
    bool m_measureFit = false;
    mutable std::once_flag m_codebooksOnce;
    mutable std::unique_ptr<SphinxCodebooks> m_codebooks; // read on the first adaptation
    // Decoders (a few hundred ms to load), one per concurrent alignment.
    mutable ObjectPool<SphinxDecoder> m_decoders;
};

} // namespace lipsync
