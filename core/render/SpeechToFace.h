#pragma once
// Generation from new speech, shared by `lipsync render` and the studio's "generate from new
// speech": any audio or video file with its transcript ->
//   forced alignment (an Aligner: the shipped aligner model, one of ours, or CMU Sphinx's)
//   -> phone label of every video frame (voteFrameLabels, docs/models.md §0)
//   -> the most likely feature trajectory of a trained dynamic model (DynamicModel::generate)
//   -> frames rendered by FaceRenderer (into the clip's own frames, or a neutral frame)
//   -> MP4 (H.264 + the recording's sound as AAC) or PNGs.
// Each step reports progress into its share of the Feedback and honours cancel.
//
// Media without sound cannot be aligned: generateFromSpeech() throws lipsync::Error naming the
// file ("no audio stream"); there is no silent-audio fallback, since the labels come from the speech.
#include "aam/AamModel.h"
#include "align/Aligner.h"
#include "io/AudioDecoder.h"
#include "annotation/Tier.h"
#include "render/FaceRenderer.h"
#include "render/PostureTransfer.h"
#include "render/VideoExporter.h"

#include <Eigen/Core>

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

class RecordingSound;

class DynamicModel;
class Feedback;

struct SpeechToFaceRequest
{
    std::string mediaPath;          // audio or video with speech
    std::string transcriptPath;     // what readTranscript() reads: .align, .lab, .txt, .TextGrid
    // The words themselves (typed in the studio), used instead of reading transcriptPath; the
    // path, if any, then only names them in errors.
    std::optional<std::vector<std::string>> words;
    std::string modelPath;          // a trained dynamic model (ModelFile)
    std::string aamPath;            // the AAM the model's features are parameters of
    // The same models already in memory (the studio's), used instead of the files when set; the
    // caller then vouches that the model is the AAM's.
    std::shared_ptr<const AamModel> aam;
    std::shared_ptr<const DynamicModel> model;
    AlignerChoice aligner;          // default: the shipped aligner model (ShippedAlignerModel)
    // Where the aligners come from (the studio's AlignerCache, loaded once a session): `aligner`,
    // and the generic one when the words misfit the voice (alignAnyVoice); null: made for this
    // request.
    std::shared_ptr<AlignerCache> aligners;
    // Another video of the person to render the new speech into (BackgroundRetiming: played in
    // runs with cuts where the head's motion allows, for as long as the speech lasts); empty:
    // the media's own frames, or the neutral frame for sound alone.
    std::string backgroundPath;
    // Frames per second of the generated sequence; 0: the video's rate (the background's when
    // given), for audio only the
    // model's (25 if it records none). A model trained at another rate generates at its own and
    // is sampled at these frames.
    double frameRate = 0.0;
    // Pronunciation overrides (a project's Project::pronunciations), before CMU and espeak-ng.
    std::map<std::string, std::string> pronunciations;
    // Close the lips on /p b m/ (render/BilabialClosure, when it applies to the AAM); false: the
    // model's trajectory as it is.
    bool closeBilabials = true;
    // Keep the posture of the frames drawn into (render/PostureTransfer); false: the model's.
    bool keepPosture = true;
};

