#include "aam/AamBuilder.h"

#include "aam/AamFitter.h"
#include "aam/FaceDetector.h"
#include "aam/FrameSelection.h"

#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "aam/TextureNormalisation.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <Eigen/Cholesky>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lipsync {

namespace {

// Ridge of the detector keypoint regression, relative to the mean keypoint variance.
constexpr double kDetectorRidge = 0.1;

double eyeDistance(const Eigen::VectorXd &shape)
{
    return (shape.segment<2>(2 * scheme23::kLeftEyeOuter)
            - shape.segment<2>(2 * scheme23::kRightEyeOuter))
        .norm();
}

// Why an example cannot be used, or empty.
std::string checkExample(const AamTrainingExample &e)
{
    if (e.shape.size() != 2 * scheme23::kPointCount)
        return "has " + std::to_string(e.shape.size() / 2) + " points, expected 23";
    if (!e.shape.allFinite())
        return "has non-finite points";
    if (shapeSpread(e.shape) < 1.0 || eyeDistance(e.shape) < 2.0)
        return "has a degenerate shape (points coincide or lie on a line)";
    for (int i = 0; i < scheme23::kPointCount; ++i) {
        const double x = e.shape[2 * i], y = e.shape[2 * i + 1];
        if (x < 0 || y < 0 || x > e.image.cols - 1 || y > e.image.rows - 1)
            return "point " + std::to_string(i) + " (" + landmarkDefinitions()[size_t(i)].name
                   + ") lies outside the " + std::to_string(e.image.cols) + "x"
                   + std::to_string(e.image.rows) + " image";
    }
    return {};
}

// The options' reference eye distance, or the automatic one for these examples.
double chosenReferenceEyeDistance(const std::vector<AamTrainingExample> &examples, const AamBuildOptions &options)
{
    if (options.referenceEyeDistance > 0)
        return options.referenceEyeDistance;
    std::vector<double> sizes;
    for (const AamTrainingExample &e : examples)
        if (e.shape.size() == 2 * scheme23::kPointCount && e.shape.allFinite())
            sizes.push_back(eyeDistance(e.shape));
    if (sizes.empty())
        return AamBuildOptions::kAutoReferenceMin;
    std::nth_element(sizes.begin(), sizes.begin() + sizes.size() / 2, sizes.end());
    return std::clamp(std::round(AamBuildOptions::kAutoReferenceScale * sizes[sizes.size() / 2]),
                      AamBuildOptions::kAutoReferenceMin, AamBuildOptions::kAutoReferenceMax);
}

int chosenLevels(double referenceEyeDistance, const AamBuildOptions &options)
{
    if (options.levels > 0)
        return std::clamp(options.levels, 1, 4);
    int levels = 1;
    while (levels < 4 && referenceEyeDistance * std::pow(0.5, levels) >= AamBuildOptions::kCoarsestEyeDistance)
        ++levels;
    return levels;
}

// The combined PCA runs on data that is already centred (uncentred PCA, n-dimensional span), so
// its last mode has no variance; n-1 modes there are the images' limit as for the others.
AamModeChoice aamModeChoiceOf(const Pca &pca, int samples)
{
    const bool imageBound = pca.limit == PcaLimit::Rank && pca.modes() >= samples - 1;
    return {pca.modes(), pca.retainedFraction(), imageBound ? PcaLimit::Samples : pca.limit};
}

// Keeps up to `maxCount` training images as the model's exemplar detail: each image's combined
// parameters c_i = Q^T j_i and its textureDetail(), quantised to 8 bits. With more images than that, a
// farthest-point subset in the whitened combined parameters (FrameSelection's farthestPointSample,
// from the image nearest the mean face), so every region of the face space keeps its nearest real
// example.
void addExemplars(AamModel &model, const Eigen::MatrixXd &joint, const Eigen::MatrixXd &colour,
                  const Pca &texturePca, int maxCount)
{
    const int n = int(joint.cols());
    if (maxCount <= 0 || n == 0 || model.combinedModes() == 0)
        return;
    const Eigen::MatrixXd params = model.combinedBasis.transpose() * joint; // nc x n
    const Eigen::VectorXd invSd = model.combinedVariances.cwiseMax(1e-12).cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd white = invSd.asDiagonal() * params;
    std::vector<int> chosen;
    if (n <= maxCount) {
        for (int i = 0; i < n; ++i)
            chosen.push_back(i);
    } else {
        chosen = farthestPointSample(white, maxCount).picks;
    }
    const int e = int(chosen.size());
    model.exemplarParams.resize(model.combinedModes(), e);
    model.exemplarDetail.resize(colour.rows(), e);
    model.exemplarScales.resize(e);
    for (int k = 0; k < e; ++k) {
        const int i = chosen[size_t(k)];
        const Eigen::VectorXd centred = colour.col(i) - texturePca.mean;
        const Eigen::VectorXd residual = textureDetail(
            model.warp(0), centred - texturePca.basis * (model.combinedBasis.bottomRows(model.textureModes()) * params.col(i)));
        const double peak = residual.cwiseAbs().maxCoeff();
        const double scale = peak > 0 ? peak / 127.0 : 0.0;
        model.exemplarParams.col(k) = params.col(i);
        model.exemplarScales[k] = scale;
        for (Eigen::Index r = 0; r < residual.size(); ++r)
            model.exemplarDetail(r, k) = std::int8_t(scale > 0 ? std::lround(residual[r] / scale) : 0);
    }
}

} // namespace

