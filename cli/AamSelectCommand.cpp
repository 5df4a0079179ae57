// `lipsync aam select --media DIR|FILES --count N --out DIR`: frames to train a person-specific
// AAM on, chosen to differ from each other (core/aam/FrameSelection: farthest-point sampling of
// the detected faces' appearance), written as images with automatic 23 points (.pts beside each,
// as `landmarks detect` places them), so that `aam build --images DIR` builds from them. The
// frames whose points an AAM of the other picks disagrees with most are listed first for review.
#include "CommandLine.h"

#include "aam/AamBuilder.h"
#include "aam/AamFitter.h"
#include "aam/AutoLandmarks.h"
#include "aam/FaceDetector.h"
#include "aam/FrameSelection.h"
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QSet>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// Detections below this score are not candidates (flat grey frames before a keyframe, blur).
constexpr double kMinSelectScore = 0.8;
// Frames listed for review in the text output.
constexpr int kReviewLines = 10;

struct SelectCandidate
{
    int source = 0;
    int frame = 0;
    FaceDetection face;
};

struct SelectedFrame
{
    SelectCandidate candidate;
    double distance = 0.0; // farthest-point distance when picked
    QString image, pts, method;
    cv::Mat pixels;
    Eigen::VectorXd shape;
    double disagreement = -1.0;
};

QStringList selectSources(const CommandLine &a)
{
    QStringList sources;
    if (a.isSet("media")) {
        const QDir dir(a.value("media"));
        if (!dir.exists())
            throw Error("directory does not exist", a.value("media").toStdString(), "--media");
        for (const QString &name : dir.entryList({"*.mpg", "*.mp4", "*.mov", "*.avi", "*.mkv"}, QDir::Files,
                                                 QDir::Name))
            sources << dir.filePath(name);
    }
    sources << a.positional();
    return sources;
}

// Held-out folds of the review.
constexpr int kReviewFolds = 5;

// NME between each frame's automatic points and where an AAM built from the other frames (5-fold:
// a misplaced point is not in the model that judges it), fitted from those points at the finest
// level, moves them: large for a misplaced point, or a face none of the other frames resembles.
// With fewer than 2 x kReviewFolds frames, one AAM of all of them judges.
void reviewSelection(std::vector<SelectedFrame> &frames, std::vector<std::string> &warnings)
{
    const int folds = int(frames.size()) >= 2 * kReviewFolds ? kReviewFolds : 1;
    AamBuildOptions build;
    build.referenceEyeDistance = 50; // placement, not texture detail, is judged: the small frame is enough
    build.levels = 1;
    AamFitOptions fit;
    fit.coarsestLevel = 0;
    for (int fold = 0; fold < folds; ++fold) {
        std::vector<AamTrainingExample> examples;
        for (size_t i = 0; i < frames.size(); ++i)
            if (folds == 1 || int(i) % folds != fold)
                examples.push_back({frames[i].image.toStdString(), {}, frames[i].pixels.clone(), frames[i].shape});
        Feedback feedback;
        const AamModel model = buildAam(std::move(examples), build, feedback, &warnings);
        const AamFitter fitter(model);
        for (size_t i = 0; i < frames.size(); ++i)
            if (folds == 1 || int(i) % folds == fold)
                frames[i].disagreement =
                    normalisedMeanError(fitter.fit(frames[i].pixels, frames[i].shape, fit).shape, frames[i].shape);
    }
}

