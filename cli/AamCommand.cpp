// `lipsync aam build` and `lipsync aam eval`: train an AAM from labelled images and measure how well
// it fits held-out images from the face detector's initialisation.
#include "CommandLine.h"

#include "aam/AamBuilder.h"
#include "aam/AamFitter.h"
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QJsonArray>
#include <QJsonObject>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// Why a PCA of the build kept the modes it did, in words.
QString modeReason(const AamModeChoice &c, double fraction, int cap, int images)
{
    switch (c.limit) {
    case PcaLimit::Variance:
        return QStringLiteral("%1 % of the variance reached").arg(100.0 * fraction, 0, 'g', 3);
    case PcaLimit::Cap:
        return QStringLiteral("capped at %1 modes (%2 % of the variance)")
            .arg(cap)
            .arg(100.0 * c.retainedVariance, 0, 'f', 1);
    case PcaLimit::Samples:
        return QStringLiteral("%1 training images allow at most %2 modes (%3 % of the variance)")
            .arg(images)
            .arg(c.modes)
            .arg(100.0 * c.retainedVariance, 0, 'f', 1);
    case PcaLimit::Rank:
        break;
    }
    return QStringLiteral("the remaining modes have no variance (%1 % of the variance)")
        .arg(100.0 * c.retainedVariance, 0, 'f', 1);
}

QJsonObject modeChoiceJson(const AamModeChoice &c, double fraction, int cap, int images)
{
    return QJsonObject{{"modes", c.modes},
                       {"variance_fraction", fraction},
                       {"retained_variance", c.retainedVariance},
                       {"limit", pcaLimitName(c.limit)},
                       {"cap", cap > 0 ? QJsonValue(cap) : QJsonValue()},
                       {"reason", modeReason(c, fraction, cap, images)}};
}

