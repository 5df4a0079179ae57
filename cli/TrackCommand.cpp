// `lipsync track --model MODEL VIDEO --out FEATURES.csv`: fits the AAM to every frame (the previous
// frame initialises the next, re-detecting when the fit error jumps) and writes one row per frame
// with a face: the frame index, then the combined parameters (the paper's y_t).
#include "Command.h"

#include "aam/FaceDetector.h"
#include "aam/FaceTracker.h"
#include "aam/PtsFile.h"
#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "io/VideoReader.h"
#include "util/Error.h"

#include <QDir>
#include <QJsonObject>

#include <chrono>
#include <cstdio>
#include <sstream>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

int runTrack(const QStringList &args)
{
    const Arguments a(args);
    if (const QStringList bad = a.unknown({"model", "out", "json", "points"}); !bad.isEmpty())
        return fail("track: unknown option " + bad.join(", "), 2);
    if (a.positional().size() != 1 || !a.has("model") || !a.has("out"))
        return fail("usage: lipsync track --model MODEL VIDEO --out FEATURES.csv "
                    "[--points POINTS.csv] [--json]",
                    2);
    const std::string videoPath = a.positional().front().toStdString();
    const AamModel model = AamModel::load(a.value("model").toStdString());
    FaceDetectorPaths paths;
    paths.useDlib = false;
    FaceDetector detector(paths);
    if (!detector.hasYunet() && !detector.hasHaar())
        return fail("track: no face detector available (YuNet model or Haar cascade)");
    FaceTracker tracker(model, &detector);
    VideoReader video(videoPath);

    std::vector<int> frames;
    std::vector<Eigen::VectorXd> rows;
    std::ostringstream points;
    points << "frame,error";
    for (int i = 0; i < model.pointCount(); ++i)
        points << ",x" << i << ",y" << i;
    points << "\n";
    int total = 0, noFace = 0, redetections = 0;
    double errorSum = 0.0, seconds = 0.0;
    for (int index = 0; index < video.frameCount(); ++index) {
        ++total;
        const cv::Mat frame = video.frame(index);
        if (frame.empty()) {
            ++noFace;
            tracker.reset();
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const TrackedFrame tracked = tracker.track(frame);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        if (!tracked.found) {
            ++noFace;
            continue;
        }
        redetections += tracked.redetected ? 1 : 0;
        errorSum += tracked.fit.error;
        frames.push_back(index);
        rows.push_back(tracked.features);
        points << index << "," << tracked.fit.error;
        for (Eigen::Index k = 0; k < tracked.fit.shape.size(); ++k)
            points << "," << tracked.fit.shape[k];
        points << "\n";
    }
    if (total == 0)
        throw Error("the video holds no frames", videoPath);
    if (rows.empty())
        throw Error("no face found in any of the " + std::to_string(total) + " frames", videoPath);
    Eigen::MatrixXd values(Eigen::Index(rows.size()), model.combinedModes());
    for (size_t r = 0; r < rows.size(); ++r)
        values.row(Eigen::Index(r)) = rows[r].transpose();
    const std::string out = a.value("out").toStdString();
    writeFeatureCsv(out, values, frames);
    if (a.has("points"))
        writeFileAtomically(a.value("points").toStdString(), points.str());

    const int tracked = int(rows.size());
    const QJsonObject result{{"video", QString::fromStdString(videoPath)},
                             {"out", QString::fromStdString(out)},
                             {"model", QString::fromStdString(model.identifier)},
                             {"frames", total},
                             {"tracked", tracked},
                             {"no_face", noFace},
                             {"redetections", redetections},
                             {"parameters", model.combinedModes()},
                             {"mean_fit_error", errorSum / tracked},
                             {"fps", seconds > 0 ? tracked / seconds : 0.0}};
    if (a.flag("json"))
        printJson(result);
    else
        std::printf("tracked %d of %d frames (%d without a face), %.0f frames/s -> %s\n", tracked,
                    total, noFace, result["fps"].toDouble(), out.c_str());
    return 0;
}

const CommandRegistration registration{
    "track", "fit an AAM through a video and write per-frame features (--model MODEL VIDEO --out CSV)",
    &runTrack};

} // namespace
