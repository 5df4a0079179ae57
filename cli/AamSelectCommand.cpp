// `lipsync aam select --media DIR|FILES --count N --out DIR`: frames to train a person-specific
// AAM on (core/aam/FramePicking: farthest-point sampling of the detected faces' appearance),
// written as images with automatic 23 points (.pts beside each, as `landmarks detect` places them),
// so that `aam build --images DIR` builds from them. The frames whose points an AAM of the other
// picks disagrees with most are listed first for review.
#include "CommandLine.h"

#include "aam/AamModel.h"
#include "aam/FaceDetector.h"
#include "aam/FramePicking.h"
#include "aam/PtsFile.h"
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

// Frames listed for review in the text output.
constexpr int kReviewLines = 10;

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

int runAamSelect(const CommandLine &a)
{
    if (!a.isSet("media") && a.positional().isEmpty())
        throw UsageError("give --media DIR or the videos");
    FramePickingOptions options;
    options.count = a.integer("count", 1);
    options.step = a.integer("step", 1);
    options.dimensions = a.integer("dimensions", 1);
    options.review = !a.isSet("no-review");
    if (!parseAutoLandmarkMethod(a.value("method").toStdString(), options.method))
        throw UsageError("--method must be auto, dlib, aam or template");
    if (options.method == AutoLandmarkMethod::Aam && !a.isSet("aam"))
        throw UsageError("--method aam needs --aam AAM");
    const bool json = a.isSet("json");
    const auto started = std::chrono::steady_clock::now();

    const QStringList sources = selectSources(a);
    if (sources.isEmpty())
        throw Error("no video files (*.mpg, *.mp4, *.mov, *.avi, *.mkv)", a.value("media").toStdString());
    std::optional<AamModel> model;
    if (a.isSet("aam")) {
        model = AamModel::load(a.value("aam").toStdString());
        options.aam = &*model;
    }
    FaceDetectorPaths paths;
    paths.useDlib = options.method == AutoLandmarkMethod::Auto || options.method == AutoLandmarkMethod::Dlib;
    FaceDetector detector(paths);
    if (!detector.hasYunet() && !detector.hasHaar())
        return fail("aam select: no face detector available (YuNet model or Haar cascade)");
    std::vector<std::string> videos;
    for (const QString &source : sources)
        videos.push_back(source.toStdString());
    Feedback feedback;
    if (!json)
        feedback.onStatus = [](const std::string &s) { std::fprintf(stderr, "aam select: %s\n", s.c_str()); };
    const FramePicking picked = pickFramesToLabel(videos, options, detector, feedback);

    // The picks as PNGs with their .pts, named after the clip and frame.
    const QDir out(a.value("out"));
    if (!QDir().mkpath(out.path()))
        throw Error("cannot create the folder", out.path().toStdString(), "--out");
    std::map<QString, int> methods;
    std::vector<QString> images;
    for (const PickedFrame &f : picked.frames) {
        const QString stem = QStringLiteral("%1_%2").arg(QFileInfo(sources[f.source]).completeBaseName()).arg(f.frame);
        const QString image = out.filePath(stem + ".png"), pts = out.filePath(stem + ".pts");
        if (!cv::imwrite(image.toStdString(), f.pixels))
            throw Error("cannot write the image", image.toStdString());
        writePtsFile(pts.toStdString(), f.shape);
        images.push_back(image);
        ++methods[QString::fromStdString(f.method)];
    }

    for (const auto &w : picked.warnings)
        std::fprintf(stderr, "lipsync: warning: %s\n", w.c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    const bool review = options.review && picked.frames.size() >= 3;
    QSet<int> clipsUsed;
    QJsonArray selected, reviewList;
    for (size_t i = 0; i < picked.frames.size(); ++i) {
        const PickedFrame &f = picked.frames[i];
        clipsUsed.insert(f.source);
        const QString pts = images[i].left(images[i].size() - 4) + QStringLiteral(".pts");
        selected.append(QJsonObject{{"image", images[i]},
                                    {"pts", pts},
                                    {"source", sources[f.source]},
                                    {"frame", f.frame},
                                    {"method", QString::fromStdString(f.method)},
                                    {"distance", std::isfinite(f.distance) ? QJsonValue(f.distance) : QJsonValue()},
                                    {"disagreement", review ? QJsonValue(f.disagreement) : QJsonValue()}});
    }
    if (review)
        for (int i : picked.worstFirst)
            reviewList.append(QJsonObject{{"image", images[size_t(i)]}, {"disagreement", picked.frames[size_t(i)].disagreement}});
    QJsonObject methodCounts;
    for (const auto &[name, n] : methods)
        methodCounts[name] = n;
    QJsonArray warningArray;
    for (const auto &w : picked.warnings)
        warningArray.append(QString::fromStdString(w));
    QJsonArray isolatedList;
    for (const auto &[source, frame] : picked.isolated)
        isolatedList.append(QStringLiteral("%1 frame %2").arg(QFileInfo(sources[source]).fileName()).arg(frame));
    if (json) {
        printJson(QJsonObject{{"out", a.value("out")},
                              {"sources", int(sources.size())},
                              {"clips_used", int(clipsUsed.size())},
                              {"candidates", picked.candidates},
                              {"isolated", isolatedList},
                              {"count", int(picked.frames.size())},
                              {"step", options.step},
                              {"dimensions", options.dimensions},
                              {"detector", QString::fromStdString(detector.available())},
                              {"methods", methodCounts},
                              {"selected", selected},
                              {"review", reviewList},
                              {"seconds", seconds},
                              {"warnings", warningArray}});
        return 0;
    }
    std::printf("selected %d of %d candidate frames from %d of %d clips -> %s (", int(picked.frames.size()),
                picked.candidates, int(clipsUsed.size()), int(sources.size()), qPrintable(a.value("out")));
    bool first = true;
    for (const auto &[name, n] : methods) {
        std::printf("%s%s %d", first ? "" : ", ", qPrintable(name), n);
        first = false;
    }
    std::printf(")\n");
    if (!picked.isolated.empty())
        std::printf("left out %d candidate frames unlike any frame of another clip (e.g. %s)\n",
                    int(picked.isolated.size()), qPrintable(isolatedList.first().toString()));
    if (review) {
        std::printf("review first (NME between the automatic points and an AAM of the other frames fitted from them):\n");
        for (size_t i = 0; i < picked.worstFirst.size() && int(i) < kReviewLines; ++i) {
            const int k = picked.worstFirst[i];
            std::printf("  %.4f  %s\n", picked.frames[size_t(k)].disagreement, qPrintable(images[size_t(k)]));
        }
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