Eigen::VectorXd textureDetail(const PiecewiseAffineWarp &warp, const Eigen::VectorXd &residual)
{
    const Eigen::VectorXf r = residual.cast<float>();
    const Eigen::VectorXf ones = Eigen::VectorXf::Ones(warp.pixelCount());
    cv::Mat blurred = warp.toImage(r.data(), 3, 0.f), weight = warp.toImage(ones.data(), 1, 0.f);
    cv::GaussianBlur(blurred, blurred, cv::Size(), kDetailSigma);
    cv::GaussianBlur(weight, weight, cv::Size(), kDetailSigma);
    Eigen::VectorXd detail = residual;
    for (int i = 0; i < warp.pixelCount(); ++i) {
        const int x = warp.pixelX(i), y = warp.pixelY(i);
        const float w = std::max(1e-6f, weight.at<float>(y, x));
        for (int c = 0; c < 3; ++c)
            detail[3 * i + c] -= double(blurred.at<cv::Vec3f>(y, x)[c] / w);
    }
    return detail;
}

std::vector<AamTrainingExample> loadTrainingDirectory(const std::string &directory,
                                                      std::vector<std::string> *warnings)
{
    const QDir dir(QString::fromStdString(directory));
    if (!dir.exists())
        throw Error("directory does not exist", directory);
    const QStringList images = dir.entryList(
        {"*.jpg", "*.jpeg", "*.png", "*.bmp", "*.JPG", "*.PNG", "*.JPEG"}, QDir::Files, QDir::Name);
    std::vector<AamTrainingExample> out;
    for (const QString &name : images) {
        const QString pts = dir.filePath(QFileInfo(name).completeBaseName() + ".pts");
        if (!QFileInfo::exists(pts)) {
            if (warnings)
                warnings->push_back(name.toStdString() + ": no .pts beside it, skipped");
            continue;
        }
        AamTrainingExample e;
        e.name = name.toStdString();
        e.imagePath = dir.filePath(name).toStdString();
        try {
            e.shape = readFaceShape(pts.toStdString());
        } catch (const Error &error) {
            if (warnings)
                warnings->push_back(std::string(error.what()) + ", skipped");
            continue;
        }
        out.push_back(std::move(e));
    }
    if (out.empty())
        throw Error("no labelled images (image files with a .pts of the same name)", directory);
    return out;
}

