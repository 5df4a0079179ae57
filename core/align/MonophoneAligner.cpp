#include "align/MonophoneAligner.h"

#include "align/AlignerUtterance.h"
#include "align/LongAlignment.h"
#include "align/Realignment.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

namespace lipsync {

namespace {

// An error of aligning the words to the recording: it names the media, and the transcript if given.
Error misfit(const Error &e, const std::string &mediaPath, const std::string &transcriptPath)
{
    return Error(transcriptPath.empty() ? e.reason() : e.reason() + " (transcript " + transcriptPath + ")", mediaPath);
}

// The decoded recording, and what to align it with: the model, or when adaptation is asked for
// the model moved to the recording's speaker (`adapted`).
struct Prepared
{
    PreparedUtterance utterance;
    std::optional<AcousticModel> adapted;
    AdaptationReport report;

    const AcousticModel &modelOr(const AcousticModel &model) const { return adapted ? *adapted : model; }
    // The output without its alignment.
    AlignerOutput output(const AcousticModel &model) const
    {
        AlignerOutput out;
        out.duration = utterance.duration;
        out.audioFrames = model.featureOptions();
        out.adaptation = report;
        return out;
    }
};

Prepared prepare(const RecordingSound &sound, const std::vector<std::string> &words, const AcousticModel &model,
                 const Lexicon &lexicon, bool adapt, Feedback &feedback, const std::string &transcriptPath = {})
{
    const std::string &mediaPath = sound.path();
    Prepared p{prepareUtterance(std::filesystem::path(mediaPath).stem().string(), mediaPath,
                                *sound.at(model.featureOptions().sampleRate), words, model, lexicon, transcriptPath),
               std::nullopt, {}};
    if (adapt) {
        try {
            p.adapted = SpeakerAdaptation::adapt(model, p.utterance.pronunciations, p.utterance.features, {},
                                                 feedback, &p.report);
        } catch (const Error &e) {
            throw misfit(e, mediaPath, transcriptPath);
        }
    }
    return p;
}

} // namespace

MonophoneAligner::MonophoneAligner(const std::string &path, bool adapt)
    : m_path(path), m_model(AcousticModel::load(path)), m_adapt(adapt)
{
}

double transcriptFit(const AcousticModel &model, const Eigen::MatrixXf &features, const AlignmentResult &alignment)
{
    // The forced path against each frame's best state alone: both per frame, so the score does
    // not grow with the utterance.
    const int T = int(features.rows());
    if (T == 0 || alignment.frames == 0)
        return std::numeric_limits<double>::quiet_NaN();
    const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = features;
    double best = 0;
    for (int t = 0; t < T; ++t) {
        float top = -std::numeric_limits<float>::infinity();
        for (int j = 0; j < model.stateCount(); ++j)
            top = std::max(top, model.state(j).logLikelihood(rows.data() + size_t(t) * size_t(rows.cols())));
        best += top;
    }
    return (alignment.logLikelihood - best) / double(T);
}

AlignerOutput MonophoneAligner::align(const RecordingSound &sound, const std::vector<std::string> &words,
                                      const Lexicon &lexicon, Feedback &feedback,
                                      const std::string &transcriptPath) const
{
    const std::string &mediaPath = sound.path();
    if (words.empty())
        throw Error("the transcript has no words to align", transcriptPath.empty() ? mediaPath : transcriptPath);
    if (const double seconds = MediaInfo::probe(mediaPath).audioDuration; seconds > kLongRecordingSeconds)
        return alignLong(sound, seconds, words, lexicon, feedback, transcriptPath);
    const Prepared p = prepare(sound, words, m_model, lexicon, m_adapt, feedback, transcriptPath);
    AlignerOutput out = p.output(m_model);
    try {
        out.alignment = ForcedAligner(p.modelOr(m_model))
                            .align(p.utterance.features, p.utterance.words, p.utterance.pronunciations,
                                   p.utterance.duration);
    } catch (const Error &e) {
        throw misfit(e, mediaPath, transcriptPath);
    }
    if (m_measureFit)
        if (const double fit = transcriptFit(p.modelOr(m_model), p.utterance.features, out.alignment); std::isfinite(fit))
            out.transcriptFit = TranscriptFit{fit, kTranscriptFitThreshold};
    // The model's correction, none once adapted to the recording's speaker (SpeakerAdaptation).
    p.modelOr(m_model).boundaryCorrection().apply(out.alignment);
    return out;
}

AlignerOutput MonophoneAligner::alignLong(const RecordingSound &sound, double seconds,
                                          const std::vector<std::string> &words,
                                          const Lexicon &lexicon, Feedback &feedback,
                                          const std::string &transcriptPath) const
{
    const std::string &mediaPath = sound.path();
    if (seconds > kMaxRecordingSeconds)
        throw Error("the recording is " + std::to_string(int(seconds / 60)) + " min long; up to "
                        + std::to_string(int(kMaxRecordingSeconds / 60))
                        + " min are aligned in one go: split it into parts (ffmpeg -f segment)",
                    mediaPath);
    if (m_adapt)
        throw Error("speaker adaptation needs a recording of at most " + std::to_string(int(kLongRecordingSeconds / 60))
                        + " min: align this one without it, or split it into utterances first (lipsync project "
                          "import-long) and adapt to those",
                    mediaPath);
    const std::shared_ptr<const AudioBuffer> sampled = sound.at(m_model.featureOptions().sampleRate);
    const AudioBuffer &audio = *sampled;
    const PreparedUtterance u = pronounceUtterance(std::filesystem::path(mediaPath).stem().string(), mediaPath, audio,
                                                   words, m_model, lexicon, transcriptPath);
    // Subtitles' cue times choose the words of each window.
    std::vector<Interval> cues;
    if (!transcriptPath.empty())
        cues = readTranscript(transcriptPath).cues.intervals;
    AlignerOutput out;
    out.duration = u.duration;
    out.audioFrames = m_model.featureOptions();
    try {
        out.alignment = alignLongRecording(m_model, audio.samples, u.words, u.pronunciations, cues, feedback);
    } catch (const Error &e) {
        throw misfit(e, mediaPath, transcriptPath);
    }
    m_model.boundaryCorrection().apply(out.alignment);
    return out;
}

AlignerOutput MonophoneAligner::realign(const std::string &mediaPath, const Realignment &realignment,
                                        const Lexicon &lexicon, Feedback &feedback) const
{
    const Prepared p = prepare(RecordingSound(mediaPath), realignment.words(), m_model, lexicon, m_adapt, feedback);
    AlignerOutput out = p.output(m_model);
    try {
        out.alignment = realignment.run(ForcedAligner(p.modelOr(m_model)), p.utterance.features,
                                        p.utterance.pronunciations, p.utterance.duration);
    } catch (const Error &e) {
        throw misfit(e, mediaPath, {});
    }
    std::vector<double> fixed;
    for (const FixedBoundary &b : realignment.fixed())
        fixed.push_back(b.time);
    p.modelOr(m_model).boundaryCorrection().apply(out.alignment, fixed);
    return out;
}

} // namespace lipsync
