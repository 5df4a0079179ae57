#pragma once
// The realism report (docs/models.md §6.5): how much rendered faces move like the recording, on
// held-out sequences. The project's sequences are split into the folds of `lipsync evaluate`
// (§6.1, same seed, same list); every dynamic model is trained on the other folds, generates the
// held-out sequence from its phone labels, and is rendered into the recording's frames exactly as
// the studio's preview and `lipsync render` draw it (core/render FaceRenderer: AAM synthesis
// composited at the tracked head pose). "tracked" renders the sequence's own tracked parameters
// the same way: the AAM's re-synthesis, the ceiling the AAM allows.
//
// The lips are measured on the pixels, with dlib's 68-point predictor, independent of the AAM: on
// every frame of the recording the face is detected (core/aam FaceDetector) and the points
// predicted in dlib's box; each rendering of that frame is measured in the same box (the renderer
// draws the face at the recorded pose, so the head is where it was). A frame of the recording
// without a face is skipped and counted. Per sequence and method (core/eval/RealismMetrics):
//   correlation  Pearson correlation of the generated and the recorded lip opening over frames;
//   articulation s.d. of the generated opening / s.d. of the recorded one;
//   closure      /p b m/ segments where the lips reach the clip's closed level, generated /
//                recorded (pooled over a fold's sequences);
//   lag          the audio-visual lag (frames) of the generated opening minus the recording's;
//   sharpness    mean squared Laplacian in the mouth box, generated / recorded;
//   seamDeltaE   mean CIE Lab ΔE across the edge of the synthesised region in the render, and
//                seamDeltaERecorded the same pixel pairs in the recording; seamDeltaENatural the
//                step a real edge shows there: the same pixels of the recording where closed lips
//                were drawn, and where an inside was drawn the recording's own inner-lip edge in
//                its frames opened as wide (the same pixels of the recording hold its lips there);
//   speechCorrelation  the correlation over the speech frames alone (first to last spoken
//                phone), without the silence-speech-silence shape every clip shares;
//   controlCorrelation, controlSpeechCorrelation  the same with each recording paired with the
//                render of the next held-out sequence of its fold: what no lip-sync at all scores;
//   closureRecall /p b m/ segments closed in both the render and the recording / closed in the
//                recording (pooled over a fold);
//   falseClosures, falseClosuresRecorded  closures in the speech outside every /p b m/ segment,
//                per second of speech, in the render and in the recording;
//   observerFrames, observerVideos  the machine observer's held-out accuracy (MachineObserver:
//                0.5 cannot tell the render from the recording), with the row "re-encoded
//                recording" comparing the recording with its own second encode;
//   observerRecorded  the share of the recording's held-out frames the observer calls rendered
//                (its false alarms), beside which the next four read;
//   observerWarped, observerNarrowed, observerInsides, observerClosures  the share of rendered
//                frames it calls rendered among those where the recording's face was only moved
//                (its mouth not squeezed narrower), where it was only moved and its mouth squeezed
//                narrower (over 2 % of the mouth's width, at least a pixel), where an inside was
//                drawn, and where closed lips were drawn (FrameDrawing; the default composite
//                only): which of the renderer's steps give a frame away;
//   shapeCorrelation  Pearson correlation of the method's own inner-lip gap (the AAM shape of its
//                parameters: what the animation exports carry) with the opening measured on its
//                render: how faithfully the render draws the mouth it was given;
//   shiftedSpeechCorrelation  speechCorrelation with each frame t drawn into the footage half the
//                clip away (background frame t + T/2, circularly), whose mouth moves but not as
//                this recording's: drawn into its own frame, a render keeps some of the recorded
//                lips' movement (the warp moves the recording's lips by generated - tracked, so
//                where the tracker misfits them the misfit stays, and follows the recording);
//                here it does not count. What new speech rendered into a person's other footage
//                (render --background) shows.
// Fold value = mean over the fold's sequences (those where the value is defined); reported as the
// mean over folds with a 95 % t interval (§6.3).
#include "aam/AamSynthesizer.h"
#include "animation/MouthShapePrior.h"
#include "dynamics/ModelFile.h"
#include "eval/Evaluation.h"
#include "eval/MachineObserver.h"
#include "eval/RealismMetrics.h"
#include "render/ExemplarSelection.h"

#include <QJsonObject>

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;
class Project;

