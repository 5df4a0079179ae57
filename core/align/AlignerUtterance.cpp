#include "align/AlignerUtterance.h"

#include "io/AudioDecoder.h"
#include "util/Error.h"

#include <cmath>

namespace lipsync {

PreparedUtterance prepareUtterance(const std::string &id, const std::string &mediaPath,
                                   const std::vector<std::string> &words, const AcousticModel &model,
                                   const Lexicon &lexicon)
{
    PreparedUtterance u;
    u.id = id;
    u.words = words;
    try {
        u.pronunciations = lexicon.pronounceAll(words);
    } catch (const Error &e) {
        throw Error(e.reason(), mediaPath);
    }
    const AudioBuffer audio = AudioDecoder::decode(mediaPath, model.featureOptions().sampleRate);
    u.duration = audio.duration();
    float peak = 0;
    for (float s : audio.samples)
        peak = std::max(peak, std::abs(s));
    // -80 dBFS: nothing to align words to.
    if (peak < 1e-4f)
        throw Error("the audio is silent", mediaPath);
    u.features = model.features(audio);
    if (u.features.rows() == 0)
        throw Error("the audio is shorter than one analysis window", mediaPath);
    return u;
}

AcousticModel featureModel(const TrainerOptions &options)
{
    const int d = Mfcc(options.features).dimension();
    return AcousticModel(options.features, options.normalization, Eigen::VectorXf::Zero(d), Eigen::VectorXf::Ones(d));
}

} // namespace lipsync