int runAamBuild(const CommandLine &a)
{
    // --generic: the cross-validated settings for in-the-wild faces; options given explicitly win.
    AamBuildOptions options = a.isSet("generic") ? AamBuildOptions::generic() : AamBuildOptions{};
    auto number = [&](const char *name, double &target) {
        if (a.isSet(name))
            target = a.number(name);
    };
    number("shape-variance", options.shapeVariance);
    number("texture-variance", options.textureVariance);
    number("combined-variance", options.combinedVariance);
    number("eye-distance", options.referenceEyeDistance);
    if (a.isSet("max-modes"))
        options.maxCombinedModes = a.integer("max-modes", 0);
    if (a.isSet("levels"))
        options.levels = a.integer("levels", 0);
    if (a.isSet("exemplars"))
        options.maxExemplars = a.integer("exemplars", 0);
    options.mirror = options.mirror || a.isSet("mirror");
    const QString features = a.isSet("fit-features") ? a.value("fit-features") : a.isSet("generic") ? "igo" : "grey";
    if (features != "grey" && features != "igo")
        throw UsageError("--fit-features must be grey or igo");
    options.fitFeatures = features == "igo" ? AamFitFeatures::GradientOrientation : AamFitFeatures::Grey;
    // --eye-distance 0 and --levels 0: automatic (AamBuildOptions).
    if (options.referenceEyeDistance != 0 && options.referenceEyeDistance < 8)
        throw UsageError("--eye-distance must be 0 (automatic) or at least 8 pixels");

    std::vector<std::string> warnings;
    const auto started = std::chrono::steady_clock::now();
    std::vector<AamTrainingExample> examples =
        loadTrainingDirectory(a.value("images").toStdString(), &warnings);
    Feedback feedback;
    FaceDetector detector(FaceDetectorPaths::boxesOnly());
    if (!a.isSet("no-detector") && (detector.hasYunet() || detector.hasHaar()))
        options.detector = &detector;
    const bool json = a.isSet("json");
    if (!json)
        feedback.onStatus = [](const std::string &s) { std::fprintf(stderr, "aam build: %s\n", s.c_str()); };
    AamBuildReport report;
    const AamModel model = buildAam(std::move(examples), options, feedback, &warnings, &report);
    model.save(a.value("out").toStdString());
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    for (const auto &w : warnings)
        std::fprintf(stderr, "lipsync: warning: %s\n", w.c_str());
    QJsonArray warningArray;
    for (const auto &w : warnings)
        warningArray.append(QString::fromStdString(w));
    const double shapeTotal = model.shapeVariances.sum();
    QJsonObject out{{"model", a.value("out")},
                    {"identifier", QString::fromStdString(model.identifier)},
                    {"images", model.trainingImages},
                    {"points", model.pointCount()},
                    {"triangles", int(model.triangles.size())},
                    {"shape_modes", model.shapeModes()},
                    {"texture_modes", model.textureModes()},
                    {"combined_modes", model.combinedModes()},
                    {"modes",
                     QJsonObject{{"shape", modeChoiceJson(report.shape, options.shapeVariance, 0,
                                                          model.trainingImages)},
                                 {"texture", modeChoiceJson(report.texture, options.textureVariance, 0,
                                                            model.trainingImages)},
                                 {"combined", modeChoiceJson(report.combined, options.combinedVariance,
                                                             options.maxCombinedModes, model.trainingImages)}}},
                    {"texture_pixels", model.warp(0).pixelCount()},
                    {"exemplars", model.exemplarCount()},
                    {"reference_eye_distance", report.referenceEyeDistance},
                    {"levels", int(model.levels.size())},
                    {"mirrored", options.mirror},
                    {"features", features},
                    {"shape_variance_total", shapeTotal},
                    {"detector_calibrated", model.detectorShape.size() > 0},
                    {"seconds", seconds},
                    {"warnings", warningArray}};
    if (json)
        printJson(out);
    else
        std::printf("built %s from %d images: %d shape, %d texture, %d combined modes (%s)\n"
                    "  reference frame: %.0f pixels between the outer eye corners, %d levels; %d exemplars\n"
                    "  combined: %s\n  shape: %s\n  texture: %s\n",
                    qPrintable(a.value("out")), model.trainingImages, model.shapeModes(),
                    model.textureModes(), model.combinedModes(), model.identifier.c_str(),
                    report.referenceEyeDistance, int(model.levels.size()), model.exemplarCount(),
                    qPrintable(modeReason(report.combined, options.combinedVariance,
                                          options.maxCombinedModes, model.trainingImages)),
                    qPrintable(modeReason(report.shape, options.shapeVariance, 0, model.trainingImages)),
                    qPrintable(modeReason(report.texture, options.textureVariance, 0, model.trainingImages)));
    return 0;
}

double overlap(const cv::Rect2d &a, const cv::Rect2d &b)
{
    const double inter = (a & b).area();
    const double uni = a.area() + b.area() - inter;
    return uni > 0 ? inter / uni : 0.0;
}

cv::Rect2d boundingBox(const Eigen::VectorXd &shape)
{
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (Eigen::Index i = 0; i < shape.size() / 2; ++i) {
        x0 = std::min(x0, shape[2 * i]);
        x1 = std::max(x1, shape[2 * i]);
        y0 = std::min(y0, shape[2 * i + 1]);
        y1 = std::max(y1, shape[2 * i + 1]);
    }
    return {x0, y0, x1 - x0, y1 - y0};
}

// The fit's start for the labelled face `truth` in `image`: the detection overlapping it most (an
// image may hold several faces), as dlib's points mapped to ours (init dlib) or the mean shape
// placed in the detection's box. Empty without such a detection.
Eigen::VectorXd startShape(FaceDetector &detector, const AamModel &model, const cv::Mat &image,
                           const Eigen::VectorXd &truth, const QString &init)
{
    const std::vector<FaceDetection> faces = detector.detect(image);
    const cv::Rect2d truthBox = boundingBox(truth);
    const FaceDetection *best = nullptr;
    double bestOverlap = 0.0;
    for (const auto &f : faces) {
        const double o = overlap(f.box, truthBox);
        if (o > bestOverlap) {
            bestOverlap = o;
            best = &f;
        }
    }
    if (best && init == "dlib") {
        const Eigen::VectorXd points = detector.dlibLandmarks(image, *best);
        return points.size() == 136 ? mapIbug68To23(points) : Eigen::VectorXd();
    }
    return best ? initialShapeFromDetection(model, *best) : Eigen::VectorXd();
}

