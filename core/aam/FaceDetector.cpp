#include "aam/FaceDetector.h"

#include "aam/AamModel.h"
#include "aam/DlibFaceModels.h"
#include "aam/LandmarkScheme.h"
#include "util/Environment.h"
#include "util/ResourceLocator.h"
#include "util/SystemPaths.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <opencv2/imgproc.hpp>
#include <opencv2/objdetect.hpp>

#include <algorithm>
#include <cstdlib>
#include <mutex>
#include <optional>

namespace lipsync {

struct FaceDetector::Impl
{
    cv::Ptr<cv::FaceDetectorYN> yunet;
    cv::CascadeClassifier haar;
    bool haarLoaded = false;
    DlibFaceModels dlib;
};

std::string FaceDetector::findYunetModel()
{
    if (std::string chosen = environment::value("LIPSYNC_YUNET_MODEL");
        !chosen.empty() && QFileInfo::exists(QString::fromStdString(chosen)))
        return chosen;
    return ResourceLocator::find("models/face_detection_yunet_2022mar.onnx");
}

FaceDetectorPaths FaceDetectorPaths::boxesOnly()
{
    FaceDetectorPaths paths;
    paths.useDlib = false;
    return paths;
}

std::string FaceDetectorPaths::haarCascadeFile() const
{
    return haarCascade.empty() ? systempaths::kHaarCascade : haarCascade;
}

std::string FaceDetectorPaths::dlibPredictorFile() const
{
    return dlibPredictor.empty() ? systempaths::kDlibPredictor : dlibPredictor;
}

FaceDetector::FaceDetector(const FaceDetectorPaths &paths) : m_impl(std::make_unique<Impl>())
{
    const std::string yunetPath = paths.yunetModel.empty() ? findYunetModel() : paths.yunetModel;
    if (!yunetPath.empty() && QFileInfo::exists(QString::fromStdString(yunetPath))) {
        try {
            m_impl->yunet = cv::FaceDetectorYN::create(yunetPath, "", cv::Size(320, 320), 0.6f, 0.3f, 20);
        } catch (const cv::Exception &) {
            m_impl->yunet.release();
        }
    }
    const std::string haarPath = paths.haarCascadeFile();
    if (QFileInfo::exists(QString::fromStdString(haarPath)))
        m_impl->haarLoaded = m_impl->haar.load(haarPath);
    const std::string dlibPath = paths.dlibPredictorFile();
    if (paths.useDlib && DlibFaceModels::available() && QFileInfo::exists(QString::fromStdString(dlibPath)))
        m_impl->dlib.loadPredictor(dlibPath);
}

FaceDetector::~FaceDetector() = default;

bool FaceDetector::hasYunet() const
{
    return !m_impl->yunet.empty();
}

bool FaceDetector::hasHaar() const
{
    return m_impl->haarLoaded;
}

bool FaceDetector::hasDlib() const
{
    return m_impl->dlib.hasPredictor();
}

std::string FaceDetector::available() const
{
    std::string s;
    auto add = [&](bool on, const char *name) {
        if (!on)
            return;
        if (!s.empty())
            s += ',';
        s += name;
    };
    add(hasYunet(), "yunet");
    add(hasHaar(), "haar");
    add(hasDlib(), "dlib");
    return s.empty() ? "none" : s;
}

std::vector<FaceDetection> FaceDetector::detect(const cv::Mat &bgrIn)
{
    std::vector<FaceDetection> out;
    if (bgrIn.empty())
        return out;
    cv::Mat bgr = bgrIn;
    if (bgr.type() == CV_8UC1)
        cv::cvtColor(bgrIn, bgr, cv::COLOR_GRAY2BGR);
    if (m_impl->yunet) {
        // YuNet works best on images of a few hundred pixels: detect on a downscaled copy.
        const double maxSide = 640.0;
        const double f = std::min(1.0, maxSide / std::max(bgr.cols, bgr.rows));
        cv::Mat small = bgr;
        if (f < 1.0)
            cv::resize(bgr, small, cv::Size(), f, f, cv::INTER_AREA);
        cv::Mat faces;
        m_impl->yunet->setInputSize(small.size());
        m_impl->yunet->detect(small, faces);
        for (int r = 0; r < faces.rows; ++r) {
            const float *row = faces.ptr<float>(r);
            FaceDetection d;
            d.source = "yunet";
            d.box = cv::Rect2d(row[0] / f, row[1] / f, row[2] / f, row[3] / f);
            d.score = row[14];
            d.hasKeypoints = true;
            for (int k = 0; k < 5; ++k)
                d.keypoints[size_t(k)] = Eigen::Vector2d(row[4 + 2 * k] / f, row[5 + 2 * k] / f);
            // Order by image side regardless of the model's convention.
            if (d.keypoints[0].x() > d.keypoints[1].x())
                std::swap(d.keypoints[0], d.keypoints[1]);
            if (d.keypoints[3].x() > d.keypoints[4].x())
                std::swap(d.keypoints[3], d.keypoints[4]);
            out.push_back(d);
        }
    }
    if (out.empty() && m_impl->haarLoaded) {
        cv::Mat grey;
        cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
        cv::equalizeHist(grey, grey);
        std::vector<cv::Rect> rects;
        std::vector<int> levels;
        std::vector<double> weights;
        const int minSide = std::max(24, std::min(bgr.cols, bgr.rows) / 10);
        m_impl->haar.detectMultiScale(grey, rects, levels, weights, 1.1, 3, 0,
                                      cv::Size(minSide, minSide), cv::Size(), true);
        for (size_t i = 0; i < rects.size(); ++i) {
            FaceDetection d;
            d.source = "haar";
            d.box = rects[i];
            d.score = i < weights.size() ? weights[i] : 0.0;
            out.push_back(d);
        }
    }
    std::sort(out.begin(), out.end(), [](const FaceDetection &a, const FaceDetection &b) {
        return a.box.area() * (0.5 + a.score) > b.box.area() * (0.5 + b.score);
    });
    return out;
}

namespace {
cv::Mat greyImage(const cv::Mat &bgr)
{
    cv::Mat grey;
    if (bgr.channels() == 3)
        cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
    else
        grey = bgr;
    return grey;
}
} // namespace

std::optional<cv::Rect2d> FaceDetector::dlibFaceBox(const cv::Mat &bgr, const FaceDetection &face)
{
    if (!m_impl->dlib.hasPredictor() || bgr.empty())
        return std::nullopt;
    const cv::Mat grey = greyImage(bgr);
    // dlib's predictor was trained on the boxes of dlib's HOG detector: use that detector's box
    // for this face when it finds one (on a copy of at most 480 pixels, for speed); otherwise
    // adjust the YuNet box, which is larger and higher, towards the HOG convention.
    cv::Rect2d b = face.box;
    bool fromHog = false;
    const double f = std::min(1.0, 480.0 / std::max(grey.cols, grey.rows));
    cv::Mat small = grey;
    if (f < 1.0)
        cv::resize(grey, small, cv::Size(), f, f, cv::INTER_AREA);
    double best = 0.0;
    for (const cv::Rect2d &r : m_impl->dlib.hogFaces(small)) {
        const cv::Rect2d candidate(r.x / f, r.y / f, r.width / f, r.height / f);
        const double inter = (candidate & face.box).area();
        const double iou = inter / (candidate.area() + face.box.area() - inter);
        if (iou > best && iou > 0.3) {
            best = iou;
            b = candidate;
            fromHog = true;
        }
    }
    if (!fromHog && face.source == "yunet") {
        const double cx = b.x + 0.5 * b.width, w = 0.86 * b.width;
        const double top = b.y + 0.17 * b.height, h = 0.86 * b.height;
        b = cv::Rect2d(cx - 0.5 * w, top, w, h);
    }
    return b;
}

Eigen::VectorXd FaceDetector::dlibLandmarksInBox(const cv::Mat &bgr, const cv::Rect2d &b)
{
    if (!m_impl->dlib.hasPredictor() || bgr.empty())
        return {};
    return m_impl->dlib.landmarks68(greyImage(bgr), b);
}

Eigen::VectorXd FaceDetector::dlibLandmarks(const cv::Mat &bgr, const FaceDetection &face)
{
    const std::optional<cv::Rect2d> box = dlibFaceBox(bgr, face);
    return box ? dlibLandmarksInBox(bgr, *box) : Eigen::VectorXd();
}

Eigen::VectorXd keypointAnchors(const Eigen::VectorXd &shape)
{
    auto centre = [&](int from) {
        Eigen::Vector2d c = Eigen::Vector2d::Zero();
        for (int i = from; i < from + 4; ++i)
            c += shape.segment<2>(2 * i);
        return Eigen::Vector2d(c / 4.0);
    };
    Eigen::VectorXd anchors(8);
    anchors << centre(0), centre(4), shape.segment<2>(2 * scheme23::kMouthLeft),
        shape.segment<2>(2 * scheme23::kMouthRight);
    return anchors;
}

Eigen::VectorXd detectionAnchors(const FaceDetection &face)
{
    if (!face.hasKeypoints)
        return {};
    Eigen::VectorXd anchors(8);
    anchors << face.keypoints[0], face.keypoints[1], face.keypoints[3], face.keypoints[4];
    return anchors;
}

Eigen::VectorXd detectionKeypoints(const FaceDetection &face)
{
    if (!face.hasKeypoints)
        return {};
    Eigen::VectorXd k(10);
    for (int i = 0; i < 5; ++i)
        k.segment<2>(2 * i) = face.keypoints[size_t(i)];
    return k;
}

Eigen::VectorXd initialShapeFromDetection(const Eigen::VectorXd &meanShape, const FaceDetection &face)
{
    const Eigen::VectorXd model = keypointAnchors(meanShape);
    Eigen::VectorXd target = detectionAnchors(face);
    if (target.size() == 0) {
        // Typical positions in a frontal Haar box (fractions of width and height).
        const cv::Rect2d &b = face.box;
        auto at = [&](double fx, double fy) { return Eigen::Vector2d(b.x + fx * b.width, b.y + fy * b.height); };
        target.resize(8);
        target << at(0.31, 0.40), at(0.69, 0.40), at(0.36, 0.76), at(0.64, 0.76);
    }
    return alignSimilarity(model, target).apply(meanShape);
}

Eigen::VectorXd initialShapeFromDetection(const AamModel &model, const FaceDetection &face)
{
    if (face.hasKeypoints && model.detectorShape.size() == model.meanShape.size()) {
        // detectorShape lives in the frame where the keypoints sit on the mean shape's anchors.
        const Similarity t = alignSimilarity(keypointAnchors(model.meanShape), detectionAnchors(face));
        if (model.detectorRegression.size() == 0)
            return t.apply(model.detectorShape);
        const Eigen::VectorXd k = t.inverse().apply(detectionKeypoints(face));
        return t.apply(Eigen::VectorXd(model.detectorShape
                                       + model.detectorRegression * (k - model.detectorKeypointMean)));
    }
    return initialShapeFromDetection(model.meanShape, face);
}

} // namespace lipsync
