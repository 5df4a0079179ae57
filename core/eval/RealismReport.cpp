#include "eval/RealismReport.h"

#include "aam/AamModel.h"
#include "animation/MouthMeasures.h"
#include "aam/FaceDetectorPool.h"
#include "align/FrameLabels.h"
#include "align/StreamingPhoneRecognizer.h"
#include "dynamics/LabelledFolder.h"
#include "eval/CrossValidation.h"
#include "eval/EncodedAppearance.h"
#include "eval/MachineObserver.h"
#include "eval/RealismMetrics.h"
#include "eval/Statistics.h"
#include "io/AudioDecoder.h"
#include "project/Project.h"
#include "render/BilabialClosure.h"
#include "render/FaceRenderer.h"
#include "render/PostureTransfer.h"
#include "render/LowerFaceWarp.h"
#include "tasks/BlockingMap.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonArray>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <numeric>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>

namespace lipsync {

const std::vector<std::string> &realismMetrics()
{
    // In the order a reader of the report takes them: does the mouth follow the speech (beside
    // the control that cannot be good), how much it moves and closes, can it be told from the
    // recording, then the picture's detail.
    static const std::vector<std::string> names{
        "speechCorrelation", "controlSpeechCorrelation", "shiftedSpeechCorrelation",
        "correlation",       "controlCorrelation",       "articulation",
        "closure",           "closureRecall",            "falseClosures",
        "falseClosuresRecorded", "observerFrames",       "observerVideos",
        "observerRecorded",  "observerWarped",           "observerNarrowed",
        "observerInsides",   "observerClosures",         "sharpness",
        "seamDeltaE",        "seamDeltaERecorded",       "seamDeltaENatural",
        "lag",               "shapeCorrelation"};
    return names;
}

namespace {

constexpr double kNoFigure = std::numeric_limits<double>::quiet_NaN();
const std::string kTracked = "tracked";
const std::string kReencoded = RealismMethod::kReencoded;
// The machine observer reads every other frame: neighbouring frames look alike, and memory stays
// small over hundreds of sequences.
constexpr int kObserverStep = 2;
// A moved-only frame counts as narrowed (FrameDrawing::Narrowed) where the warp took more than
// this share of the mouth's width, and at least a pixel, off the recorded inner-lip opening
// [choice: a pixel at GRID's mouth width].
constexpr double kNarrowedShare = 0.02;
const std::string kLive = "live ";

// The phone of each of `frames` video frames as live recognition hears the sequence's sound.
std::vector<int> liveLabels(const AcousticModel &acoustic, const PhoneBigram &bigram, const std::string &mediaPath,
                            const FrameClock &frames)
{
    const AudioBuffer sound = AudioDecoder::decode(mediaPath, acoustic.featureOptions().sampleRate);
    StreamingPhoneRecognizer recognizer(acoustic, bigram);
    constexpr size_t kBlock = 160;
    for (size_t at = 0; at < sound.samples.size(); at += kBlock)
        recognizer.push(sound.samples.data() + at, std::min(kBlock, sound.samples.size() - at));
    recognizer.finish();
    Tier phones{"phones", {}};
    StreamingPhoneRecognizer::appendToTier(phones, 0, recognizer.takeDecided(), acoustic.featureOptions());
    std::vector<int> labels;
    for (const std::string &label : voteFrameLabels(phones, frames, acoustic.featureOptions()))
        labels.push_back(PhoneSet::index(label));
    return labels;
}

double meanOfFinite(const std::vector<double> &values)
{
    double sum = 0;
    int n = 0;
    for (double v : values)
        if (std::isfinite(v)) {
            sum += v;
            ++n;
        }
    return n ? sum / n : kNoFigure;
}

// Mean over frames of `generated` divided by that of `recorded`, over the frames where both are finite.
double ratioOfMeans(const std::vector<double> &generated, const std::vector<double> &recorded)
{
    double g = 0, r = 0;
    for (size_t t = 0; t < std::min(generated.size(), recorded.size()); ++t)
        if (std::isfinite(generated[t]) && std::isfinite(recorded[t])) {
            g += generated[t];
            r += recorded[t];
        }
    return r > 0 ? g / r : kNoFigure;
}

struct Rendering
{
    std::string method;
    Eigen::MatrixXd features;
    // Generated renderings keep the background's posture (render/PostureTransfer); null: drawn as given.
    std::shared_ptr<const PostureTransfer> posture = nullptr;