struct SpeechToFaceResult
{
    std::string mediaPath;
    std::shared_ptr<const AamModel> aam; // FaceRenderers made for this result refer to it
    std::string modelKind;        // the model's kind id (dynamics/ModelKind.h)
    std::string alignerModelPath; // the aligner used (Aligner::name)
    // The request's aligner misfit the voice and CMU Sphinx's generic model aligned it instead
    // (align/ProjectAligner's alignAnyVoice; generateFromSpeech).
    bool voiceRealigned = false;
    Tier words{"words", {}};      // forced alignment
    Tier phones{"phones", {}};
    double frameRate = 25.0;
    // When each generated frame is shown, on the media's timeline (the video's own frames when
    // rendering into them, else every 1 / frameRate from 0 for as long as the sound lasts).
    FrameClock frames;
    std::vector<int> labels;      // PhoneSet index of every frame
    Eigen::MatrixXd features;     // generated parameters, frames x d (lips closed on /p b m/ if asked)
    // The model's posture transfer (request.keepPosture), applied as each frame is drawn; null: none.
    std::shared_ptr<const PostureTransfer> posture;
    AudioBuffer audio;            // the recording's sound (own rate), first sample with frame 0
                                  // (startTime = frames.startTime())
    bool hasVideo = false;        // the media has a video stream (render into its frames)
    std::string backgroundPath;   // rendered into this video, re-timed, instead (request.backgroundPath)
    double seconds = 0.0;         // wall time of generateFromSpeech

    int frameCount() const { return int(features.rows()); }
};

// Align, label and generate. Throws lipsync::Error naming the file at fault (media without
// sound, a transcript that does not fit the audio, a model made for another AAM, ...); Canceled.
// Words are pronounced from request.pronunciations, then the CMU dictionary, espeak-ng for the rest.
SpeechToFaceResult generateFromSpeech(const SpeechToFaceRequest &request, Feedback &feedback);
// The same from an alignment the caller made (`lipsync render`, with the aligner options every
// aligning command shares): its phones voted onto the frames with its own audio frames. `sound`
// is the recording's (request.mediaPath): the one the caller aligned, so it is decoded once.
SpeechToFaceResult generateFromAlignment(const SpeechToFaceRequest &request, const AlignerOutput &aligned,
                                         const RecordingSound &sound, Feedback &feedback);
// The same for a recording already aligned (a project sequence's phone tier, and its words if
// any): no aligner; request.transcriptPath and the aligner are not used.
SpeechToFaceResult generateFromPhones(const SpeechToFaceRequest &request, const Tier &phones,
                                      const Tier &words, Feedback &feedback);

// The renderer for a result: into the background video re-timed to the result's length when it
// has one, else into the media's own frames when it has video, else a neutral frame. (Tracking
// the clip for the pose reports into `feedback`.)
std::unique_ptr<FaceRenderer> makeRenderer(const SpeechToFaceResult &result,
                                           const std::string &mediaPath, Feedback &feedback);

struct RenderOptions
{
    bool sideBySide = false;  // the real clip left, the generated face right
    CompositeOptions composite; // the lower face, colour-matched (AamSynthesizer), unless set
    std::string leftLabel;    // drawn in the panels' corners when not empty (ASCII)
    std::string rightLabel;
    VideoExportOptions video; // frame rate is set from the result
};

// Frame `index` of the rendered clip.
cv::Mat renderFrame(const SpeechToFaceResult &result, FaceRenderer &renderer, int index,
                    const RenderOptions &options = {});

// Writes the rendered clip with the recording's sound (exportVideo: atomic, no file under `path`
// on error or cancel). Returns the frames written.
int exportRenderedVideo(const SpeechToFaceResult &result, FaceRenderer &renderer,
                        const std::string &path, Feedback &feedback, const RenderOptions &options = {});
// The rendered frames as PNGs in `folder` (exportImageSequence: atomic). Returns the files.
std::vector<std::string> exportRenderedImages(const SpeechToFaceResult &result, FaceRenderer &renderer,
                                              const std::string &folder, Feedback &feedback,
                                              const RenderOptions &options = {});

struct SpeechVideoReport
{
    SpeechToFaceResult generated;
    int framesWritten = 0;
    double renderSeconds = 0.0; // tracking + rendering + encoding
};

// Everything at once: generate from speech, render and write `outPath` (what `lipsync render` does
// step by step: align with its aligner options, generateFromAlignment, makeRenderer, export).
SpeechVideoReport renderSpeechVideo(const SpeechToFaceRequest &request, const std::string &outPath,
                                    Feedback &feedback, const RenderOptions &options = {});

} // namespace lipsync