namespace {

// The examples an AAM is built from: read, checked (a reason for each left out goes to `warn`),
// pre-scaled so the face is about reference size (the warp then samples without aliasing and
// memory stays small), and mirrored when asked.
std::vector<AamTrainingExample> usableExamples(std::vector<AamTrainingExample> examples, const AamBuildOptions &options,
                                               double referenceEyeDistance, Feedback &feedback,
                                               const std::function<void(const std::string &)> &warn)
{
    std::vector<AamTrainingExample> usable;
    for (size_t i = 0; i < examples.size(); ++i) {
        feedback.throwIfCanceled();
        feedback.setProgress(0.4 * double(i) / double(examples.size()));
        AamTrainingExample &e = examples[i];
        if (e.image.empty() && !e.imagePath.empty())
            e.image = cv::imread(e.imagePath, cv::IMREAD_COLOR);
        if (e.image.empty()) {
            warn(e.name + ": cannot read the image, skipped");
            continue;
        }
        if (e.image.type() == CV_8UC1)
            cv::cvtColor(e.image, e.image, cv::COLOR_GRAY2BGR);
        if (e.image.type() != CV_8UC3) {
            warn(e.name + ": not an 8-bit image, skipped");
            continue;
        }
        if (const std::string why = checkExample(e); !why.empty()) {
            warn(e.name + ": " + why + ", skipped");
            continue;
        }
        const double f = referenceEyeDistance / eyeDistance(e.shape);
        if (f < 0.8) {
            cv::Mat small;
            cv::resize(e.image, small, cv::Size(), f, f, cv::INTER_AREA);
            e.image = small;
            e.shape = (e.shape.array() + 0.5) * f - 0.5;
        }
        usable.push_back(std::move(e));
    }
    if (options.mirror) {
        const size_t originals = usable.size();
        for (size_t i = 0; i < originals; ++i) {
            AamTrainingExample m;
            m.name = usable[i].name + " (mirrored)";
            cv::flip(usable[i].image, m.image, 1);
            m.shape = mirrorShape(usable[i].shape, usable[i].image.cols);
            usable.push_back(std::move(m));
        }
    }
    return usable;
}

// The training textures under `model`'s warp: colour at level 0 (normalised; the mean photometric
// transform goes into the model) and the fitting channels at every level.
void sampleTextures(AamModel &model, const std::vector<AamTrainingExample> &usable, Feedback &feedback,
                    Eigen::MatrixXd &colour, std::vector<Eigen::MatrixXd> &grey)
{
    const int n = int(usable.size());
    const int levelCount = int(model.levels.size());
    const int colourSize = 3 * model.warp(0).pixelCount();
    colour.resize(colourSize, n);
    grey.assign(size_t(levelCount), Eigen::MatrixXd());
    for (int l = 0; l < levelCount; ++l)
        grey[size_t(l)].resize(model.fitChannels() * model.warp(l).pixelCount(), n);
    double scaleSum = 0.0, offsetSum = 0.0;
    std::vector<float> buffer;
    for (int i = 0; i < n; ++i) {
        feedback.throwIfCanceled();
        feedback.setProgress(0.4 + 0.4 * double(i) / n);
        const AamTrainingExample &e = usable[size_t(i)];
        buffer.resize(size_t(colourSize));
        model.warp(0).sampleColour(e.image, e.shape, buffer.data());
        const PhotometricTransform t = normaliseTexture(buffer.data(), buffer.size());
        scaleSum += t.scale;
        offsetSum += t.offset;
        colour.col(i) = Eigen::Map<Eigen::VectorXf>(buffer.data(), colourSize).cast<double>();

        cv::Mat g;
        cv::cvtColor(e.image, g, cv::COLOR_BGR2GRAY);
        g.convertTo(g, CV_32F);
        const double imageScale = model.referenceScale / shapeSize(e.shape);
        for (int l = 0; l < levelCount; ++l) {
            const double f = imageScale * model.levels[size_t(l)].scale;
            cv::Mat gl = g;
            Eigen::VectorXd s = e.shape;
            if (f < 0.8) {
                cv::resize(g, gl, cv::Size(), f, f, cv::INTER_AREA);
                s = (s.array() + 0.5) * f - 0.5;
            }
            const int count = model.fitChannels() * model.warp(l).pixelCount();
            buffer.resize(size_t(count));
            sampleFittingChannels(model.warp(l), fittingChannels(smoothedForFitting(gl), model.fitFeatures), s,
                                  buffer.data());
            normaliseTexture(buffer.data(), buffer.size());
            grey[size_t(l)].col(i) = Eigen::Map<Eigen::VectorXf>(buffer.data(), count).cast<double>();
        }
    }
    model.meanTextureScale = scaleSum / n;
    model.meanTextureOffset = offsetSum / n;
}

// The mean of the training shapes in the frame of the detector's keypoints, expressed where those
// keypoints sit on the mean shape, and a ridge regression of the shape on them.
void calibrateDetector(AamModel &model, const std::vector<AamTrainingExample> &usable, FaceDetector &detector,
                       Feedback &feedback, const std::function<void(const std::string &)> &warn)
{
    feedback.setStatus("calibrating the face detector");
    const Eigen::VectorXd anchors = keypointAnchors(model.meanShape);
    std::vector<Eigen::VectorXd> keypoints, targets; // both in the frame of the anchors
    for (const auto &e : usable) {
        feedback.throwIfCanceled();
        const std::vector<FaceDetection> faces = detector.detect(e.image);
        // The detection whose keypoints are nearest the labelled eyes and mouth.
        const Eigen::VectorXd truth = keypointAnchors(e.shape);
        const double eyes = eyeDistance(e.shape);
        for (const auto &f : faces) {
            const Eigen::VectorXd k = detectionAnchors(f);
            if (k.size() == 0 || (k - truth).cwiseAbs().maxCoeff() > 0.5 * eyes)
                continue;
            const Similarity t = alignSimilarity(k, anchors);
            targets.push_back(t.apply(e.shape));
            keypoints.push_back(t.apply(detectionKeypoints(f)));
            break;
        }
    }
    const int count = int(targets.size());
    if (count >= 3) {
        Eigen::MatrixXd Y(model.meanShape.size(), count), K(10, count);
        for (int i = 0; i < count; ++i) {
            Y.col(i) = targets[size_t(i)];
            K.col(i) = keypoints[size_t(i)];
        }
        model.detectorShape = Y.rowwise().mean();
        model.detectorKeypointMean = K.rowwise().mean();
        // Ridge regression of the shape on the keypoints, R = Yc Kc^T (Kc Kc^T + lambda I)^-1:
        // a start that follows the detected nose and mouth, not just the mean. The ridge
        // (a tenth of the mean keypoint variance per sample) keeps it near the mean for the
        // few-image person-specific models.
        const Eigen::MatrixXd Kc = K.colwise() - model.detectorKeypointMean;
        const Eigen::MatrixXd Yc = Y.colwise() - model.detectorShape;
        Eigen::MatrixXd gram = Kc * Kc.transpose();
        gram.diagonal().array() += kDetectorRidge * gram.trace() / 10.0 + 1e-12;
        model.detectorRegression = gram.ldlt().solve(Kc * Yc.transpose()).transpose();
    } else {
        warn("the face detector found too few training faces to calibrate its initialisation");
    }
}

} // namespace

