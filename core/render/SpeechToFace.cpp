#include "render/SpeechToFace.h"

#include "align/FrameLabels.h"
#include "align/Lexicon.h"
#include "align/ProjectAligner.h"
#include "align/PronunciationDictionary.h"
#include "dynamics/ModelFile.h"
#include "io/MediaInfo.h"
#include "io/RecordingSound.h"
#include "io/Transcript.h"
#include "io/VideoReader.h"
#include "project/Project.h"
#include "render/BilabialClosure.h"
#include "render/FaceRenderer.h"
#include "render/FrameComposition.h"
#include "render/ImageSequenceExporter.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

namespace lipsync {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

namespace {

// What both entry points share: the media checked for sound, the AAM and the model loaded and
// checked against each other.
struct Loaded
{
    MediaInfo info;
    MediaInfo background; // request.backgroundPath's, when given
    std::shared_ptr<const AamModel> aam;
    std::shared_ptr<const DynamicModel> model;
};

Loaded loadInputs(const SpeechToFaceRequest &request)
{
    Loaded in;
    in.info = MediaInfo::probe(request.mediaPath);
    if (!request.backgroundPath.empty()) {
        in.background = MediaInfo::probe(request.backgroundPath);
        if (!in.background.hasVideo || in.background.frameCount == 0)
            throw Error("no video stream to render the face into", request.backgroundPath);
    }
    if (!in.info.hasAudio)
        throw Error("no audio stream: lip movements are generated from speech, so the recording "
                    "needs its sound",
                    request.mediaPath);
    in.aam = request.aam ? request.aam : std::make_shared<const AamModel>(AamModel::load(request.aamPath));
    // A model trained without naming its AAM (`lipsync train` without --aam) is accepted if its
    // dimension fits; one that names another AAM is not.
    std::string modelAam;
    in.model = request.model ? request.model : std::shared_ptr<const DynamicModel>(loadModel(request.modelPath, {}, &modelAam));
    if (!request.model && !modelFitsAam(modelAam, in.aam->identifier))
        throw Error("the model was trained for AAM '" + modelAam + "', not for " + request.aamPath
                        + " ('" + in.aam->identifier + "')",
                    request.modelPath, "aam");
    if (in.model->dimension() != in.aam->combinedModes())
        throw Error("the model generates " + std::to_string(in.model->dimension())
                        + " parameters, the AAM has " + std::to_string(in.aam->combinedModes()),
                    request.modelPath);
    return in;
}

// Labels by the voting rule of docs/models.md §0 (one per video frame: the clip's own frame count
// when rendering into its frames at its rate, else as many frames as the sound lasts), the
// generated trajectory, and the sound for export.
void labelAndGenerate(const SpeechToFaceRequest &request, const Loaded &in, const RecordingSound &sound,
                      double audioDuration, const MfccOptions &audioFrames, SpeechToFaceResult &result,
                      Feedback &feedback);

// The phones and words of an aligner's output, voted onto the frames with its own audio frames.
void labelAndGenerate(const SpeechToFaceRequest &request, const Loaded &in, const RecordingSound &sound,
                      const AlignerOutput &aligned, SpeechToFaceResult &result, Feedback &feedback)
{
    result.words = aligned.alignment.words;
    result.phones = aligned.alignment.phones;
    labelAndGenerate(request, in, sound, aligned.duration, aligned.audioFrames, result, feedback);
}

void labelAndGenerate(const SpeechToFaceRequest &request, const Loaded &in, const RecordingSound &sound,
                      double audioDuration, const MfccOptions &audioFrames, SpeechToFaceResult &result,
                      Feedback &feedback)
{
    result.mediaPath = request.mediaPath;
    result.aam = in.aam;
    result.modelKind = in.model->kind();
    result.backgroundPath = request.backgroundPath;
    result.hasVideo = in.info.hasVideo && in.info.frameCount > 0 && request.backgroundPath.empty();
    const double modelRate = in.model->frameRate();
    result.frameRate = request.frameRate > 0                      ? request.frameRate
                       : !request.backgroundPath.empty()          ? in.background.frameRate
                       : result.hasVideo && in.info.frameRate > 0 ? in.info.frameRate
                       : modelRate > 0                            ? modelRate
                                                                  : Project::kAudioOnlyFrameRate;
    const bool ownFrames = result.hasVideo && std::abs(result.frameRate - in.info.frameRate) < 1e-6;
    // The clip's own frames at their timestamps, or frames at the asked rate from 0 that cover
    // the sound.
    result.frames = ownFrames ? in.info.frames
                              : FrameClock::uniform(result.frameRate,
                                                    std::max(1, int(std::ceil(audioDuration * result.frameRate - 1e-6))));
    const int frames = result.frames.count();
    // The §0 vote on `clock`, a label outside the phone set taken as silence.
    auto labelsOn = [&](const FrameClock &clock) {
        std::vector<int> labels;
        for (const std::string &label : voteFrameLabels(result.phones, clock, audioFrames)) {
            const int index = PhoneSet::index(label);
            labels.push_back(index >= 0 ? index : int(PhoneSet::kSilence));
        }
        return labels;
    };
    result.labels = labelsOn(result.frames);
    if (modelRate > 0 && (result.frames.isVariable() || std::abs(modelRate - result.frameRate) > 1e-6 * modelRate)) {
        // The model's dynamics are per frame of its own rate: generate on an even grid at that
        // rate over the same stretch, then sample the trajectory at the output frames' times
        // (linear interpolation).
        const double from = result.frames.startTime();
        const int modelFrames = std::max(1, int(std::ceil(result.frames.duration() * modelRate - 1e-6)));
        const Eigen::MatrixXd generated = in.model->generate(labelsOn(FrameClock::uniform(modelRate, modelFrames, from)));
        result.features.resize(frames, generated.cols());
        for (int t = 0; t < frames; ++t) {
            const double at = std::clamp((result.frames.time(t) - from) * modelRate, 0.0, double(modelFrames - 1));
            const int a = int(at);
            const int b = std::min(a + 1, modelFrames - 1);
            result.features.row(t) = (1.0 - (at - a)) * generated.row(a) + (at - a) * generated.row(b);
        }
    } else {
        result.features = in.model->generate(result.labels);
    }
    if (request.closeBilabials)
        result.features = BilabialClosure::closeOnPhones(*in.aam, result.features, result.phones, result.frames);
    if (request.keepPosture)
        result.posture = PostureTransfer::forModel(*in.model, *in.aam);
    feedback.throwIfCanceled();
    // The sound at its own rate, its first sample with the first frame.
    result.audio = alignAudioToVideo(*sound.own(), result.frames.startTime());
    feedback.setProgress(1.0);
}

} // namespace

SpeechToFaceResult generateFromSpeech(const SpeechToFaceRequest &request, Feedback &feedback)
{
    const auto start = std::chrono::steady_clock::now();
    feedback.setStatus("Aligning " + request.mediaPath);
    // Models first: a wrong file fails before the (longer) alignment.
    const Loaded in = loadInputs(request);
    const std::shared_ptr<const Aligner> aligner =
        request.aligners ? request.aligners->get(request.aligner) : std::shared_ptr<const Aligner>(createAligner(request.aligner));
    SpeechToFaceResult result;
    const std::vector<std::string> words = request.words ? *request.words : readTranscript(request.transcriptPath).words;
    feedback.throwIfCanceled();
    feedback.setProgress(0.1);

    const Lexicon lexicon(&PronunciationDictionary::cmu(), Lexicon::parseOverrides(request.pronunciations));
    // Decoded once at its own rate, for the output; the aligner takes it resampled to its rate.
    const RecordingSound sound(request.mediaPath);
    sound.own();
    Feedback aligning(feedback, 0.1, 0.8);
    // In any voice: the project's aligner gives way to the generic model where it misfits the voice.
    const VoiceAlignment voice =
        alignAnyVoice(*aligner, request.aligner, false, sound, words, lexicon, aligning, request.transcriptPath,
                      request.aligners.get());
    const AlignerOutput &aligned = voice.output;
    result.alignerModelPath = voice.aligner;
    result.voiceRealigned = voice.generic;
    feedback.throwIfCanceled();
    feedback.setProgress(0.8);
    labelAndGenerate(request, in, sound, aligned, result, feedback);
    result.seconds = secondsSince(start);
    return result;
}

SpeechToFaceResult generateFromAlignment(const SpeechToFaceRequest &request, const AlignerOutput &aligned,
                                         const RecordingSound &sound, Feedback &feedback)
{
    const auto start = std::chrono::steady_clock::now();
    feedback.setStatus("Generating for " + request.mediaPath);
    const Loaded in = loadInputs(request);
    SpeechToFaceResult result;
    labelAndGenerate(request, in, sound, aligned, result, feedback);
    result.seconds = secondsSince(start);
    return result;
}

SpeechToFaceResult generateFromPhones(const SpeechToFaceRequest &request, const Tier &phones,
                                      const Tier &words, Feedback &feedback)
{
    const auto start = std::chrono::steady_clock::now();
    feedback.setStatus("Generating for " + request.mediaPath);
    const Loaded in = loadInputs(request);
    if (phones.intervals.empty())
        throw Error("no phone alignment: align the speech first", request.mediaPath);
    SpeechToFaceResult result;
    result.phones = phones;
    result.words = words;
    labelAndGenerate(request, in, RecordingSound(request.mediaPath), in.info.audioEndTime, MfccOptions{}, result,
                     feedback);
    result.seconds = secondsSince(start);
    return result;
}

std::unique_ptr<FaceRenderer> makeRenderer(const SpeechToFaceResult &result,
                                           const std::string &mediaPath, Feedback &feedback)
{
    if (!result.aam)
        throw Error("cannot render: nothing was generated", mediaPath);
    if (!result.backgroundPath.empty()) {
        auto renderer = std::make_unique<FaceRenderer>(*result.aam, result.backgroundPath, feedback);
        renderer->retime(result.frameCount());
        return renderer;
    }
    if (result.hasVideo && !mediaPath.empty())
        return std::make_unique<FaceRenderer>(*result.aam, mediaPath, feedback);
    return std::make_unique<FaceRenderer>(*result.aam);
}

cv::Mat renderFrame(const SpeechToFaceResult &result, FaceRenderer &renderer, int index,
                    const RenderOptions &options)
{
    Eigen::VectorXd c = result.features.row(std::clamp<Eigen::Index>(index, 0, result.features.rows() - 1)).transpose();
    if (result.posture)
        c = result.posture->apply(c, renderer.posture(index));
    renderer.setCompositeOptions(options.composite);
    if (options.sideBySide)
        return renderer.renderSideBySide(index, c, options.leftLabel, options.rightLabel);
    cv::Mat frame = renderer.render(index, c);
    if (!options.rightLabel.empty())
        return composeGrid({frame}, 1, {options.rightLabel});
    return frame;
}

namespace {

void checkRenderable(const SpeechToFaceResult &result, const FaceRenderer &renderer,
                     const RenderOptions &options, const std::string &out)
{
    if (result.frameCount() == 0)
        throw Error("cannot export: nothing was generated", out);
    if (options.sideBySide && !renderer.hasVideo())
        throw Error("side by side needs the real video, and the media has none", result.mediaPath);
}

} // namespace

int exportRenderedVideo(const SpeechToFaceResult &result, FaceRenderer &renderer,
                        const std::string &path, Feedback &feedback, const RenderOptions &options)
{
    checkRenderable(result, renderer, options, path);
    VideoExportOptions video = options.video;
    video.setFrames(result.frames);
    return exportVideo(
        path, result.frameCount(), [&](int i) { return renderFrame(result, renderer, i, options); },
        result.audio.samples.empty() ? nullptr : &result.audio, feedback, video);
}

std::vector<std::string> exportRenderedImages(const SpeechToFaceResult &result, FaceRenderer &renderer,
                                              const std::string &folder, Feedback &feedback,
                                              const RenderOptions &options)
{
    checkRenderable(result, renderer, options, folder);
    return exportImageSequence(folder, result.frameCount(),
                               [&](int i) { return renderFrame(result, renderer, i, options); }, feedback);
}

SpeechVideoReport renderSpeechVideo(const SpeechToFaceRequest &request, const std::string &outPath,
                                    Feedback &feedback, const RenderOptions &options)
{
    SpeechVideoReport report;
    {
        Feedback step(feedback, 0.0, 0.4);
        report.generated = generateFromSpeech(request, step);
    }
    const auto start = std::chrono::steady_clock::now();
    std::unique_ptr<FaceRenderer> renderer;
    {
        Feedback step(feedback, 0.4, 0.55);
        renderer = makeRenderer(report.generated, request.mediaPath, step);
    }
    {
        Feedback step(feedback, 0.55, 1.0);
        report.framesWritten = exportRenderedVideo(report.generated, *renderer, outPath, step, options);
    }
    report.renderSeconds = secondsSince(start);
    return report;
}

} // namespace lipsync
