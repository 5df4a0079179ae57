// `lipsync landmarks detect IMAGE|VIDEO [--frame N] --out FILE.pts`: automatic 23 points for a
// face. dlib's 68-point predictor when installed, else an AAM fit from the detector (--aam), else
// the template shape placed on the detection. `landmarks detect FOLDER|PROJECT --out DIR`: every
// image and video (at --frame) of a folder, or every sequence of a project, into DIR/NAME.pts
// (BatchRunner).
#include "BatchRunner.h"
#include "CommandLine.h"

#include "aam/AamFitter.h"
#include "aam/AamModel.h"
#include "aam/AutoLandmarks.h"
#include "aam/FaceDetectorPool.h"
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "io/MediaFolder.h"
#include "io/VideoReader.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <optional>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

bool isImageFile(const QString &path)
{
    static const QStringList extensions{".jpg", ".jpeg", ".png", ".bmp", ".tif", ".tiff", ".ppm", ".pgm"};
    for (const QString &ext : extensions)
        if (path.endsWith(ext, Qt::CaseInsensitive))
            return true;
    return false;
}

struct DetectOptions
{
    AutoLandmarkMethod how = AutoLandmarkMethod::Auto;
    bool useDlib = true;
    int frame = 0;
    bool frameGiven = false;
    const AamFitter *fitter = nullptr; // made once for every image
};

FaceDetectorPaths detectorPaths(const DetectOptions &o)
{
    FaceDetectorPaths paths;
    paths.useDlib = o.useDlib;
    return paths;
}

// The image `input` is, or its video's frame; errors name the file.
cv::Mat readInput(const std::string &input, const DetectOptions &o)
{
    if (isImageFile(QString::fromStdString(input))) {
        cv::Mat image = cv::imread(input, cv::IMREAD_COLOR);
        if (image.empty())
            throw Error("cannot read the image", input);
        return image;
    }
    VideoReader video(input);
    if (o.frame >= video.frameCount())
        throw Error("the video has no frame " + std::to_string(o.frame) + " (" + std::to_string(video.frameCount())
                        + " frames)",
                    input, "--frame");
    cv::Mat image = video.frame(o.frame);
    if (image.empty())
        throw Error("frame " + std::to_string(o.frame) + " cannot be decoded", input);
    return image;
}

// Finds the points of the first face of `input` with a detector of `detectors` and writes them to
// `out`; the --json report.
QJsonObject detectOne(const std::string &input, const std::string &out, const DetectOptions &o,
                      FaceDetectorPool &detectors)
{
    const cv::Mat image = readInput(input, o);
    const FaceDetectorPool::Lease lease(detectors);
    FaceDetector &detector = *lease;
    const std::vector<FaceDetection> faces = detector.detect(image);
    if (faces.empty())
        throw Error("no face found" + (o.frameGiven ? " in frame " + std::to_string(o.frame) : std::string())
                        + " (detectors: " + detector.available() + ")",
                    input);
    const FaceDetection &face = faces.front();
    const AutoLandmarks found = detectAutoLandmarks(image, face, detector, o.how, o.fitter);
    const Eigen::VectorXd &shape = found.shape;
    writePtsFile(out, shape);
    QJsonArray points;
    for (int i = 0; i < scheme23::kPointCount; ++i)
        points.append(QJsonArray{shape[2 * i], shape[2 * i + 1]});
    return QJsonObject{
        {"input", QString::fromStdString(input)},
        {"frame", isImageFile(QString::fromStdString(input)) ? 0 : o.frame},
        {"out", QString::fromStdString(out)},
        {"method", QString::fromStdString(found.method)},
        {"points", points},
        {"face", QJsonObject{{"x", face.box.x}, {"y", face.box.y}, {"width", face.box.width},
                             {"height", face.box.height}, {"score", face.score},
                             {"detector", QString::fromStdString(face.source)}}},
        {"faces", int(faces.size())},
        {"state", "automatic"}};
}