int runAamSelect(const CommandLine &a)
{
    if (!a.isSet("media") && a.positional().isEmpty())
        throw UsageError("give --media DIR or the videos");
    const int count = a.integer("count", 1);
    const int step = a.integer("step", 1);
    const int dimensions = a.integer("dimensions", 1);
    AutoLandmarkMethod method = AutoLandmarkMethod::Auto;
    if (!parseAutoLandmarkMethod(a.value("method").toStdString(), method))
        throw UsageError("--method must be auto, dlib, aam or template");
    if (method == AutoLandmarkMethod::Aam && !a.isSet("aam"))
        throw UsageError("--method aam needs --aam AAM");
    const bool json = a.isSet("json");
    const auto started = std::chrono::steady_clock::now();

    const QStringList sources = selectSources(a);
    if (sources.isEmpty())
        throw Error("no video files (*.mpg, *.mp4, *.mov, *.avi, *.mkv)", a.value("media").toStdString());
    std::optional<AamModel> model;
    if (a.isSet("aam"))
        model = AamModel::load(a.value("aam").toStdString());
    FaceDetectorPaths paths;
    paths.useDlib = method == AutoLandmarkMethod::Auto || method == AutoLandmarkMethod::Dlib;
    FaceDetector detector(paths);
    if (!detector.hasYunet() && !detector.hasHaar())
        return fail("aam select: no face detector available (YuNet model or Haar cascade)");

    // 1. Candidates: every step-th frame of every clip with a confident face, described by its
    //    appearance.
    std::vector<SelectCandidate> candidates;
    std::vector<Eigen::VectorXd> descriptors;
    std::vector<std::string> warnings;
    for (int s = 0; s < sources.size(); ++s) {
        VideoReader video(sources[s].toStdString());
        for (int t = step / 2; t < video.frameCount(); t += step) {
            const cv::Mat frame = video.frame(t);
            const std::vector<FaceDetection> faces = detector.detect(frame);
            if (faces.empty() || faces.front().score < kMinSelectScore)
                continue;
            // With dlib, the face is placed in the descriptor by its eye points and its mouth
            // and jaw points join the descriptor; YuNet's keypoints alone are a few pixels off.
            Eigen::VectorXd points;
            if (detector.hasDlib()) {
                const Eigen::VectorXd ibug = detector.dlibLandmarks(frame, faces.front());
                if (ibug.size() != 2 * scheme23::kIbugPointCount)
                    continue;
                points = mapIbug68To23(ibug);
            }
            candidates.push_back({s, t, faces.front()});
            descriptors.push_back(faceAppearanceDescriptor(frame, faces.front(), points));
        }
        if (!json)
            std::fprintf(stderr, "\raam select: %d/%d clips, %zu candidate frames", int(s + 1),
                         int(sources.size()), candidates.size());
    }
    if (!json)
        std::fprintf(stderr, "\n");
    if (candidates.empty())
        return fail("aam select: no face found in any candidate frame");
    Eigen::MatrixXd descriptorMatrix(descriptors.front().size(), Eigen::Index(descriptors.size()));
    for (size_t i = 0; i < descriptors.size(); ++i)
        descriptorMatrix.col(Eigen::Index(i)) = descriptors[i];
    std::vector<int> groups, excluded;
    for (const SelectCandidate &c : candidates)
        groups.push_back(c.source);
    const DiverseSelection selection = selectDiverseFrames(descriptorMatrix, count, dimensions, groups, &excluded);

    // 2. Write the picks with their automatic points, clip by clip.
    std::vector<SelectedFrame> frames;
    for (size_t k = 0; k < selection.picks.size(); ++k) {
        SelectedFrame f;
        f.candidate = candidates[size_t(selection.picks[k])];
        f.distance = selection.distances[k];
        frames.push_back(std::move(f));
    }
    std::stable_sort(frames.begin(), frames.end(), [](const SelectedFrame &x, const SelectedFrame &y) {
        return std::pair(x.candidate.source, x.candidate.frame) < std::pair(y.candidate.source, y.candidate.frame);
    });
    const QDir out(a.value("out"));
    if (!QDir().mkpath(out.path()))
        throw Error("cannot create the folder", out.path().toStdString(), "--out");
    std::map<QString, int> methods;
    std::optional<VideoReader> video;
    for (SelectedFrame &f : frames) {
        const QString source = sources[f.candidate.source];
        if (!video || video->path() != source.toStdString())
            video.emplace(source.toStdString());
        f.pixels = video->frame(f.candidate.frame);
        const AutoLandmarks points =
            detectAutoLandmarks(f.pixels, f.candidate.face, detector, method, model ? &*model : nullptr);
        f.shape = points.shape;
        f.method = QString::fromStdString(points.method);
        ++methods[f.method];
        const QString stem = QStringLiteral("%1_%2").arg(QFileInfo(source).completeBaseName()).arg(f.candidate.frame);
        f.image = out.filePath(stem + ".png");
        f.pts = out.filePath(stem + ".pts");
        if (!cv::imwrite(f.image.toStdString(), f.pixels))
            throw Error("cannot write the image", f.image.toStdString());
        writePtsFile(f.pts.toStdString(), f.shape);
    }

    // 3. Review order.
    const bool review = !a.isSet("no-review") && frames.size() >= 3;
    if (review)
        reviewSelection(frames, warnings);
    std::vector<const SelectedFrame *> worstFirst;
    for (const SelectedFrame &f : frames)
        worstFirst.push_back(&f);
    std::stable_sort(worstFirst.begin(), worstFirst.end(),
                     [](const SelectedFrame *x, const SelectedFrame *y) { return x->disagreement > y->disagreement; });

    for (const auto &w : warnings)
        std::fprintf(stderr, "lipsync: warning: %s\n", w.c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    QSet<int> clipsUsed;
    QJsonArray selected, reviewList;
    for (const SelectedFrame &f : frames) {
        clipsUsed.insert(f.candidate.source);
        selected.append(QJsonObject{{"image", f.image},
                                    {"pts", f.pts},
                                    {"source", sources[f.candidate.source]},
                                    {"frame", f.candidate.frame},
                                    {"method", f.method},
                                    {"distance", std::isfinite(f.distance) ? QJsonValue(f.distance) : QJsonValue()},
                                    {"disagreement", review ? QJsonValue(f.disagreement) : QJsonValue()}});
    }
    if (review)
        for (const SelectedFrame *f : worstFirst)
            reviewList.append(QJsonObject{{"image", f->image}, {"disagreement", f->disagreement}});
    QJsonObject methodCounts;
    for (const auto &[name, n] : methods)
        methodCounts[name] = n;
    QJsonArray warningArray;
    for (const auto &w : warnings)
        warningArray.append(QString::fromStdString(w));
    QJsonArray isolatedList;
    for (int i : excluded)
        isolatedList.append(QStringLiteral("%1 frame %2")
                                .arg(QFileInfo(sources[candidates[size_t(i)].source]).fileName())
                                .arg(candidates[size_t(i)].frame));
    if (json) {
        printJson(QJsonObject{{"out", a.value("out")},
                              {"sources", int(sources.size())},
                              {"clips_used", int(clipsUsed.size())},
                              {"candidates", int(candidates.size())},
                              {"isolated", isolatedList},
                              {"count", int(frames.size())},
                              {"step", step},
                              {"dimensions", dimensions},
                              {"detector", QString::fromStdString(detector.available())},
                              {"methods", methodCounts},
                              {"selected", selected},
                              {"review", reviewList},
                              {"seconds", seconds},
                              {"warnings", warningArray}});
        return 0;
    }
    std::printf("selected %d of %d candidate frames from %d of %d clips -> %s (", int(frames.size()),
                int(candidates.size()), int(clipsUsed.size()), int(sources.size()), qPrintable(a.value("out")));
    bool first = true;
    for (const auto &[name, n] : methods) {
        std::printf("%s%s %d", first ? "" : ", ", qPrintable(name), n);
        first = false;
    }
    std::printf(")\n");
    if (!excluded.empty())
        std::printf("left out %d candidate frames unlike any frame of another clip (e.g. %s)\n",
                    int(excluded.size()), qPrintable(isolatedList.first().toString()));
    if (review) {
        std::printf("review first (NME between the automatic points and an AAM of the other frames fitted from them):\n");
        for (size_t i = 0; i < worstFirst.size() && int(i) < kReviewLines; ++i)
            std::printf("  %.4f  %s\n", worstFirst[i]->disagreement, qPrintable(worstFirst[i]->image));
    }
    return 0;
}

const CommandRegistration selectRegistration{
    {"aam select", "pick diverse video frames to label and auto-landmark them (--media DIR --out DIR)",
     "Picks diverse frames of many clips for an AAM: every --step-th frame with a confident face, described "
     "by its appearance (mouth region, face, mouth and jaw points), reduced by PCA, then chosen by "
     "farthest-point sampling, leaving out frames unlike any frame of another clip. Each is written as a "
     "PNG with automatic 23 points (.pts, as landmarks detect), and listed worst-fitting first for review "
     "(an AAM of the other frames, 5-fold). Then: lipsync aam build --images DIR.",
     {{"media", "DIR", "a folder of videos (*.mpg, *.mp4, *.mov, *.avi, *.mkv)"},
      {"out", "DIR", "where the frames and their .pts go", {}, CommandOption::Required},
      {"count", "N", "how many frames to pick", QStringLiteral("150")},
      {"step", "N", "look at every N-th frame", QStringLiteral("5")},
      {"method", "auto|dlib|aam|template", "how the points are placed (as landmarks detect)", QStringLiteral("auto")},
      {"aam", "AAM", "the AAM for --method aam (or auto without dlib)", {}, CommandOption::Optional, {"model"}},
      {"dimensions", "N", "PCA dimensions of the appearance description", QStringLiteral("24")},
      {"no-review", {}, "skip the worst-first review"}},
     {{"VIDEO...", "videos to pick from (besides --media)", true}}},
    &runAamSelect};

} // namespace
