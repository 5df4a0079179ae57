// `lipsync landmarks detect IMAGE|VIDEO [--frame N] --out FILE.pts`: automatic 23 points for a
// face. dlib's 68-point predictor when installed, else an AAM fit from the detector (--aam), else
// the template shape placed on the detection.
#include "CommandLine.h"

#include "aam/AamModel.h"
#include "aam/AutoLandmarks.h"
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "io/VideoReader.h"
#include "util/Error.h"

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

int runLandmarksDetect(const CommandLine &a)
{
    const std::string input = a.positional().front().toStdString();
    const QString method = a.value("method");
    AutoLandmarkMethod how = AutoLandmarkMethod::Auto;
    if (!parseAutoLandmarkMethod(method.toStdString(), how))
        throw UsageError("--method must be auto, dlib, aam or template");
    if (method == "aam" && !a.isSet("aam"))
        throw UsageError("--method aam needs --aam AAM");
    const int frameIndex = a.integer("frame", 0);

    cv::Mat image;
    if (isImageFile(QString::fromStdString(input))) {
        if (a.isSet("frame") && frameIndex != 0)
            throw UsageError("--frame applies to videos only");
        image = cv::imread(input, cv::IMREAD_COLOR);
        if (image.empty())
            throw Error("cannot read the image", input);
    } else {
        VideoReader video(input);
        if (frameIndex >= video.frameCount())
            throw Error("the video has no frame " + std::to_string(frameIndex) + " ("
                            + std::to_string(video.frameCount()) + " frames)",
                        input, "--frame");
        image = video.frame(frameIndex);
        if (image.empty())
            throw Error("frame " + std::to_string(frameIndex) + " cannot be decoded", input);
    }

    FaceDetectorPaths paths;
    paths.useDlib = method == "auto" || method == "dlib";
    FaceDetector detector(paths);
    const std::vector<FaceDetection> faces = detector.detect(image);
    if (faces.empty())
        return fail(QString::fromStdString(input) + ": no face found"
                    + (a.isSet("frame") ? QStringLiteral(" in frame %1").arg(frameIndex) : QString())
                    + " (detectors: " + QString::fromStdString(detector.available()) + ")");
    const FaceDetection &face = faces.front();

    std::optional<AamModel> model;
    if (a.isSet("aam"))
        model = AamModel::load(a.value("aam").toStdString());
    const AutoLandmarks found = detectAutoLandmarks(image, face, detector, how, model ? &*model : nullptr);
    const Eigen::VectorXd &shape = found.shape;
    const QString used = QString::fromStdString(found.method);
    const std::string out = a.value("out").toStdString();
    writePtsFile(out, shape);

    if (a.isSet("json")) {
        QJsonArray points;
        for (int i = 0; i < scheme23::kPointCount; ++i)
            points.append(QJsonArray{shape[2 * i], shape[2 * i + 1]});
        printJson(QJsonObject{
            {"input", QString::fromStdString(input)},
            {"frame", frameIndex},
            {"out", QString::fromStdString(out)},
            {"method", used},
            {"points", points},
            {"face", QJsonObject{{"x", face.box.x}, {"y", face.box.y}, {"width", face.box.width},
                                 {"height", face.box.height}, {"score", face.score},
                                 {"detector", QString::fromStdString(face.source)}}},
            {"faces", int(faces.size())},
            {"state", "automatic"}});
    } else {
        std::printf("%s: 23 points (%s) -> %s\n", input.c_str(), qPrintable(used), out.c_str());
    }
    return 0;
}

const CommandRegistration registration{
    {"landmarks detect", "automatic 23 face points for an image or video frame (--out FILE.pts)",
     "The 23 face points of the first face found in an image or a video frame: dlib's 68-point predictor "
     "when installed, else an AAM fitted from the detection (--aam), else the template shape placed on the "
     "detection.",
     {{"out", "FILE.pts", "the points to write", {}, CommandOption::Required},
      {"frame", "N", "the video frame (videos only)", "0"},
      {"method", "auto|dlib|aam|template", "how the points are found (auto: the first that is available)", "auto"},
      {"aam", "AAM", "the AAM to fit (--method aam or auto)", {}, CommandOption::Optional, {"model"}}},
     {{"INPUT", "an image or a video (IMAGE|VIDEO)"}}},
    &runLandmarksDetect};

} // namespace
