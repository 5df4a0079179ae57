// `lipsync track VIDEO --aam AAM --out FEATURES.csv`: an AAM fitted through a video (VideoTracking),
// its combined parameters per frame written as CSV; the declaration at the end describes it.
#include "CommandLine.h"

#include "aam/FaceDetector.h"
#include "aam/VideoTracking.h"
#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "tasks/Feedback.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cmath>
#include <cstdio>
#include <sstream>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

int runTrack(const CommandLine &a)
{
    const std::string videoPath = a.positional().front().toStdString();
    const AamModel model = AamModel::load(a.value("aam").toStdString());
    FaceDetectorPaths paths;
    paths.useDlib = false;
    FaceDetector detector(paths);
    if (!detector.hasYunet() && !detector.hasHaar())
        return fail("track: no face detector available (YuNet model or Haar cascade)");
    Feedback feedback;
    const VideoTrackingResult r = trackVideo(model, videoPath, detector, feedback);
    const int frames = int(r.features.rows());
    const std::string out = a.value("out").toStdString();
    writeFeatureCsv(out, r.features, {}, r.frameRate); // the rate labels in seconds need
    if (a.isSet("points")) {
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
        writeFileAtomically(a.value("points").toStdString(), points.str());
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
    const QJsonObject result{{"video", QString::fromStdString(videoPath)},
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
    if (a.isSet("json"))
        printJson(result);
    else
        std::printf("tracked %d of %d frames (%d without a face), %.0f frames/s -> %s\n", tracked,
                    frames, noFace, result["fps"].toDouble(), out.c_str());
    return 0;
}

const CommandRegistration registration{
    {QStringLiteral("track"),
     QStringLiteral("fit an AAM through a video and write per-frame features (VIDEO --aam AAM --out CSV)"),
     QStringLiteral("Fits the AAM to every frame of a video (the previous frame initialises the next, "
                    "re-detecting the face when the fit error jumps) and writes one row per frame: the frame "
                    "index, then the combined parameters (the paper's y_t). Frames without a face take the "
                    "nearest tracked frame's parameters and are reported."),
     {{QStringLiteral("aam"), QStringLiteral("AAM"), QStringLiteral("the AAM to fit (lipsync aam build)"), {},
       CommandOption::Required, {QStringLiteral("model")}},
      {QStringLiteral("out"), QStringLiteral("FEATURES.csv"), QStringLiteral("the per-frame features to write"), {},
       CommandOption::Required},
      {QStringLiteral("points"), QStringLiteral("POINTS.csv"),
       QStringLiteral("also write every frame's fit error and landmark points")}},
     {{QStringLiteral("VIDEO"), QStringLiteral("the video to track")}}},
    &runTrack};

} // namespace
