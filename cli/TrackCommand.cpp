// `lipsync track VIDEO --aam AAM --out FEATURES.csv`: an AAM fitted through a video (VideoTracking),
// its combined parameters per frame written as CSV; `lipsync track FOLDER|PROJECT --aam AAM --out
// DIR` every video of a folder or project into DIR/ID.csv (BatchRunner). The declaration at the
// end describes it.
#include "BatchRunner.h"
#include "CommandLine.h"

#include "aam/FaceDetectorPool.h"
#include "aam/VideoTracking.h"
#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "tasks/Feedback.h"

#include "util/Error.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// Tracks `videoPath` with a detector of `detectors`, writes its features to `out` (and every
// frame's points to `pointsPath` if not empty); the --json report.
QJsonObject trackOne(const AamModel &model, const std::string &videoPath, const std::string &out,
                     const std::string &pointsPath, FaceDetectorPool &detectors, Feedback &feedback)
{
    const FaceDetectorPool::Lease detector(detectors);
    if (!detector->hasYunet() && !detector->hasHaar())
        throw Error("no face detector available (YuNet model or Haar cascade)");
    const VideoTrackingResult r = trackVideo(model, videoPath, *detector, feedback);
    const int frames = int(r.features.rows());
    writeFeatureCsv(out, r.features, {}, r.frameRate); // the rate labels in seconds need
    if (!pointsPath.empty()) {
        std::ostringstream points;
        points << "frame,error";
        for (int i = 0; i < model.pointCount(); ++i)
            points << ",x" << i << ",y" << i;
        points << "\n";
        for (int f = 0; f < frames; ++f) {
            points << f << ",";
            if (std::isfinite(r.errors[f]))
                points << r.errors[f];
            for (Eigen::Index k = 0; k < r.shapes.cols(); ++k)
                points << "," << r.shapes(f, k);
            points << "\n";
        }
        writeFileAtomically(pointsPath, points.str());
    }
    const int noFace = int(r.framesWithoutFace.size());
    const int tracked = frames - noFace;
    double errorSum = 0.0;
    for (int f = 0; f < frames; ++f)
        if (std::isfinite(r.errors[f]))
            errorSum += r.errors[f];
    QJsonArray missing, worst;
    for (int f : r.framesWithoutFace)
        missing.append(f);
    for (int f : r.worstFrames(5))
        worst.append(f);
    return QJsonObject{{"video", QString::fromStdString(videoPath)},
                       {"out", QString::fromStdString(out)},
                       {"model", QString::fromStdString(model.identifier)},
                       {"frames", frames},
                       {"tracked", tracked},
                       {"no_face", noFace},
                       {"frames_without_face", missing},
                       {"worst_frames", worst},
                       {"redetections", r.redetections},
                       {"parameters", model.combinedModes()},
                       {"mean_fit_error", tracked ? errorSum / tracked : 0.0},
                       {"fps", r.trackingSeconds > 0 ? frames / r.trackingSeconds : 0.0}};
}

int runTrack(const CommandLine &a)
{
    const AamModel model = AamModel::load(a.value("aam").toStdString());
    FaceDetectorPool detectors(FaceDetectorPaths::boxesOnly());
    const QString input = a.positional().front();
    if (isBatchInput(input)) {
        if (a.isSet("points"))
            throw UsageError(QStringLiteral("--points is for one video"));
        const QDir out = batchOutputFolder(a);
        std::vector<BatchJob> jobs;
        for (const BatchRecording &r : batchRecordings(input))
            jobs.push_back({r.id, r.media, {r.media, a.value("aam")}, out.filePath(r.id + QStringLiteral(".csv"))});
        makeOutputsUnique(jobs);
        const BatchRunner runner(a);
        return runner.finish(runner.run(jobs,
                                        [&](const BatchJob &job, Feedback &feedback) {
                                            return trackOne(model, job.file.toStdString(), job.output.toStdString(),
                                                            {}, detectors, feedback);
                                        }),
                             QStringLiteral("tracked"));
    }
    Feedback feedback;
    const QJsonObject result = trackOne(model, input.toStdString(), a.value("out").toStdString(),
                                        a.value("points").toStdString(), detectors, feedback);
    if (a.isSet("json"))
        printJson(result);
    else
        std::printf("tracked %d of %d frames (%d without a face), %.0f frames/s -> %s\n", result["tracked"].toInt(),
                    result["frames"].toInt(), result["no_face"].toInt(), result["fps"].toDouble(),
                    qPrintable(result["out"].toString()));
    return 0;
}

const CommandRegistration registration{
    CommandSpec{QStringLiteral("track"),
     QStringLiteral("fit an AAM through a video and write per-frame features (VIDEO --aam AAM --out CSV)"),
     QStringLiteral("Fits the AAM to every frame of a video (the previous frame initialises the next, "
                    "re-detecting the face when the fit error jumps) and writes one row per frame: the frame "
                    "index, then the combined parameters (the paper's y_t). Frames without a face take the "
                    "nearest tracked frame's parameters and are reported.\n"
                    "Given a folder of videos or a project folder, tracks every one in this process into --out "
                    "DIR/NAME.csv, for `lipsync project import PROJECT --features DIR`: -j at a time, skipping "
                    "those whose features are newer than their video and the AAM, with progress on stderr and "
                    "a list of the failures at the end (exit code 1 if any)."),
     {{QStringLiteral("aam"), QStringLiteral("AAM"), QStringLiteral("the AAM to fit (lipsync aam build)"), {},
       CommandOption::Required, {QStringLiteral("model")}},
      {QStringLiteral("out"), QStringLiteral("FEATURES.csv|DIR"),
       QStringLiteral("the per-frame features to write; with a folder to track, their folder"), {},
       CommandOption::Required},
      {QStringLiteral("points"), QStringLiteral("POINTS.csv"),
       QStringLiteral("also write every frame's fit error and landmark points")}},
     {{QStringLiteral("VIDEO"), QStringLiteral("the video to track, or a folder of videos, or a project folder")}}}
        .add(batchOptions()),
    &runTrack};

} // namespace