struct RealismOptions
{
    // The folds, seed, models and model options of `lipsync evaluate` (parallelFolds is not used:
    // the held-out sequences are measured in parallel).
    EvaluationOptions crossValidation;
    int maxLag = 5;            // audio-visual lags searched, frames either way
    std::string dlibPredictor; // empty: systempaths::kDlibPredictor (Debian's libdlib-data)
    CompositeOptions composite; // how the renders are drawn (the preview's by default)
    // Close the lips on /p b m/ in the models' trajectories (render/BilabialClosure), as renders
    // do by default; the tracked re-synthesis is never changed.
    bool closeBilabials = true;
    // Generated faces keep the posture of the frames they are drawn into (render/PostureTransfer),
    // as renders do by default.
    bool keepPosture = true;
    // Also every model driven live (render/LiveSession): each held-out sequence's phones
    // recognised from its sound as it streams in (StreamingPhoneRecognizer with this aligner
    // model and phone bigram), not taken from its forced alignment, and the face generated from
    // them frame by frame as Live does (DynamicModel::promptStreamer: Brand at its fixed lag,
    // phones in context guessed as they come); reported as "live <kind>".
    // Empty: not measured.
    std::string liveAcousticModel;
    std::string liveBigram;
    // Also every model's trajectory replaced by recorded frames of its training folds
    // (render/ExemplarSelection), reported as "<kind> exemplars". None: not measured.
    std::optional<ExemplarSelection::Options> exemplars;
    // The x264 quality at which the machine observer's streams are encoded (EncodedAppearance):
    // 0, lossless with colour at full resolution, by default, so that the encoder hides nothing
    // and gives nothing away (the recording against its own re-encode reads 0.5); the export's
    // quality (VideoExportOptions::crf) is what a viewer of an export gets.
    int observerCrf = 0;
    // The phone means of HMM-mean and Brand started from other speakers' mouths, combined with
    // each fold's own frames (animation/MouthShapePrior); null: the person's own means alone.
    std::shared_ptr<const MouthShapePrior> mouthPrior;
    double mouthPriorWeight = MouthShapePrior::kCrossValidated; // or frames
};

struct RealismSequenceMethod
{
    double correlation = 0, articulation = 0, lag = 0, sharpness = 0;
    double seamDeltaE = 0, seamDeltaERecorded = 0, seamDeltaENatural = 0;
    double speechCorrelation = 0;
    double shapeCorrelation = 0;
    double shiftedSpeechCorrelation = 0;
    int closed = 0;         // bilabial segments closed in the render
    int closedBoth = 0;     // ... and in the recording
    int falseClosures = 0;  // closures in the speech outside /p b m/
    Eigen::MatrixXf appearance; // the machine observer's view of the encoded render's frames
    std::vector<FrameDrawing> drawing; // what was drawn in each of them (empty: not split)
    int skippedFrames = 0;  // frames the predictor found no lips in the render
    std::vector<double> opening; // per frame (NaN: not measured)
    std::vector<double> shapeOpening; // the inner-lip gap of the method's own shape, per frame
};

struct RealismSequence
{
    std::string name;
    int fold = 0;
    int frames = 0;
    int skippedFrames = 0; // frames of the recording without a face
    int bilabials = 0;     // /p b m/ segments
    int closedRecorded = 0;
    double closedLevel = 0; // the recording's closed lip opening
    double lagRecorded = 0;
    FrameRange speech{0, -1}; // frames from the first to the last spoken phone
    double speechSeconds = 0;
    int falseClosuresRecorded = 0;
    std::vector<double> recordedOpening; // per frame (NaN: no face)
    Eigen::MatrixXf recordedAppearance;  // the machine observer's view of the re-encoded recording
    Eigen::MatrixXf reencodedAppearance; // ... and of its second encode
    std::map<std::string, RealismSequenceMethod> methods; // "tracked", "dpds", ...
};

struct RealismMethod
{
    // The machine observer's control: the recording told from its own second encode (no lips of
    // its own, only the observer's figures).
    static constexpr const char *kReencoded = "re-encoded recording";
    std::string kind;
    std::map<std::string, MetricSummary> metrics; // realismMetrics()
};

struct RealismResult
{
    int folds = 0;
    std::uint64_t seed = 0;
    int sequences = 0;
    long long frames = 0;
    long long skippedFrames = 0;
    int bilabials = 0;      // /p b m/ segments of all sequences
    int closedRecorded = 0; // of them closed in the recording
    std::vector<std::vector<int>> foldMembers;
    std::vector<double> trainingSpeechSeconds; // per fold: the speech its models were trained on
    std::vector<double> priorWeights;          // per fold with a mouth prior: the weight taken (frames)
    std::vector<RealismMethod> methods; // tracked first, then the options' kinds
    std::vector<RealismSequence> perSequence;

    QJsonObject toJson() const;
};

// Every measure's name (docs/models.md §6.5), in the order the CLI's table and the studio's list
// them: speechCorrelation, controlSpeechCorrelation, shiftedSpeechCorrelation, correlation,
// controlCorrelation, articulation, closure, closureRecall, falseClosures, falseClosuresRecorded,
// observerFrames, observerVideos, observerRecorded, observerWarped, observerNarrowed,
// observerInsides, observerClosures, sharpness, seamDeltaE, seamDeltaERecorded, seamDeltaENatural, lag,
// shapeCorrelation.
const std::vector<std::string> &realismMetrics();

// Throws lipsync::Error naming the project when it has no AAM, no sequence with features and
// phones, a sequence without media, or when dlib's predictor is not installed; Canceled.
RealismResult evaluateRealism(const Project &project, const RealismOptions &options, Feedback &feedback);

} // namespace lipsync