int runAamEval(const CommandLine &a)
{
    const QString init = a.value("init");
    if (init != "detector" && init != "dlib" && init != "none")
        throw UsageError("--init must be detector, dlib or none");
    const QString algorithm = a.value("algorithm");
    if (algorithm != "project-out" && algorithm != "wiberg")
        throw UsageError("--algorithm must be project-out or wiberg");
    const double priorWeight = a.number("prior-weight");
    if (priorWeight < 0)
        throw UsageError("--prior-weight must be a number >= 0");
    const double spread = a.positiveNumber("start-spread");
    const AamModel model = AamModel::load(a.value("aam").toStdString());
    const AamFitter fitter(model);
    FaceDetectorPaths paths;
    paths.useDlib = init == "dlib"; // loading the predictor takes seconds: only when used
    FaceDetector detector(paths);
    if (!detector.hasYunet() && !detector.hasHaar())
        return fail("aam eval: no face detector available (YuNet model or Haar cascade)");
    if (init == "dlib" && !detector.hasDlib())
        return fail(
            QStringLiteral("aam eval: --init dlib needs %1").arg(QString::fromStdString(paths.dlibPredictorFile())));
    std::vector<std::string> warnings;
    std::vector<AamTrainingExample> examples =
        loadTrainingDirectory(a.value("images").toStdString(), &warnings);

    std::vector<double> nmes, initNmes;
    int noFace = 0;
    double fitSeconds = 0.0, detectSeconds = 0.0;
    QJsonArray perImage;
    for (auto &e : examples) {
        const cv::Mat image = cv::imread(e.imagePath, cv::IMREAD_COLOR);
        if (image.empty()) {
            warnings.push_back(e.name + ": cannot read the image");
            continue;
        }
        const auto t0 = std::chrono::steady_clock::now();
        const Eigen::VectorXd start = startShape(detector, model, image, e.shape, init);
        const auto t1 = std::chrono::steady_clock::now();
        detectSeconds += std::chrono::duration<double>(t1 - t0).count();
        if (start.size() == 0) {
            ++noFace;
            perImage.append(QJsonObject{{"image", QString::fromStdString(e.name)}, {"face", false}});
            continue;
        }
        AamFitResult fit;
        fit.shape = start;
        if (init != "none") {
            const auto t2 = std::chrono::steady_clock::now();
            AamFitOptions fitOptions;
            if (algorithm == "wiberg")
                fitOptions.algorithm = AamFitAlgorithm::Wiberg;
            fitOptions.multiStart = a.isSet("multi-start");
            fitOptions.shapePriorWeight = priorWeight;
            fitOptions.multiStartSpread = spread;
            // dlib's points are already close: refine at the finest level only.
            if (init == "dlib")
                fitOptions.coarsestLevel = 0;
            fit = fitter.fit(image, start, fitOptions);
            fitSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t2).count();
        }
        const double nme = normalisedMeanError(fit.shape, e.shape);
        const double nme0 = normalisedMeanError(start, e.shape);
        nmes.push_back(nme);
        initNmes.push_back(nme0);
        perImage.append(QJsonObject{{"image", QString::fromStdString(e.name)},
                                    {"face", true},
                                    {"nme", nme},
                                    {"nme_init", nme0},
                                    {"fit_error", fit.error},
                                    {"iterations", fit.iterations}});
    }
    auto mean = [](const std::vector<double> &v) {
        double s = 0;
        for (double x : v)
            s += x;
        return v.empty() ? 0.0 : s / double(v.size());
    };
    auto median = [](std::vector<double> v) {
        if (v.empty())
            return 0.0;
        std::sort(v.begin(), v.end());
        const size_t m = v.size() / 2;
        return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
    };
    for (const auto &w : warnings)
        std::fprintf(stderr, "lipsync: warning: %s\n", w.c_str());
    const int fitted = int(nmes.size());
    QJsonObject out{{"images", fitted + noFace},
                    {"fitted", fitted},
                    {"no_face", noFace},
                    {"init", init},
                    {"algorithm", algorithm},
                    {"multi_start", a.isSet("multi-start")},
                    {"prior_weight", priorWeight},
                    {"start_spread", spread},
                    {"nme_mean", mean(nmes)},
                    {"nme_median", median(nmes)},
                    {"nme_init_mean", mean(initNmes)},
                    {"nme_init_median", median(initNmes)},
                    {"fps", fitSeconds > 0 ? fitted / fitSeconds : 0.0},
                    {"fps_with_detection",
                     fitSeconds + detectSeconds > 0 ? fitted / (fitSeconds + detectSeconds) : 0.0},
                    {"detector", QString::fromStdString(detector.available())},
                    {"model", QString::fromStdString(model.identifier)},
                    {"per_image", perImage}};
    if (a.isSet("json")) {
        printJson(out);
    } else {
        std::printf("%d images (%d without a face): NME mean %.4f median %.4f (init %.4f), %.1f fits/s\n",
                    fitted + noFace, noFace, mean(nmes), median(nmes), mean(initNmes),
                    out["fps"].toDouble());
    }
    return fitted > 0 ? 0 : 1;
}

