// `lipsync aam build` and `lipsync aam eval`: train an AAM from labelled images and measure how well
// it fits held-out images from the face detector's initialisation.
#include "Command.h"

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

int runAamBuild(const QStringList &args)
{
    const Arguments a(args);
    if (const QStringList bad = a.unknown({"images", "out", "json", "shape-variance",
                                           "texture-variance", "combined-variance", "max-modes",
                                           "eye-distance", "levels", "no-detector", "mirror", "features",
                                           "generic"});
        !bad.isEmpty())
        return fail("aam build: unknown option " + bad.join(", "), 2);
    if (!a.has("images") || !a.has("out"))
        return fail("usage: lipsync aam build --images DIR --out MODEL [--combined-variance F] "
                    "[--shape-variance F] [--texture-variance F] [--max-modes N (32; 0: no cap)] "
                    "[--eye-distance PX (0: automatic)] [--levels N (0: automatic)] [--mirror] "
                    "[--features grey|igo] [--generic] "
                    "[--no-detector] [--json]",
                    2);
    // --generic: the cross-validated settings for in-the-wild faces; options given explicitly win.
    AamBuildOptions options = a.flag("generic") ? AamBuildOptions::generic() : AamBuildOptions{};
    bool ok = true;
    auto number = [&](const char *name, double &target) {
        if (a.has(name)) {
            bool good = false;
            target = a.value(name).toDouble(&good);
            ok = ok && good;
        }
    };
    number("shape-variance", options.shapeVariance);
    number("texture-variance", options.textureVariance);
    number("combined-variance", options.combinedVariance);
    number("eye-distance", options.referenceEyeDistance);
    double maxModes = options.maxCombinedModes, levels = options.levels;
    number("max-modes", maxModes);
    number("levels", levels);
    options.maxCombinedModes = int(maxModes);
    options.levels = int(levels);
    options.mirror = options.mirror || a.flag("mirror");
    const QString features = a.value("features", a.flag("generic") ? "igo" : "grey");
    if (features != "grey" && features != "igo")
        return fail("aam build: --features must be grey or igo", 2);
    options.fitFeatures = features == "igo" ? AamFitFeatures::GradientOrientation : AamFitFeatures::Grey;
    // --eye-distance 0 and --levels 0: automatic (AamBuildOptions).
    if (!ok || (options.referenceEyeDistance != 0 && options.referenceEyeDistance < 8) || options.levels < 0)
        return fail("aam build: bad numeric option", 2);

    std::vector<std::string> warnings;
    const auto started = std::chrono::steady_clock::now();
    std::vector<AamTrainingExample> examples =
        loadTrainingDirectory(a.value("images").toStdString(), &warnings);
    Feedback feedback;
    FaceDetectorPaths paths;
    paths.useDlib = false;
    FaceDetector detector(paths);
    if (!a.flag("no-detector") && (detector.hasYunet() || detector.hasHaar()))
        options.detector = &detector;
    const bool json = a.flag("json");
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
                    "  reference frame: %.0f pixels between the outer eye corners, %d levels\n"
                    "  combined: %s\n  shape: %s\n  texture: %s\n",
                    qPrintable(a.value("out")), model.trainingImages, model.shapeModes(),
                    model.textureModes(), model.combinedModes(), model.identifier.c_str(),
                    report.referenceEyeDistance, int(model.levels.size()),
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

int runAamEval(const QStringList &args)
{
    const Arguments a(args);
    if (const QStringList bad = a.unknown({"model", "images", "json", "init", "levels", "algorithm",
                                           "multi-start", "prior-weight", "start-spread"});
        !bad.isEmpty())
        return fail("aam eval: unknown option " + bad.join(", "), 2);
    if (!a.has("model") || !a.has("images"))
        return fail("usage: lipsync aam eval --model MODEL --images DIR [--init detector|dlib|none] "
                    "[--algorithm project-out|wiberg] [--multi-start] [--prior-weight W] [--start-spread F] "
                    "[--json]",
                    2);
    const QString init = a.value("init", "detector");
    if (init != "detector" && init != "dlib" && init != "none")
        return fail("aam eval: --init must be detector, dlib or none", 2);
    const QString algorithm = a.value("algorithm", "project-out");
    if (algorithm != "project-out" && algorithm != "wiberg")
        return fail("aam eval: --algorithm must be project-out or wiberg", 2);
    bool priorOk = true;
    const double priorWeight = a.has("prior-weight") ? a.value("prior-weight").toDouble(&priorOk)
                                                     : AamFitOptions::kDefaultShapePriorWeight;
    if (!priorOk || priorWeight < 0)
        return fail("aam eval: --prior-weight must be a number >= 0", 2);
    const double spread = a.has("start-spread") ? a.value("start-spread").toDouble(&priorOk)
                                                : AamFitOptions{}.multiStartSpread;
    if (!priorOk || spread <= 0)
        return fail("aam eval: --start-spread must be a number > 0", 2);
    const AamModel model = AamModel::load(a.value("model").toStdString());
    const AamFitter fitter(model);
    FaceDetectorPaths paths;
    paths.useDlib = init == "dlib"; // loading the predictor takes seconds: only when used
    FaceDetector detector(paths);
    if (!detector.hasYunet() && !detector.hasHaar())
        return fail("aam eval: no face detector available (YuNet model or Haar cascade)");
    if (init == "dlib" && !detector.hasDlib())
        return fail("aam eval: --init dlib needs /usr/share/dlib/shape_predictor_68_face_landmarks.dat");
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
        const std::vector<FaceDetection> faces = detector.detect(image);
        // The detection that overlaps the labelled face most (images may hold several faces).
        const cv::Rect2d truthBox = boundingBox(e.shape);
        const FaceDetection *best = nullptr;
        double bestOverlap = 0.0;
        for (const auto &f : faces) {
            const double o = overlap(f.box, truthBox);
            if (o > bestOverlap) {
                bestOverlap = o;
                best = &f;
            }
        }
        Eigen::VectorXd start;
        if (best && init == "dlib") {
            const Eigen::VectorXd points = detector.dlibLandmarks(image, *best);
            if (points.size() == 136)
                start = mapIbug68To23(points);
        } else if (best) {
            start = initialShapeFromDetection(model, *best);
        }
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
            fitOptions.multiStart = a.flag("multi-start");
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
                    {"multi_start", a.flag("multi-start")},
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
    if (a.flag("json")) {
        printJson(out);
    } else {
        std::printf("%d images (%d without a face): NME mean %.4f median %.4f (init %.4f), %.1f fits/s\n",
                    fitted + noFace, noFace, mean(nmes), median(nmes), mean(initNmes),
                    out["fps"].toDouble());
    }
    return fitted > 0 ? 0 : 1;
}

const CommandRegistration buildRegistration{
    "aam build", "train an AAM from images with .pts landmarks (--images DIR --out MODEL)", &runAamBuild};
const CommandRegistration evalRegistration{
    "aam eval", "fit an AAM to labelled images from the detector and report NME (--model --images)",
    &runAamEval};

} // namespace