    // The parameters of frame `row` as drawn into background frame `t`.
    Eigen::VectorXd drawn(int row, const FaceRenderer &renderer, int t) const
    {
        const Eigen::VectorXd c = features.row(row).transpose();
        return posture ? posture->apply(c, renderer.posture(t)) : c;
    }
};

// The colour step across the edge of what each method's render synthesised, per frame
// (seamDeltaE, seamDeltaERecorded, seamDeltaENatural).
class SeamSeries
{
public:
    SeamSeries(size_t methods, size_t frames)
        : m_seam(methods, std::vector<double>(frames, kNoFigure)), m_samePixels(m_seam), m_insideAsked(m_seam),
          m_trackedOpening(frames, kNoFigure), m_ownEdge(frames, kNoFigure)
    {}

    // Recorded frame t: its tracked opening and the step across its own inner-lip edge.
    void addRecorded(const FaceRenderer &renderer, int t, const cv::Mat &recorded)
    {
        const Eigen::VectorXd tracked = renderer.trackedShape(t);
        m_trackedOpening[size_t(t)] = LowerFaceWarp::opening(tracked);
        cv::Mat inside;
        renderer.insideWeight(tracked).convertTo(inside, CV_8U, 255.0);
        m_ownEdge[size_t(t)] = seamDeltaE(recorded, recorded, inside).frame;
    }

    // Method m's render `generated` of parameters c into recorded frame t (after addRecorded);
    // returns what the render drew there beyond moving the recording's face.
    FrameDrawing addRendered(size_t m, const FaceRenderer &renderer, int t, const Eigen::VectorXd &c,
                             const cv::Mat &generated, const cv::Mat &recorded)
    {
        const size_t ut = size_t(t);
        bool inside = false, closing = false;
        cv::Mat weight;
        renderer.synthesisedWeight(t, c, &inside, &closing).convertTo(weight, CV_8U, 255.0);
        const SeamDeltaE s = seamDeltaE(generated, recorded, weight);
        m_seam[m][ut] = s.frame;
        m_samePixels[m][ut] = s.reference;
        if (inside && std::isfinite(s.frame))
            m_insideAsked[m][ut] = LowerFaceWarp::opening(renderer.warpedShape(t, c));
        if (inside || closing)
            return inside ? FrameDrawing::Inside : FrameDrawing::Closed;
        const Eigen::VectorXd tracked = renderer.trackedShape(t);
        const double narrowing = LowerFaceWarp::opening(tracked) - LowerFaceWarp::opening(renderer.warpedShape(t, c));
        return narrowing > std::max(1.0, kNarrowedShare * LowerFaceWarp::mouthWidth(tracked)) ? FrameDrawing::Narrowed
                                                                                            : FrameDrawing::Warped;
    }

