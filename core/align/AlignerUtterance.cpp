#include "align/AlignerUtterance.h"

#include "io/AudioDecoder.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cstdio>

#include <cmath>

namespace lipsync {

PreparedUtterance prepareUtterance(const std::string &id, const std::string &mediaPath,
                                   const std::vector<std::string> &words, const AcousticModel &model,
                                   const Lexicon &lexicon, const std::string &transcriptPath)
{
    return prepareUtterance(id, mediaPath, AudioDecoder::decode(mediaPath, model.featureOptions().sampleRate), words,
                            model, lexicon, transcriptPath);
}

PreparedUtterance prepareUtterance(const std::string &id, const std::string &mediaPath, const AudioBuffer &audio,
                                   const std::vector<std::string> &words, const AcousticModel &model,
                                   const Lexicon &lexicon, const std::string &transcriptPath)
{
    PreparedUtterance u = pronounceUtterance(id, mediaPath, audio, words, model, lexicon, transcriptPath);
    u.features = model.features(audio);
    if (u.features.rows() == 0)
        throw Error("the audio is shorter than one analysis window", mediaPath);
    return u;
}

PreparedUtterance pronounceUtterance(const std::string &id, const std::string &mediaPath, const AudioBuffer &audio,
                                     const std::vector<std::string> &words, const AcousticModel &model,
                                     const Lexicon &lexicon, const std::string &transcriptPath)
{
    PreparedUtterance u;
    u.id = id;
    u.words = words;
    // The audio first: a transcript far too long for it is refused before its words are
    // pronounced (a subtitle file of 100 000 cues against a 3 s clip).
    u.duration = audio.duration();
    checkWordsFitAudio(words, u.duration, model.featureOptions().shiftSeconds, mediaPath, transcriptPath);
    try {
        u.pronunciations = lexicon.pronounceAll(words);
    } catch (const Error &e) {
        throw Error(e.reason(), mediaPath);
    }
    float peak = 0;
    for (float s : audio.samples)
        peak = std::max(peak, std::abs(s));
    // -80 dBFS: nothing to align words to.
    if (peak < 1e-4f)
        throw Error("the audio is silent", mediaPath);
    return u;
}

void checkWordsFitAudio(const std::vector<std::string> &words, double audioSeconds, double frameShift,
                        const std::string &mediaPath, const std::string &transcriptPath)
{
    // Every spoken word has a phone, and every phone three emitting states of a frame each.
    const auto spoken = std::count_if(words.begin(), words.end(), [](const std::string &w) {
        return !PhoneSet::isSilence(w) && w != "sp";
    });
    const double needed = double(spoken) * 3.0 * frameShift;
    if (needed > audioSeconds + 1e-9) {
        char message[160];
        std::snprintf(message, sizeof message,
                      "the transcript does not fit the audio: %lld words need at least %.2f s, the audio has %.2f s",
                      (long long)spoken, needed, audioSeconds);
        throw Error(transcriptPath.empty() ? std::string(message)
                                           : std::string(message) + " (transcript " + transcriptPath + ")",
                    mediaPath);
    }
}

AcousticModel featureModel(const TrainerOptions &options)
{
    const int d = Mfcc(options.features).dimension();
    return AcousticModel(options.features, options.normalization, Eigen::VectorXf::Zero(d), Eigen::VectorXf::Ones(d));
}

} // namespace lipsync