const CommandRegistration buildRegistration{
    {"aam build", "train an AAM from images with .pts landmarks (--images DIR --out AAM)",
     "Trains an active appearance model from labelled images (IMAGE.pts beside each image, 68 or 23 "
     "points): shape, texture and combined modes, resolution levels for fitting, calibrated to the face "
     "detector.",
     {{"images", "DIR", "the labelled images (IMAGE.pts beside each, 68 or 23 points)", {}, CommandOption::Required},
      {"out", "AAM", "the AAM file to write", {}, CommandOption::Required},
      {"combined-variance", "F", "the fraction of the combined variance the modes keep"},
      {"shape-variance", "F", "the fraction of the shape variance the modes keep"},
      {"texture-variance", "F", "the fraction of the texture variance the modes keep"},
      {"max-modes", "N", "at most N combined modes (0: no limit)", QString::number(AamBuildOptions{}.maxCombinedModes)},
      {"eye-distance", "PX", "the reference eye distance in pixels (0: 1.5 x the faces' median, 50..100; else >= 8)",
       QStringLiteral("0")},
      {"levels", "N", "resolution levels for fitting, each half the previous (0: automatic)", QStringLiteral("0")},
      {"mirror", {}, "add every image mirrored"},
      {"exemplars", "N", "training images kept as the detail (teeth, lip highlights) synthesis adds (0: none)",
       QString::number(AamBuildOptions{}.maxExemplars)},
      {"fit-features", "grey|igo", "what fitting compares: grey levels or image gradient orientations "
                                   "(default: grey, igo with --generic)", {}, CommandOption::Optional, {"features"}},
      {"generic", {}, "the cross-validated settings for in-the-wild faces (options given explicitly win)"},
      {"no-detector", {}, "do not calibrate the model to the face detector"}},
     {}},
    &runAamBuild};
const CommandRegistration evalRegistration{
    {"aam eval", "fit an AAM to labelled images from the detector and report NME (--aam --images)",
     "Fits an AAM to labelled images from the face detector's initialisation and reports the normalised "
     "mean error (NME) of the fitted points and the fitting speed.",
     {{"aam", "AAM", "the AAM to fit", {}, CommandOption::Required, {"model"}},
      {"images", "DIR", "the labelled images (IMAGE.pts beside each, 68 or 23 points)", {}, CommandOption::Required},
      {"init", "detector|dlib|none", "the start: the detection, dlib's 68 points, or no fit (the start only)",
       "detector"},
      {"algorithm", "project-out|wiberg", "the fitting algorithm", "project-out"},
      {"multi-start", {}, "also fit from shifted starts and keep the best fit"},
      {"prior-weight", "W", "the weight of the shape prior (>= 0)",
       QString::number(AamFitOptions::kDefaultShapePriorWeight)},
      {"start-spread", "F", "how far the multi-start starts are shifted (> 0)",
       QString::number(AamFitOptions{}.multiStartSpread)}},
     {}},
    &runAamEval};

} // namespace