// Every image and video of a folder (or sequence of a project) into `--out` DIR/NAME.pts.
int detectFolder(const CommandLine &a, const DetectOptions &o, const QString &modelFile)
{
    const QString folder = a.positional().front();
    const QDir out = batchOutputFolder(a);
    std::vector<std::pair<QString, QString>> inputs; // name, file
    for (const QFileInfo &image : QDir(folder).entryInfoList(QDir::Files, QDir::Name))
        if (isImageFile(image.fileName()) && !image.fileName().startsWith(QLatin1Char('.')))
            inputs.emplace_back(image.completeBaseName(), image.absoluteFilePath());
    try {
        for (const BatchRecording &r : batchRecordings(folder))
            inputs.emplace_back(r.id, r.media);
    } catch (const Error &) {
        if (inputs.empty())
            throw Error("no images, media files (" + mediaExtensionList() + ") or project.json", folder.toStdString());
    }
    std::vector<BatchJob> jobs;
    for (const auto &[name, file] : inputs) {
        QStringList depends{file};
        if (!modelFile.isEmpty())
            depends << modelFile;
        jobs.push_back({name, file, depends, out.filePath(name + QStringLiteral(".pts"))});
    }
    makeOutputsUnique(jobs);
    FaceDetectorPool detectors(detectorPaths(o));
    const BatchRunner runner(a);
    return runner.finish(runner.run(jobs,
                                    [&](const BatchJob &job, Feedback &) {
                                        return detectOne(job.file.toStdString(), job.output.toStdString(), o, detectors);
                                    }),
                         QStringLiteral("landmarked"));
}

int runLandmarksDetect(const CommandLine &a)
{
    const QString method = a.value("method");
    DetectOptions o;
    if (!parseAutoLandmarkMethod(method.toStdString(), o.how))
        throw UsageError("--method must be auto, dlib, aam or template");
    if (method == "aam" && !a.isSet("aam"))
        throw UsageError("--method aam needs --aam AAM");
    o.useDlib = method == "auto" || method == "dlib";
    o.frame = a.integer("frame", 0);
    o.frameGiven = a.isSet("frame");
    std::optional<AamModel> model;
    std::optional<AamFitter> fitter;
    if (a.isSet("aam")) {
        model = AamModel::load(a.value("aam").toStdString());
        fitter.emplace(*model);
    }
    o.fitter = fitter ? &*fitter : nullptr;
    const QString input = a.positional().front();
    if (isBatchInput(input))
        return detectFolder(a, o, a.value("aam"));
    if (isImageFile(input) && o.frameGiven && o.frame != 0)
        throw UsageError("--frame applies to videos only");
    FaceDetectorPool detectors(detectorPaths(o));
    const QJsonObject result = detectOne(input.toStdString(), a.value("out").toStdString(), o, detectors);
    if (a.isSet("json"))
        printJson(result);
    else
        std::printf("%s: 23 points (%s) -> %s\n", qPrintable(input), qPrintable(result["method"].toString()),
                    qPrintable(result["out"].toString()));
    return 0;
}

const CommandRegistration registration{
    CommandSpec{"landmarks detect", "automatic 23 face points for an image or video frame (--out FILE.pts)",
     "The 23 face points of the first face found in an image or a video frame: dlib's 68-point predictor "
     "when installed, else an AAM fitted from the detection (--aam), else the template shape placed on the "
     "detection.\nGiven a folder of images and videos, or a project folder, finds the points of every one "
     "(videos at --frame) in this process into --out DIR/NAME.pts: -j at a time, skipping those whose points "
     "are newer than their input and the AAM, with progress on stderr and a list of the failures at the end "
     "(exit code 1 if any).",
     {{"out", "FILE.pts|DIR", "the points to write; with a folder, their folder", {}, CommandOption::Required},
      {"frame", "N", "the video frame (videos only)", "0"},
      {"method", "auto|dlib|aam|template", "how the points are found (auto: the first that is available)", "auto"},
      {"aam", "AAM", "the AAM to fit (--method aam or auto)", {}, CommandOption::Optional, {"model"}}},
     {{"INPUT", "an image or a video (IMAGE|VIDEO), or a folder of them, or a project folder"}}}
        .add(batchOptions()),
    &runLandmarksDetect};

} // namespace