AamModel buildAam(std::vector<AamTrainingExample> examples, const AamBuildOptions &options,
                  Feedback &feedback, std::vector<std::string> *warnings, AamBuildReport *report)
{
    auto warn = [&](const std::string &w) {
        if (warnings)
            warnings->push_back(w);
    };
    const double referenceEyeDistance = chosenReferenceEyeDistance(examples, options);
    const int levelCount = chosenLevels(referenceEyeDistance, options);
    feedback.setStatus("reading images");

    // 1. Read, check and pre-scale every image so the face is about reference size.
    std::vector<AamTrainingExample> usable =
        usableExamples(std::move(examples), options, referenceEyeDistance, feedback, warn);
    const int n = int(usable.size());
    if (n < 3)
        throw Error("need at least 3 usable training images, found " + std::to_string(n));

    // 2. Shape model.
    feedback.setStatus("aligning shapes");
    std::vector<Eigen::VectorXd> shapes;
    for (const auto &e : usable)
        shapes.push_back(e.shape);
    const ProcrustesResult gpa = generalisedProcrustes(shapes);
    Eigen::MatrixXd shapeData(gpa.mean.size(), n);
    for (int i = 0; i < n; ++i)
        shapeData.col(i) = gpa.aligned[size_t(i)];
    const Pca shapePca = computePca(shapeData, options.shapeVariance);
    if (shapePca.modes() == 0)
        throw Error("the training shapes do not vary; label more different frames");

    AamModel model;
    model.meanShape = gpa.mean;
    model.shapeBasis = shapePca.basis;
    model.shapeVariances = shapePca.variances;
    model.triangles = delaunayTriangles(gpa.mean * 1000.0);
    model.referenceScale = referenceEyeDistance / eyeDistance(gpa.mean);
    for (int l = 0; l < levelCount; ++l) {
        AamTextureLevel level;
        level.scale = std::pow(0.5, l);
        model.levels.push_back(level);
    }
    model.fitFeatures = options.fitFeatures;
    model.prepare();
    model.trainingImages = n;

    // 3. Textures: colour at level 0 for the combined model, grey at each level for fitting.
    feedback.setStatus("sampling textures");
    Eigen::MatrixXd colour;
    std::vector<Eigen::MatrixXd> grey;
    sampleTextures(model, usable, feedback, colour, grey);
    feedback.setStatus("texture PCA");
    feedback.throwIfCanceled();
    const Pca texturePca = computePca(colour, options.textureVariance);
    model.textureMean = texturePca.mean;
    model.textureBasis = texturePca.basis;
    model.textureVariances = texturePca.variances;
    feedback.setProgress(0.85);
    for (int l = 0; l < levelCount; ++l) {
        feedback.throwIfCanceled();
        const Pca p = computePca(grey[size_t(l)], options.textureVariance);
        auto &level = model.levels[size_t(l)];
        level.mean = p.mean;
        level.basis = p.basis;
        level.variances = p.variances;
    }
    feedback.setProgress(0.95);

    // 4. Combined model (Cootes et al. 2001, eq. 4-5).
    feedback.setStatus("combined PCA");
    const double shapeVar = std::max(1e-12, model.shapeVariances.sum());
    const double textureVar = model.textureVariances.sum();
    model.shapeWeight = textureVar > 0 ? std::sqrt(textureVar / shapeVar) : 1.0;
    const int ns = model.shapeModes(), ng = model.textureModes();
    Eigen::MatrixXd joint(ns + ng, n);
    for (int i = 0; i < n; ++i) {
        joint.col(i).head(ns) =
            model.shapeWeight * shapePca.basis.transpose() * (shapeData.col(i) - model.meanShape);
        joint.col(i).tail(ng) = texturePca.basis.transpose() * (colour.col(i) - texturePca.mean);
    }
    const Pca combined = computePca(joint, options.combinedVariance, options.maxCombinedModes, false);
    model.combinedBasis = combined.basis;
    model.combinedVariances = combined.variances;
    addExemplars(model, joint, colour, texturePca, options.maxExemplars);
    if (report)
        *report = {aamModeChoiceOf(shapePca, n), aamModeChoiceOf(texturePca, n), aamModeChoiceOf(combined, n),
                   referenceEyeDistance, levelCount};
    // 5. Detector calibration.
    if (options.detector)
        calibrateDetector(model, usable, *options.detector, feedback, warn);
    if (options.singlePrecisionBases) {
        model.singlePrecisionBases = true;
        const auto round = [](Eigen::MatrixXd &m) { m = m.cast<float>().cast<double>(); };
        round(model.textureBasis);
        for (AamTextureLevel &level : model.levels)
            round(level.basis);
    }
    model.identifier = model.computeIdentifier();
    feedback.setProgress(1.0);
    feedback.setStatus("done");
    return model;
}

} // namespace lipsync
