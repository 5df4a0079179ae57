#pragma once
// A proposed transcript for a recording that has none: CMU Sphinx's generic US-English acoustic
// model with its language model and dictionary (Debian's pocketsphinx-en-us) decode the speech.
// The words are a proposal for the user to correct (`lipsync transcribe`), not a reference: on
// GRID's command sentences the generic language model gets most words, not all.
#include "annotation/Tier.h"
#include "tasks/Feedback.h"

#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class SphinxDecoder;

class SpeechRecognizer
{
public:
    // `modelDir`: the en-us folder (empty: $LIPSYNC_SPHINX_MODEL or Debian's); its language model
    // and dictionary are the ones beside it (en-us.lm.bin, cmudict-en-us.dict). Throws
    // lipsync::Error naming what is missing.
    explicit SpeechRecognizer(const std::string &modelDir = {});
    ~SpeechRecognizer();

    struct Result
    {
        std::vector<std::string> words;
        // Each word's posterior probability in the recogniser's lattice (SphinxDecoder::Word::
        // confidence), NaN where there was none.
        std::vector<double> confidence;
        Tier timing{"words", {}}; // each word's time as decoded, silence between them
        double duration = 0;      // seconds of audio
    };
    // Decodes the recording at `mediaPath` (any audio or video; errors name it). Recordings of
    // more than kMaxSeconds are refused: one utterance's search grows with its length.
    static constexpr double kMaxSeconds = 120.0;
    Result recognize(const std::string &mediaPath, Feedback &feedback = Feedback::none()) const;

private:
    std::unique_ptr<SphinxDecoder> m_decoder;
};

// A proposed word below this posterior is doubtful: shown for review (docs/performance.md,
// "Confidence of proposed words").
constexpr double kDoubtfulWordConfidence = 0.5;

// The indices of the doubtful words among `confidence` (one posterior per word, below
// kDoubtfulWordConfidence), the most doubtful first.
std::vector<int> doubtfulWords(const std::vector<double> &confidence);
inline std::vector<int> doubtfulWords(const SpeechRecognizer::Result &result)
{
    return doubtfulWords(result.confidence);
}

} // namespace lipsync