    void summarise(size_t m, RealismSequenceMethod &r) const
    {
        r.seamDeltaE = meanOfFinite(m_seam[m]);
        r.seamDeltaERecorded = meanOfFinite(m_samePixels[m]);
        r.seamDeltaENatural = meanOfFinite(naturalSeamDeltaE(m_samePixels[m], m_insideAsked[m], m_trackedOpening, m_ownEdge));
    }

private:
    std::vector<std::vector<double>> m_seam, m_samePixels; // per method and frame: render, recording
    std::vector<std::vector<double>> m_insideAsked;       // the opening asked where an inside was drawn
    std::vector<double> m_trackedOpening, m_ownEdge;      // per recorded frame
};

// "tracked" drawn with the parameters `renderer` tracked in its video, so that it is the recording
// itself (or, synthesising, its re-synthesis): the project's features come from another run of the
// tracker and differ by hundredths of a pixel, which the placement by the eyes
// (FaceRenderer::drawnPose) would turn into a warp, resampling the recorded face.
void drawTrackedAsTracked(const FaceRenderer &renderer, std::vector<Rendering> &renderings)
{
    const Eigen::MatrixXd &own = renderer.trackedFeatures();
    for (Rendering &r : renderings)
        if (r.method == kTracked && own.cols() == r.features.cols() && own.rows() >= r.features.rows())
            r.features = own.topRows(r.features.rows());
}

// What was drawn in the frames the machine observer reads (EncodedAppearance::appearance: every
// kObserverStep-th frame with a mouth box in the recording), where the renderer moves the
// recording's face; empty for a synthesised face, which is drawn whole.
std::vector<FrameDrawing> observedDrawing(const std::vector<FrameDrawing> &drawing,
                                          const std::vector<std::optional<cv::Rect2d>> &recordedBoxes,
                                          const CompositeOptions &composite)
{
    std::vector<FrameDrawing> out;
    if (composite.synthesisesFace())
        return out;
    for (size_t t = 0; t < drawing.size() && t < recordedBoxes.size(); t += kObserverStep)
        if (recordedBoxes[t])
            out.push_back(drawing[t]);
    return out;
}

// Renders and measures one held-out sequence (see the header).
RealismSequence measureSequence(const AamModel &aam, const std::string &mediaPath, const Sequence &sequence,
                                std::vector<Rendering> renderings, FaceDetector &detector,
                                const RealismOptions &options, Feedback &feedback)
{
    FaceRenderer renderer(aam, mediaPath, feedback, &detector);
    renderer.setCompositeOptions(options.composite);
    drawTrackedAsTracked(renderer, renderings);
    int frames = renderer.videoFrameCount();
    for (const Rendering &r : renderings)
        frames = std::min(frames, int(r.features.rows()));
    RealismSequence out;
    out.name = sequence.id;
    out.frames = frames;
    const size_t methods = renderings.size();
    std::vector<double> recordedOpening(size_t(frames), kNoFigure), recordedSharpness(size_t(frames), kNoFigure);
    std::vector<std::vector<double>> opening(methods, recordedOpening), sharpness(methods, recordedOpening);
    SeamSeries seams(methods, size_t(frames));
    // Frame t - T/2 drawn into frame t, whose mouth does not follow it (shiftedSpeechCorrelation).
    std::vector<std::vector<double>> shifted(methods, recordedOpening);
    std::vector<int> skipped(methods, 0);
    std::vector<std::vector<FrameDrawing>> drawing(methods, std::vector<FrameDrawing>(size_t(frames), FrameDrawing::Warped));
    // The inner-lip gap of each method's own shape (the AAM's inner-lip centres, normalised frame):
    // the mouth the animation exports carry, to compare with what the render shows.
    std::vector<std::vector<double>> shapeOpening(methods, recordedOpening);
    // The machine observer's mouth box in each stream's frames: dlib's mouth points of that frame
    // itself (the recording's for the recording), as a detector of rendered faces would crop it.
    // The recording's box on a render would say where the recording's mouth was: a cue no
    // viewer has.
    std::vector<std::vector<std::optional<cv::Rect2d>>> boxes(methods + 1,
                                                              std::vector<std::optional<cv::Rect2d>>(size_t(frames)));
    EncodedAppearance tapes(int(methods) + 1, options.observerCrf);
    cv::Mat generated;
    for (int t = 0; t < frames; ++t) {
        feedback.throwIfCanceled();
        const cv::Mat recorded = renderer.background(t);
        tapes.add(0, recorded);
        const std::vector<FaceDetection> faces = detector.detect(recorded);
        const std::optional<cv::Rect2d> box
            = faces.empty() ? std::nullopt : detector.dlibFaceBox(recorded, faces.front());
        const Eigen::VectorXd points = box ? detector.dlibLandmarksInBox(recorded, *box) : Eigen::VectorXd();
        if (points.size() != 136) {
            ++out.skippedFrames;
            for (size_t m = 0; m < methods; ++m) {
                recorded.copyTo(generated);
                renderer.renderInto(t, renderings[m].drawn(t, renderer, t), generated);
                tapes.add(int(m) + 1, generated);
            }
            continue;
        }
        const size_t ut = size_t(t);
        recordedOpening[ut] = innerLipOpening(points);
        const cv::Rect2d mouth = mouthBox(points);
        boxes[0][ut] = mouth;
        recordedSharpness[ut] = gradientEnergy(recorded, mouth);
        seams.addRecorded(renderer, t, recorded);
        for (size_t m = 0; m < methods; ++m) {
            const Eigen::VectorXd c = renderings[m].drawn(t, renderer, t);
            recorded.copyTo(generated);
            renderer.renderInto(t, c, generated);
            tapes.add(int(m) + 1, generated);
            shapeOpening[m][ut] = LowerFaceWarp::opening(renderer.synthesizer().shape(c));
            const Eigen::VectorXd rendered = detector.dlibLandmarksInBox(generated, *box);
            if (rendered.size() != 136) {
                ++skipped[m];
            } else {
                opening[m][ut] = innerLipOpening(rendered);
                boxes[m + 1][ut] = mouthBox(rendered);
            }
            sharpness[m][ut] = gradientEnergy(generated, mouth);
            drawing[m][ut] = seams.addRendered(m, renderer, t, c, generated, recorded);
            const int away = (t + frames - frames / 2) % frames;
            recorded.copyTo(generated);
            renderer.renderInto(t, renderings[m].drawn(away, renderer, t), generated);
            const Eigen::VectorXd there = detector.dlibLandmarksInBox(generated, *box);
            if (there.size() == 136)
                shifted[m][size_t(away)] = innerLipOpening(there);
        }
        feedback.setProgress(double(t + 1) / frames);
    }

    std::vector<double> energy(size_t(frames), kNoFigure);
    try {
        energy = audioEnergyPerFrame(AudioDecoder::decode(mediaPath), sequence.clock().slice(0, frames));
    } catch (const Error &) {
        // No sound: the lag is undefined, everything else stands.
    }
    out.lagRecorded = avLag(recordedOpening, energy, options.maxLag);
    out.closedLevel = closedLevel(recordedOpening);
    const std::vector<FrameRange> bilabials = bilabialSegments(sequence.phones, sequence.clock().slice(0, frames));
    out.bilabials = int(bilabials.size());
    out.closedRecorded = closedSegments(recordedOpening, bilabials, out.closedLevel);
    const FrameClock clock = sequence.clock().slice(0, frames);
    out.speech = speechFrames(sequence.phones, clock);
    out.speechSeconds = out.speech.last >= out.speech.first
                            ? clock.endTime(out.speech.last) - clock.time(out.speech.first)
                            : 0.0;
    out.falseClosuresRecorded = closuresOutside(recordedOpening, bilabials, out.speech, out.closedLevel);
    out.recordedOpening = recordedOpening;
    EncodedAppearance::Result seen = tapes.appearance(boxes, kObserverStep);
    out.recordedAppearance = std::move(seen.streams[0]);
    out.reencodedAppearance = std::move(seen.reencoded);
    for (size_t m = 0; m < methods; ++m) {
        RealismSequenceMethod r;
        r.correlation = pearsonOverFrames(opening[m], recordedOpening);
        r.speechCorrelation = pearsonOverFrames(onlyWithin(opening[m], out.speech), recordedOpening);
        r.shiftedSpeechCorrelation = pearsonOverFrames(onlyWithin(shifted[m], out.speech), recordedOpening);
        r.shapeCorrelation = pearsonOverFrames(shapeOpening[m], opening[m]);
        r.shapeOpening = std::move(shapeOpening[m]);
        r.closedBoth = closedInBoth(opening[m], recordedOpening, bilabials, out.closedLevel);
        r.falseClosures = closuresOutside(opening[m], bilabials, out.speech, out.closedLevel);
        r.appearance = std::move(seen.streams[m + 1]);
        r.drawing = observedDrawing(drawing[m], boxes[0], options.composite);
        r.articulation = articulationRatio(opening[m], recordedOpening);
        r.lag = avLag(opening[m], energy, options.maxLag) - out.lagRecorded;
        r.sharpness = ratioOfMeans(sharpness[m], recordedSharpness);
        seams.summarise(m, r);
        r.closed = closedSegments(opening[m], bilabials, out.closedLevel);
        r.skippedFrames = skipped[m];
        r.opening = std::move(opening[m]);
        out.methods[renderings[m].method] = r;
    }
    return out;
}

// The value of `metric` over one fold's sequences for one method (§6.3: the mean over the
// sequences where it is defined; closure counts pool the fold's segments and speech).
double foldValue(const std::vector<const RealismSequence *> &fold, const std::string &method,
                 const std::string &metric)
{
    if (fold.empty() || !fold.front()->methods.count(method))
        return kNoFigure;
    if (metric == "closure" || metric == "closureRecall") {
        int generated = 0, recorded = 0;
        for (const RealismSequence *s : fold) {
            const RealismSequenceMethod &r = s->methods.at(method);
            generated += metric == "closure" ? r.closed : r.closedBoth;
            recorded += s->closedRecorded;
        }
        return recorded > 0 ? double(generated) / recorded : kNoFigure;
    }
    if (metric == "falseClosures" || metric == "falseClosuresRecorded") {
        double closures = 0, seconds = 0;
        for (const RealismSequence *s : fold) {
            closures += metric == "falseClosures" ? s->methods.at(method).falseClosures : s->falseClosuresRecorded;
            seconds += s->speechSeconds;
        }
        return seconds > 0 ? closures / seconds : kNoFigure;
    }
    std::vector<double> values;
    for (size_t k = 0; k < fold.size(); ++k) {
        const RealismSequence &s = *fold[k];
        const RealismSequenceMethod &r = s.methods.at(method);
        if (metric == "controlCorrelation" || metric == "controlSpeechCorrelation") {
            // The recording against the render of another sequence of the fold.
            if (fold.size() < 2)
                return kNoFigure;
            const std::vector<double> &other = fold[(k + 1) % fold.size()]->methods.at(method).opening;
            values.push_back(pearsonOverFrames(other, metric == "controlCorrelation"
                                                          ? s.recordedOpening
                                                          : onlyWithin(s.recordedOpening, s.speech)));
            continue;
        }
        values.push_back(metric == "correlation"         ? r.correlation
                         : metric == "speechCorrelation" ? r.speechCorrelation
                         : metric == "shapeCorrelation"  ? r.shapeCorrelation
                         : metric == "shiftedSpeechCorrelation" ? r.shiftedSpeechCorrelation
                         : metric == "articulation"      ? r.articulation
                         : metric == "lag"               ? r.lag
                         : metric == "sharpness"         ? r.sharpness
                         : metric == "seamDeltaE"        ? r.seamDeltaE
                         : metric == "seamDeltaERecorded" ? r.seamDeltaERecorded
                         : metric == "seamDeltaENatural" ? r.seamDeltaENatural
                                                          : kNoFigure);
    }
    return meanOfFinite(values);
}

// The machine observer's held-out accuracy per fold for `method`: the recording against its
// render, or (kReencoded) against its own second encode.
std::vector<ObserverAccuracy> observerFolds(const std::vector<std::vector<const RealismSequence *>> &byFold,
                                            const std::string &method)
{
    std::vector<ObservedClip> clips;
    for (size_t f = 0; f < byFold.size(); ++f)
        for (const RealismSequence *s : byFold[f]) {
            if (method != kReencoded && !s->methods.count(method))
                continue;
            if (method == kReencoded)
                clips.push_back({int(f), s->recordedAppearance, s->reencodedAppearance, {}});
            else
                clips.push_back({int(f), s->recordedAppearance, s->methods.at(method).appearance,
                                 s->methods.at(method).drawing});
        }
    return observeByFold(clips, int(byFold.size()));
}

MetricSummary summarise(std::vector<double> foldValues)
{
    MetricSummary summary;
    summary.folds = std::move(foldValues);
    std::vector<double> defined;
    for (double v : summary.folds)
        if (std::isfinite(v))
            defined.push_back(v);
    const stats::MeanInterval interval = stats::meanWithCi95(defined);
    summary.mean = defined.empty() ? kNoFigure : interval.mean;
    summary.ci95 = defined.size() < 2 ? kNoFigure : interval.halfWidth;
    return summary;
}

// The report's rows: tracked, each model, each model's exemplars, each model driven live, the
// observer's control.
std::vector<std::string> reportedMethods(const std::vector<std::string> &kinds, bool live, bool exemplars)
{
    std::vector<std::string> methods{kTracked};
    methods.insert(methods.end(), kinds.begin(), kinds.end());
    if (exemplars)
        for (const std::string &kind : kinds)
            methods.push_back(kind + " exemplars");
    if (live)
        for (const std::string &kind : kinds)
            methods.push_back(kLive + kind);
    methods.push_back(kReencoded);
    return methods;
}

// Every measure of `method` over the folds: the observer's accuracy per fold, the others from
// the fold's sequences (foldValue).
RealismMethod summariseMethod(const std::vector<std::vector<const RealismSequence *>> &byFold, const std::string &method)
{
    RealismMethod m;
    m.kind = method;
    std::vector<double> frameAccuracy, videoAccuracy, recorded;
    std::array<std::vector<double>, kFrameDrawings> drawn;
    for (const ObserverAccuracy &a : observerFolds(byFold, method)) {
        frameAccuracy.push_back(a.frames);
        videoAccuracy.push_back(a.videos);
        recorded.push_back(a.recordedJudgedRendered);
        for (size_t k = 0; k < drawn.size(); ++k)
            drawn[k].push_back(a.drawnJudgedRendered[k]);
    }
    m.metrics["observerFrames"] = summarise(frameAccuracy);
    m.metrics["observerVideos"] = summarise(videoAccuracy);
    m.metrics["observerRecorded"] = summarise(recorded);
    m.metrics["observerWarped"] = summarise(drawn[size_t(FrameDrawing::Warped)]);
    m.metrics["observerNarrowed"] = summarise(drawn[size_t(FrameDrawing::Narrowed)]);
    m.metrics["observerInsides"] = summarise(drawn[size_t(FrameDrawing::Inside)]);
    m.metrics["observerClosures"] = summarise(drawn[size_t(FrameDrawing::Closed)]);
    for (const std::string &metric : realismMetrics()) {
        if (m.metrics.count(metric))
            continue;
        std::vector<double> folds;
        for (const auto &fold : byFold)
            folds.push_back(foldValue(fold, method, metric));
        m.metrics[metric] = summarise(folds);
    }
    return m;
}

// Every fold's models, trained on its training folds (or as much of their speech as
// cv.trainingSpeechSeconds asks: result.trainingSpeechSeconds says how much each got), each phone's
// mean moved by `prior` of that training set when given (ModelOptions::meanShift); `exemplars`,
// when given, receives each fold's training trajectories.
using FoldPrior = std::function<Eigen::MatrixXd(const std::vector<LabelledSequence> &, double *weight)>;
// A result of `sequences` sequences split into the folds of `cv`, nothing measured yet.
RealismResult foldedResult(const EvaluationOptions &cv, int sequences)
{
    RealismResult result;
    result.folds = cv.folds;
    result.seed = cv.seed;
    result.sequences = sequences;
    result.foldMembers = makeFolds(sequences, cv.folds, cv.seed);
    return result;
}

// Each fold's models' posture transfers (render/PostureTransfer; null where none applies or
// `keep` is false).
std::vector<std::vector<std::shared_ptr<const PostureTransfer>>>
posturesOf(const std::vector<std::vector<std::shared_ptr<DynamicModel>>> &models, const AamModel &aam, bool keep)
{
    std::vector<std::vector<std::shared_ptr<const PostureTransfer>>> out(models.size());
    for (size_t f = 0; f < models.size(); ++f)
        for (const std::shared_ptr<DynamicModel> &model : models[f])
            out[f].push_back(keep && model ? PostureTransfer::forModel(*model, aam) : nullptr);
    return out;
}

std::vector<std::vector<std::shared_ptr<DynamicModel>>> trainEveryFold(const std::vector<LabelledSequence> &sequences,
                                                                       const EvaluationOptions &cv,
                                                                       RealismResult &result, Feedback &feedback,
                                                                       std::vector<std::vector<Eigen::MatrixXd>> *exemplars,
                                                                       const FoldPrior &prior)
{
    std::vector<std::vector<std::shared_ptr<DynamicModel>>> models;
    for (int f = 0; f < cv.folds; ++f) {
        Feedback child(feedback, double(f) / cv.folds, double(f + 1) / cv.folds);
        const std::vector<LabelledSequence> trainingSet = trainingSequences(
            sequences, result.foldMembers[size_t(f)], cv.trainingSpeechSeconds, cv.seed + 1 + uint64_t(f));
        result.trainingSpeechSeconds.push_back(std::accumulate(
            trainingSet.begin(), trainingSet.end(), 0.0,
            [](double sum, const LabelledSequence &s) { return sum + speechSeconds(s); }));
        if (exemplars) {
            exemplars->emplace_back();
            for (const LabelledSequence &t : trainingSet)
                exemplars->back().push_back(t.features);
        }
        ModelOptions foldOptions = cv.modelOptions;
        if (prior) {
            double weight = 0;
            foldOptions.meanShift = prior(trainingSet, &weight);
            foldOptions.priorWeight = weight;
            result.priorWeights.push_back(weight);
        }
        models.push_back(trainFoldModels(trainingSet, cv.kinds, foldOptions, child,
                                         "fold " + std::to_string(f + 1) + "/" + std::to_string(cv.folds) + ": "));
    }
    return models;
}

// The phone means of HMM-mean and Brand started from other speakers' mouths (options.mouthPrior),
// combined with each fold's own training frames; none without a prior.
FoldPrior startFromPrior(const Project &project, const AamModel &aam, const RealismOptions &options)
{
    if (!options.mouthPrior)
        return {};
    auto measurer = std::make_shared<const MouthMeasurer>(aam);
    return [&project, &options, measurer](const std::vector<LabelledSequence> &trainingSet, double *weight) {
        return projectPriorShift(*options.mouthPrior, *measurer, project, trainingSet, options.mouthPriorWeight,
                                 weight);
    };
}

} // namespace

RealismResult evaluateRealism(const Project &project, const RealismOptions &options, Feedback &feedback)
{
    const EvaluationOptions &cv = options.crossValidation;
    const std::string aamPath = project.aamPath();
    for (const std::string &kind : cv.kinds)
        createDynamicModel(kind); // reject unknown kinds before any work
    FaceDetectorPaths paths;
    paths.dlibPredictor = options.dlibPredictor;
    // Detectors for the worker threads: dlib's predictor takes a second or two to load, and one
    // detector must not be used by two threads at once.
    FaceDetectorPool pool(paths);
    if (!FaceDetectorPool::Lease(pool)->hasDlib())
        throw Error("dlib's 68-point shape predictor is not available (install Debian's libdlib-data)",
                    pool.paths().dlibPredictorFile());
    std::vector<int> projectIndex;
    const std::vector<LabelledSequence> sequences = loadProjectSequences(project, &projectIndex);
    validateSequences(sequences);
    const AamModel aam = AamModel::load(aamPath);

    RealismResult result = foldedResult(cv, int(sequences.size()));

    // Training takes a small share of the time next to rendering and landmarking.
    Feedback training(feedback, 0.0, 0.1);
    const bool live = !options.liveAcousticModel.empty();
    const AcousticModel liveAcoustic = live ? AcousticModel::load(options.liveAcousticModel) : AcousticModel();
    const PhoneBigram liveBigram = live ? PhoneBigram::load(options.liveBigram) : PhoneBigram();
    std::vector<std::vector<Eigen::MatrixXd>> trainingFrames;
    const std::vector<std::vector<std::shared_ptr<DynamicModel>>> models
        = trainEveryFold(sequences, cv, result, training, options.exemplars ? &trainingFrames : nullptr,
                         startFromPrior(project, aam, options));
    std::vector<std::unique_ptr<ExemplarSelection>> selections;
    for (const std::vector<Eigen::MatrixXd> &frames : trainingFrames)
        selections.push_back(std::make_unique<ExemplarSelection>(frames, *options.exemplars));

    // Every held-out sequence on its own: rendering and landmarking are independent per sequence.
    struct Item
    {
        int sequence = 0, fold = 0;
        RealismSequence result;
    };
    std::vector<Item> items;
    for (int f = 0; f < cv.folds; ++f)
        for (int i : result.foldMembers[size_t(f)])
            items.push_back({i, f, {}});
    const std::optional<BilabialClosure> closure
        = options.closeBilabials ? BilabialClosure::forAam(aam) : std::nullopt;
    const auto postures = posturesOf(models, aam, options.keepPosture);
    std::mutex mutex;
    std::atomic<int> done{0};
    std::atomic<bool> stop{false};
    std::exception_ptr firstError;
    feedback.setStatus("rendering and landmarking the held-out sequences");
    lipsync::blockingMap(items, [&](Item &item) {
        if (stop.load())
            return;
        std::unique_ptr<FaceDetector> detector = pool.take();
        try {
            Feedback own;
            own.onProgress = [&](double) {
                if (stop.load() || feedback.isCanceled())
                    own.cancel();
            };
            const LabelledSequence &s = sequences[size_t(item.sequence)];
            const Sequence &sequence = project.sequences[size_t(projectIndex[size_t(item.sequence)])];
            std::vector<Rendering> renderings{{kTracked, s.features}};
            const std::vector<double> closing
                = BilabialClosure::weights(sequence.phones, sequence.clock().slice(0, s.frameCount()));
            auto closed = [&](Eigen::MatrixXd trajectory, const std::vector<double> &weights) {
                return closure ? closure->apply(trajectory, weights) : trajectory;
            };
            for (size_t k = 0; k < cv.kinds.size(); ++k)
                renderings.push_back({cv.kinds[k], closed(models[size_t(item.fold)][k]->generate(s.labels), closing),
                                      postures[size_t(item.fold)][k]});
            if (!selections.empty())
                for (size_t k = 0; k < cv.kinds.size(); ++k)
                    renderings.push_back({cv.kinds[k] + " exemplars",
                                          selections[size_t(item.fold)]->select(renderings[k + 1].features)});
            if (live) {
                const std::vector<int> heard = liveLabels(liveAcoustic, liveBigram, project.mediaPath(sequence),
                                                          sequence.clock().slice(0, s.frameCount()));
                for (size_t k = 0; k < cv.kinds.size(); ++k)
                    renderings.push_back({kLive + cv.kinds[k],
                                          closed(models[size_t(item.fold)][k]->generateStreamed(heard, true),
                                                 BilabialClosure::weights(heard)),
                                          postures[size_t(item.fold)][k]});
            }
            item.result = measureSequence(aam, project.mediaPath(sequence), sequence, renderings, *detector,
                                          options, own);
            item.result.fold = item.fold;
            feedback.setProgress(0.1 + 0.9 * double(++done) / double(items.size()));
        } catch (...) {
            const std::lock_guard lock(mutex);
            if (!firstError)
                firstError = std::current_exception();
            stop = true;
        }
        pool.give(std::move(detector));
    });
    if (firstError)
        std::rethrow_exception(firstError);
    feedback.throwIfCanceled();

    std::vector<std::vector<const RealismSequence *>> byFold(size_t(cv.folds));
    for (const Item &item : items) {
        result.frames += item.result.frames;
        result.skippedFrames += item.result.skippedFrames;
        result.bilabials += item.result.bilabials;
        result.closedRecorded += item.result.closedRecorded;
        byFold[size_t(item.fold)].push_back(&item.result);
    }
    for (const std::string &method : reportedMethods(cv.kinds, live, options.exemplars.has_value()))
        result.methods.push_back(summariseMethod(byFold, method));
    // Sequences in project order.
    std::sort(items.begin(), items.end(), [](const Item &a, const Item &b) { return a.sequence < b.sequence; });
    for (Item &item : items)
        result.perSequence.push_back(std::move(item.result));
    feedback.setProgress(1.0);
    return result;
}

QJsonObject RealismResult::toJson() const
{
    QJsonObject o;
    o[QStringLiteral("folds")] = folds;
    o[QStringLiteral("seed")] = QString::number(seed);
    o[QStringLiteral("sequences")] = sequences;
    o[QStringLiteral("frames")] = double(frames);
    o[QStringLiteral("skippedFrames")] = double(skippedFrames);
    o[QStringLiteral("trainingSpeechSeconds")] = jsonNumbers(trainingSpeechSeconds);
    if (!priorWeights.empty())
        o[QStringLiteral("priorWeights")] = jsonNumbers(priorWeights);
    o[QStringLiteral("bilabials")] = bilabials;
    o[QStringLiteral("closedRecorded")] = closedRecorded;
    QJsonObject methodsObject;
    for (const RealismMethod &m : methods) {
        QJsonObject mo;
        for (const auto &[name, summary] : m.metrics)
            mo[QString::fromStdString(name)] = summary.toJson();
        methodsObject[QString::fromStdString(m.kind)] = mo;
    }
    o[QStringLiteral("methods")] = methodsObject;
    QJsonArray sequencesArray;
    for (const RealismSequence &s : perSequence) {
        QJsonObject so;
        so[QStringLiteral("name")] = QString::fromStdString(s.name);
        so[QStringLiteral("fold")] = s.fold;
        so[QStringLiteral("frames")] = s.frames;
        so[QStringLiteral("skippedFrames")] = s.skippedFrames;
        so[QStringLiteral("bilabials")] = s.bilabials;
        so[QStringLiteral("closedRecorded")] = s.closedRecorded;
        so[QStringLiteral("closedLevel")] = jsonNumber(s.closedLevel);
        so[QStringLiteral("lagRecorded")] = jsonNumber(s.lagRecorded);
        so[QStringLiteral("recordedOpening")] = jsonNumbers(s.recordedOpening);
        QJsonObject mo;
        for (const auto &[method, r] : s.methods) {
            QJsonObject ro;
            ro[QStringLiteral("correlation")] = jsonNumber(r.correlation);
            ro[QStringLiteral("articulation")] = jsonNumber(r.articulation);
            ro[QStringLiteral("lag")] = jsonNumber(r.lag);
            ro[QStringLiteral("sharpness")] = jsonNumber(r.sharpness);
            ro[QStringLiteral("seamDeltaE")] = jsonNumber(r.seamDeltaE);
            ro[QStringLiteral("seamDeltaERecorded")] = jsonNumber(r.seamDeltaERecorded);
            ro[QStringLiteral("seamDeltaENatural")] = jsonNumber(r.seamDeltaENatural);
            ro[QStringLiteral("closed")] = r.closed;
            ro[QStringLiteral("skippedFrames")] = r.skippedFrames;
            ro[QStringLiteral("opening")] = jsonNumbers(r.opening);
            ro[QStringLiteral("shapeCorrelation")] = jsonNumber(r.shapeCorrelation);
            ro[QStringLiteral("shapeOpening")] = jsonNumbers(r.shapeOpening);
            ro[QStringLiteral("shiftedSpeechCorrelation")] = jsonNumber(r.shiftedSpeechCorrelation);
            mo[QString::fromStdString(method)] = ro;
        }
        so[QStringLiteral("methods")] = mo;
        sequencesArray.append(so);
    }
    o[QStringLiteral("perSequence")] = sequencesArray;
    return o;
}

} // namespace lipsync
