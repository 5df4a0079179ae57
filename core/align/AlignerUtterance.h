#pragma once
// From a media file and its transcript to what the trainer and the aligner consume: decoded
// audio (AudioDecoder, mono at the model's rate), checked for silence, its features and the
// pronunciations of its words. Shared by the CLI, the studio and the benchmarks.
#include "align/AcousticModel.h"
#include "align/AlignerTrainer.h"
#include "align/Lexicon.h"

#include <string>
#include <vector>

namespace lipsync {

struct PreparedUtterance
{
    std::string id;
    double duration = 0;           // seconds of audio
    Eigen::MatrixXf features;
    std::vector<std::string> words;
    std::vector<std::vector<Pronunciation>> pronunciations;
};

// Decodes `mediaPath`, computes features as `model` expects and pronounces `words`.
// Throws lipsync::Error naming the file for undecodable or silent audio and for words without a
// pronunciation (all of them named).
// `transcriptPath`, when given, is named too when the words cannot fit the audio.
PreparedUtterance prepareUtterance(const std::string &id, const std::string &mediaPath,
                                   const std::vector<std::string> &words, const AcousticModel &model,
                                   const Lexicon &lexicon, const std::string &transcriptPath = {});
// The same for sound already decoded at the model's rate (`mediaPath` names it in errors).
PreparedUtterance prepareUtterance(const std::string &id, const std::string &mediaPath, const AudioBuffer &audio,
                                   const std::vector<std::string> &words, const AcousticModel &model,
                                   const Lexicon &lexicon, const std::string &transcriptPath = {});

// The same from audio already decoded at the model's rate, without the features: the checks and
// the pronunciations (a long recording's features are computed window by window, LongAlignment).
PreparedUtterance pronounceUtterance(const std::string &id, const std::string &mediaPath, const AudioBuffer &audio,
                                     const std::vector<std::string> &words, const AcousticModel &model,
                                     const Lexicon &lexicon, const std::string &transcriptPath = {});

// Throws lipsync::Error naming `mediaPath` (and `transcriptPath` if given) when the spoken words
// (silence tokens aside) cannot fit `audioSeconds` even at one phone of three `frameShift` frames
// each: checked before the words are pronounced, so a wrong, huge transcript costs no memory.
void checkWordsFitAudio(const std::vector<std::string> &words, double audioSeconds, double frameShift,
                        const std::string &mediaPath, const std::string &transcriptPath = {});

// The feature configuration of a model to be trained, as an AcousticModel that only computes
// features (no trained states).
AcousticModel featureModel(const TrainerOptions &options);

} // namespace lipsync
