#include "align/SpeechRecognizer.h"

#include "align/SphinxAligner.h"
#include "align/SphinxBackend.h"
#include "io/AudioDecoder.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace lipsync {

SpeechRecognizer::SpeechRecognizer(const std::string &modelDir)
{
    const std::string hmm = SphinxAligner::resolveModelDir(modelDir);
    const std::filesystem::path folder = std::filesystem::path(hmm).parent_path();
    const std::string lm = (folder / "en-us.lm.bin").string(), dict = (folder / "cmudict-en-us.dict").string();
    for (const std::string &file : {hmm + "/mdef", lm, dict})
        if (!std::filesystem::exists(file))
            throw Error("not found: CMU Sphinx's US-English models (Debian package pocketsphinx-en-us)", file);
    m_decoder = std::make_unique<SphinxDecoder>(
        hmm, std::vector<std::pair<std::string, std::string>>{{"-lm", lm}, {"-dict", dict}});
}

SpeechRecognizer::~SpeechRecognizer() = default;

SpeechRecognizer::Result SpeechRecognizer::recognize(const std::string &mediaPath, Feedback &feedback) const
{
    const AudioBuffer audio = AudioDecoder::decode(mediaPath, SphinxAligner::kSampleRate);
    Result result;
    result.duration = audio.duration();
    if (result.duration > kMaxSeconds)
        throw Error("too long to transcribe in one piece (" + std::to_string(int(result.duration))
                        + " s; at most " + std::to_string(int(kMaxSeconds)) + " s)",
                    mediaPath);
    if (feedback.isCanceled())
        throw Canceled();
    std::vector<SphinxDecoder::Word> words;
    try {
        words = m_decoder->recognize(toPcm16(audio.samples));
    } catch (const Error &e) {
        throw Error(e.reason(), mediaPath);
    }
    double cursor = 0;
    for (const SphinxDecoder::Word &w : words) {
        const double start = std::max(cursor, w.first * SphinxDecoder::kFrameSeconds);
        const double end = std::max(start, (w.last + 1) * SphinxDecoder::kFrameSeconds);
        if (start > cursor + 1e-9)
            result.timing.intervals.push_back(Interval{cursor, start, std::string(PhoneSet::kSilenceLabel), false});
        result.timing.intervals.push_back(Interval{start, end, w.word, false});
        result.words.push_back(w.word);
        result.confidence.push_back(w.confidence);
        cursor = end;
    }
    if (cursor < result.duration - 1e-9)
        result.timing.intervals.push_back(
            Interval{cursor, result.duration, std::string(PhoneSet::kSilenceLabel), false});
    feedback.setProgress(1.0);
    return result;
}

std::vector<int> doubtfulWords(const std::vector<double> &confidence)
{
    std::vector<int> doubtful;
    for (size_t i = 0; i < confidence.size(); ++i)
        if (confidence[i] < kDoubtfulWordConfidence) // never NaN
            doubtful.push_back(int(i));
    std::stable_sort(doubtful.begin(), doubtful.end(),
                     [&](int a, int b) { return confidence[size_t(a)] < confidence[size_t(b)]; });
    return doubtful;
}

} // namespace lipsync
