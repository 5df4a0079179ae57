// Procrustes, PCA, the piecewise-affine warp, building, saving, fitting and synthesis of an AAM,
// on the committed GRID frames (tests/data/faces/grid, 20 frames with dlib-derived 23 points).
#include "aam/AamBuilder.h"
#include "aam/AamFitLevel.h"
#include "aam/AamFitStep.h"
#include "aam/AamFitter.h"
#include "aam/AamSynthesizer.h"
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "aam/TextureNormalisation.h"
#include "aam/VideoTracking.h"
#include "io/AtomicFile.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <chrono>
#include <cstring>
#include <random>

using namespace lipsync;

namespace {

const char *kHeldOut = "sgivzn";

std::vector<AamTrainingExample> gridExamples(bool heldOut)
{
    std::vector<AamTrainingExample> all = loadTrainingDirectory(LIPSYNC_TEST_DATA "/faces/grid");
    std::vector<AamTrainingExample> out;
    for (auto &e : all)
        if ((e.name.rfind(kHeldOut, 0) == 0) == heldOut)
            out.push_back(e);
    return out;
}

Eigen::VectorXd randomShape(std::mt19937 &rng)
{
    std::normal_distribution<double> noise(0.0, 0.02);
    Eigen::VectorXd s = templateShape();
    for (Eigen::Index i = 0; i < s.size(); ++i)
        s[i] += noise(rng);
    return s;
}

} // namespace

class TestAam : public QObject
{
    Q_OBJECT

    AamModel m_model;

private slots:
    void initTestCase()
    {
        Feedback feedback;
        AamBuildOptions options;
        options.combinedVariance = 0.98;
        m_model = buildAam(gridExamples(false), options, feedback);
        QCOMPARE(m_model.trainingImages, 18);
        QCOMPARE(feedback.progress(), 1.0);
    }

    void procrustesRemovesSimilarity()
    {
        std::mt19937 rng(1);
        const Eigen::VectorXd base = randomShape(rng);
        std::vector<Eigen::VectorXd> shapes;
        for (int i = 0; i < 6; ++i) {
            Similarity t;
            t.a = (1.0 + i) * std::cos(0.3 * i);
            t.b = (1.0 + i) * std::sin(0.3 * i);
            t.tx = 10.0 * i;
            t.ty = -5.0 * i;
            shapes.push_back(t.apply(base));
        }
        const ProcrustesResult r = generalisedProcrustes(shapes);
        QVERIFY(std::abs(r.mean.norm() - 1.0) < 1e-9);
        QVERIFY(shapeCentroid(r.mean).norm() < 1e-9);
        for (const auto &a : r.aligned)
            QVERIFY((a - r.mean).norm() < 1e-9); // similar copies collapse onto the mean
        // alignSimilarity recovers a known transform exactly.
        Similarity t{1.7, -0.4, 3.0, 9.0};
        const Similarity found = alignSimilarity(base, t.apply(base));
        QVERIFY(std::abs(found.a - t.a) < 1e-9 && std::abs(found.b - t.b) < 1e-9);
        QVERIFY(std::abs(found.tx - t.tx) < 1e-9 && std::abs(found.ty - t.ty) < 1e-9);
        QVERIFY((t.inverse().compose(t).apply(base) - base).norm() < 1e-9);
    }

    void pcaModesAreOrthonormalAndReconstructionImproves()
    {
        std::mt19937 rng(2);
        std::normal_distribution<double> n(0.0, 1.0);
        Eigen::MatrixXd data(30, 40); // 30 dims, 40 samples with decaying variance per dim
        for (int j = 0; j < 40; ++j)
            for (int i = 0; i < 30; ++i)
                data(i, j) = n(rng) * std::pow(0.8, i) + 2.0;
        const Pca all = computePca(data, 1.0);
        QCOMPARE(all.modes(), 30);
        const Eigen::MatrixXd gram = all.basis.transpose() * all.basis;
        QVERIFY((gram - Eigen::MatrixXd::Identity(30, 30)).cwiseAbs().maxCoeff() < 1e-9);
        for (int m = 1; m < all.modes(); ++m)
            QVERIFY(all.variances[m] <= all.variances[m - 1]);
        double previous = 1e300;
        for (int modes : {1, 3, 6, 12, 30}) {
            const Pca p = computePca(data, 1.0, modes);
            double err = 0.0;
            for (int j = 0; j < 40; ++j)
                err += (p.reconstruct(p.project(data.col(j))) - data.col(j)).squaredNorm();
            QVERIFY2(err < previous, qPrintable(QString::number(err)));
            previous = err;
        }
        QVERIFY(previous < 1e-18 * 40 + 1e-9);
        // Gram-matrix path (fewer samples than dimensions) gives orthonormal modes too, n-1 at most.
        const Pca wide = computePca(data.leftCols(5).transpose().replicate(1, 1).transpose(), 1.0);
        QVERIFY(wide.modes() <= 4);
        const Eigen::MatrixXd g2 = wide.basis.transpose() * wide.basis;
        QVERIFY((g2 - Eigen::MatrixXd::Identity(wide.modes(), wide.modes())).cwiseAbs().maxCoeff() < 1e-9);
        // Variance retained chooses fewer modes for a lower fraction.
        QVERIFY(computePca(data, 0.5).modes() < computePca(data, 0.95).modes());
        // What stopped it: the fraction, the cap, the samples (n-1 modes), or no variance left.
        const Pca reached = computePca(data, 0.95);
        QCOMPARE(reached.limit, PcaLimit::Variance);
        QVERIFY(reached.retainedFraction() >= 0.95);
        QVERIFY(reached.retainedFraction() - reached.variances.tail(1)[0] / reached.totalVariance < 0.95);
        const Pca capped = computePca(data, 0.95, 2);
        QCOMPARE(capped.modes(), 2);
        QCOMPARE(capped.limit, PcaLimit::Cap);
        QVERIFY(capped.retainedFraction() < 0.95);
        QCOMPARE(computePca(data, 1.0).limit, PcaLimit::Rank); // all 30 dimensions kept
        const Pca few = computePca(data.leftCols(6), 1.0);
        QCOMPARE(few.modes(), 5);
        QCOMPARE(few.limit, PcaLimit::Samples);
        QCOMPARE(std::string(pcaLimitName(few.limit)), std::string("samples"));
        QCOMPARE(computePca(data, 1.0, 30).limit, PcaLimit::Rank); // a cap that does not bind
    }

    void warpRoundTrip()
    {
        const PiecewiseAffineWarp &warp = m_model.warp(0);
        QVERIFY(warp.pixelCount() > 1000);
        // Every precomputed barycentric triple sums to one and reproduces the pixel position.
        std::vector<float> positions(size_t(2 * warp.pixelCount()));
        warp.pixelPositions(warp.referenceShape(), positions.data());
        for (int i = 0; i < warp.pixelCount(); i += 7) {
            const float *w = warp.pixelBarycentric(i);
            QVERIFY(std::abs(w[0] + w[1] + w[2] - 1.f) < 1e-5f);
            QVERIFY(std::abs(positions[size_t(2 * i)] - warp.pixelX(i)) < 1e-3f);
            QVERIFY(std::abs(positions[size_t(2 * i + 1)] - warp.pixelY(i)) < 1e-3f);
        }
        // Render a smooth pattern at a shape by sampling it through the warp, then sample again at
        // the same shape after a similarity: values agree (round trip of the warp tables).
        cv::Mat image(300, 400, CV_32F);
        for (int y = 0; y < image.rows; ++y)
            for (int x = 0; x < image.cols; ++x)
                image.at<float>(y, x) = float(100 + 50 * std::sin(x * 0.05) * std::cos(y * 0.07));
        Similarity t{1.3, 0.2, 120, 60};
        const Eigen::VectorXd shape = t.apply(warp.referenceShape());
        std::vector<float> a(size_t(warp.pixelCount()));
        warp.sampleGrey(image, shape, a.data());
        for (int i = 0; i < warp.pixelCount(); i += 13) {
            const Eigen::Vector2d p = t.apply(Eigen::Vector2d(warp.pixelX(i), warp.pixelY(i)));
            const float expected = float(100 + 50 * std::sin(p.x() * 0.05) * std::cos(p.y() * 0.07));
            QVERIFY2(std::abs(a[size_t(i)] - expected) < 0.5f, qPrintable(QString::number(i)));
        }
        // Vertices map through the warp onto the shape.
        QVERIFY((warp.warpVertices(warp.referenceShape(), shape) - shape).cwiseAbs().maxCoeff() < 1e-6);
    }

    void warpPixelsBelongToTheFirstTriangleHoldingThem()
    {
        // The warp rasterises each triangle over its bounding box only: every pixel of the frame
        // must still get the first triangle (in list order) that holds it, pixels are numbered in
        // raster order, and pixels outside every triangle stay -1 in the index map.
        const PiecewiseAffineWarp &warp = m_model.warp(0);
        const Eigen::VectorXd &r = warp.referenceShape();
        const auto holds = [&](const Triangle &t, double x, double y) {
            const double ax = r[2 * t[0]], ay = r[2 * t[0] + 1];
            const double bx = r[2 * t[1]] - ax, by = r[2 * t[1] + 1] - ay;
            const double cx = r[2 * t[2]] - ax, cy = r[2 * t[2] + 1] - ay;
            const double det = bx * cy - by * cx;
            if (std::abs(det) < 1e-12)
                return false;
            const double beta = ((x - ax) * cy - (y - ay) * cx) / det;
            const double gamma = (bx * (y - ay) - by * (x - ax)) / det;
            return 1.0 - beta - gamma >= -1e-9 && beta >= -1e-9 && gamma >= -1e-9;
        };
        int next = 0;
        for (int y = 0; y < warp.height(); ++y) {
            for (int x = 0; x < warp.width(); ++x) {
                int first = -1;
                for (int t = 0; first < 0 && t < int(warp.triangles().size()); ++t)
                    if (holds(warp.triangles()[size_t(t)], x, y))
                        first = t;
                const int index = warp.indexMap().at<int>(y, x);
                if (first < 0) {
                    QCOMPARE(index, -1);
                    continue;
                }
                QCOMPARE(index, next++);
                QCOMPARE(warp.pixelTriangle(index), first);
                QCOMPARE(warp.pixelX(index), x);
                QCOMPARE(warp.pixelY(index), y);
            }
        }
        QCOMPARE(next, warp.pixelCount());
    }

    void tinyFuzzSeedsAreValidModels()
    {
        // The fuzz seeds of tests/data/fuzz/aam (see its README) must stay loadable models, or the
        // fuzzer would only explore the error paths.
        for (const char *name : {"tiny.aam", "tiny-no-identifier.aam"}) {
            const AamModel m = AamModel::load(std::string(LIPSYNC_TEST_DATA "/fuzz/aam/") + name);
            QCOMPARE(m.pointCount(), 23);
            QVERIFY(m.warp(0).pixelCount() > 50);
            QCOMPARE(m.textureMean.size(), Eigen::Index(3 * m.warp(0).pixelCount()));
        }
    }

    void damagedSizesAreRejectedBeforeAllocatingOrRasterising()
    {
        // tests/data/fuzz/aam/tiny-no-identifier.aam (no content hash to stop the damage early):
        // 23 points, 1 shape mode, 35 triangles, then the reference scale at byte 1204 and the
        // colour texture's length at 1212.
        const std::string original = readWholeFile(LIPSYNC_TEST_DATA "/fuzz/aam/tiny-no-identifier.aam");
        double scale = 0;
        int textureLength = 0;
        std::memcpy(&scale, original.data() + 1204, sizeof scale);
        std::memcpy(&textureLength, original.data() + 1212, sizeof textureLength);
        QVERIFY(std::abs(scale - 23.29) < 0.01);
        QCOMPARE(textureLength, 309);
        const auto reason = [](const std::string &bytes) -> QString {
            try {
                AamModel::fromBytes(bytes, "t.aam");
            } catch (const Error &e) {
                return QString::fromStdString(e.reason());
            }
            return QStringLiteral("loaded");
        };
        QCOMPARE(reason(original), QStringLiteral("loaded"));
        // A length claiming more doubles than the bytes left: rejected before the vector exists.
        std::string longer = original;
        const int tooMany = int((original.size() - 1216) / sizeof(double)) + 1;
        std::memcpy(longer.data() + 1212, &tooMany, sizeof tooMany);
        QVERIFY2(reason(longer).contains("more textureMean than the file holds"), qPrintable(reason(longer)));
        // A reference frame 10x larger: its triangles hold far more than the 103 declared pixels,
        // which the check before rasterising reports (after it, the message would be "texture size").
        std::string bigger = original;
        const double tenTimes = 10 * scale;
        std::memcpy(bigger.data() + 1204, &tenTimes, sizeof tenTimes);
        QCOMPARE(reason(bigger), QStringLiteral("inconsistent AAM model (level texture size)"));
    }

    void modelHasExpectedStructure()
    {
        QCOMPARE(m_model.pointCount(), 23);
        QVERIFY(m_model.shapeModes() >= 2 && m_model.shapeModes() <= 17);
        QVERIFY(m_model.combinedModes() >= 2 && m_model.combinedModes() <= 17);
        QVERIFY(m_model.triangles.size() >= 25);
        QVERIFY(QString::fromStdString(m_model.identifier).startsWith("aam-"));
        QCOMPARE(m_model.identifier, m_model.computeIdentifier());
        // Combined parameters of the mean are zero; parts survive a round trip.
        const Eigen::VectorXd c = Eigen::VectorXd::Random(m_model.combinedModes()) * 0.01;
        Eigen::VectorXd bs, bg;
        m_model.partsFromCombined(c, bs, bg);
        QVERIFY((m_model.combinedFromParts(bs, bg) - c).norm() < 1e-9);
    }

    void referenceFrameAndModesFollowTheData()
    {
        // Automatic reference frame: 1.5 times the training faces' median outer-eye distance
        // (about 64 pixels on GRID s1), and levels down to about 20 pixels.
        std::vector<AamTrainingExample> examples = gridExamples(false);
        std::vector<double> eyes;
        for (const auto &e : examples)
            eyes.push_back((e.shape.segment<2>(0) - e.shape.segment<2>(12)).norm());
        std::sort(eyes.begin(), eyes.end());
        const double median = eyes[eyes.size() / 2];
        Feedback feedback;
        AamBuildReport report;
        const AamModel automatic = buildAam(examples, AamBuildOptions{}, feedback, nullptr, &report);
        QCOMPARE(report.referenceEyeDistance, std::round(1.5 * median));
        QCOMPARE(report.levels, 3);
        QCOMPARE(int(automatic.levels.size()), 3);
        const double modelEyes = automatic.referenceScale
            * (automatic.meanShape.segment<2>(0) - automatic.meanShape.segment<2>(12)).norm();
        QVERIFY2(std::abs(modelEyes - report.referenceEyeDistance) < 1e-6, qPrintable(QString::number(modelEyes)));
        // The report matches the model; 18 images allow 17 modes, the paper's cap does not bind.
        QCOMPARE(report.combined.modes, automatic.combinedModes());
        QCOMPARE(report.shape.modes, automatic.shapeModes());
        QCOMPARE(report.texture.modes, automatic.textureModes());
        QCOMPARE(report.combined.limit, PcaLimit::Variance);
        QVERIFY(report.combined.retainedVariance >= 0.98);
        // A given size wins, and so do the levels; a cap below the variance's count binds.
        AamBuildOptions fixed;
        fixed.referenceEyeDistance = 40;
        fixed.levels = 1;
        fixed.maxCombinedModes = 3;
        const AamModel small = buildAam(examples, fixed, feedback, nullptr, &report);
        QCOMPARE(report.referenceEyeDistance, 40.0);
        QCOMPARE(int(small.levels.size()), 1);
        QVERIFY(small.warp(0).pixelCount() < automatic.warp(0).pixelCount() / 4);
        QCOMPARE(small.combinedModes(), 3);
        QCOMPARE(report.combined.limit, PcaLimit::Cap);
        // All the variance: the images are the limit.
        AamBuildOptions all;
        all.shapeVariance = all.textureVariance = all.combinedVariance = 1.0;
        buildAam(examples, all, feedback, nullptr, &report);
        QCOMPARE(report.texture.limit, PcaLimit::Samples);
        QCOMPARE(report.texture.modes, 17);
        QCOMPARE(report.combined.limit, PcaLimit::Samples);
    }

    void mirrorAugmentationDoublesTheTrainingSetAndSymmetrisesTheMean()
    {
        Feedback feedback;
        AamBuildOptions options;
        options.mirror = true;
        const AamModel mirrored = buildAam(gridExamples(false), options, feedback);
        QCOMPARE(mirrored.trainingImages, 36);
        // The mean of a set closed under mirroring is its own mirror, up to a similarity.
        const Eigen::VectorXd flipped = mirrorShape(mirrored.meanShape, 1);
        const Eigen::VectorXd aligned = alignSimilarity(flipped, mirrored.meanShape).apply(flipped);
        const double asymmetry = (aligned - mirrored.meanShape).norm();
        const Eigen::VectorXd plainFlipped = mirrorShape(m_model.meanShape, 1);
        const double plainAsymmetry =
            (alignSimilarity(plainFlipped, m_model.meanShape).apply(plainFlipped) - m_model.meanShape).norm();
        QVERIFY2(asymmetry < 1e-3 * shapeSize(mirrored.meanShape), qPrintable(QString::number(asymmetry)));
        QVERIFY(asymmetry < 0.1 * plainAsymmetry);
        // More data: at least as many shape modes as without mirroring.
        QVERIFY(mirrored.shapeModes() >= m_model.shapeModes());
    }

    void detectorRegressionStartsFromAllFiveKeypoints()
    {
        FaceDetector detector(FaceDetectorPaths::boxesOnly());
        QVERIFY2(detector.hasYunet(), "the YuNet model in resources/models was not found");
        Feedback feedback;
        AamBuildOptions options;
        options.detector = &detector;
        options.maxExemplars = 0; // version 2's content (exemplars make it 3)
        options.singlePrecisionBases = false; // (and single-precision bases 4)
        const AamModel model = buildAam(gridExamples(false), options, feedback);
        QCOMPARE(model.detectorShape.size(), Eigen::Index(46));
        QCOMPARE(model.detectorRegression.rows(), Eigen::Index(46));
        QCOMPARE(model.detectorRegression.cols(), Eigen::Index(10));
        QCOMPARE(model.detectorKeypointMean.size(), Eigen::Index(10));
        QVERIFY(model.detectorRegression.allFinite() && model.detectorRegression.norm() > 0);

        // Keypoints at their training mean: the start moves with the keypoints (a similarity of
        // them moves it by the same similarity) and is near the calibrated mean shape.
        auto detection = [](const Eigen::VectorXd &k) {
            FaceDetection face;
            face.hasKeypoints = true;
            for (int i = 0; i < 5; ++i)
                face.keypoints[size_t(i)] = k.segment<2>(2 * i);
            return face;
        };
        const Similarity move{1.7, 0.2, 40.0, 25.0};
        FaceDetection face = detection(move.apply(model.detectorKeypointMean));
        const Eigen::VectorXd start = initialShapeFromDetection(model, face);
        const Eigen::VectorXd atMean = initialShapeFromDetection(model, detection(model.detectorKeypointMean));
        QVERIFY((start - move.apply(atMean)).cwiseAbs().maxCoeff() < 1e-6);
        QVERIFY(normalisedMeanError(atMean, model.detectorShape) < 0.02);
        // A nose further to the image right moves the start: the regression uses it.
        face.keypoints[2].x() += 5.0;
        QVERIFY((initialShapeFromDetection(model, face) - start).cwiseAbs().maxCoeff() > 0.1);

        // Held-out frames: the regression start is close to the truth.
        for (const auto &e : gridExamples(true)) {
            const cv::Mat image = cv::imread(e.imagePath);
            const auto faces = detector.detect(image);
            QVERIFY(!faces.empty());
            const double nme = normalisedMeanError(initialShapeFromDetection(model, faces.front()), e.shape);
            QVERIFY2(nme < 0.1, qPrintable(QString::number(nme)));
        }

        // Saved as version 2 with the regression; a model without it stays version 1.
        QTemporaryDir dir;
        const std::string path = (dir.path() + "/r.aam").toStdString();
        model.save(path);
        QCOMPARE(int(readWholeFile(path)[8]), 2);
        const AamModel back = AamModel::load(path);
        QCOMPARE(back.identifier, model.identifier);
        QVERIFY(back.detectorRegression.isApprox(model.detectorRegression));
    }

    void saveLoadRoundTrip()
    {
        QTemporaryDir dir;
        const std::string path = (dir.path() + "/m.aam").toStdString();
        m_model.save(path);
        const AamModel back = AamModel::load(path);
        QCOMPARE(back.identifier, m_model.identifier);
        QCOMPARE(back.computeIdentifier(), m_model.identifier);
        QVERIFY(back.combinedBasis.isApprox(m_model.combinedBasis));
        QCOMPARE(back.warp(0).pixelCount(), m_model.warp(0).pixelCount());
        QVERIFY(back.exemplarDetail == m_model.exemplarDetail);
        QVERIFY(back.exemplarParams == m_model.exemplarParams);
        QVERIFY(back.exemplarScales == m_model.exemplarScales);
        // The builder's bases are single precision (version 4), read back exactly, in half the
        // bytes of the same model in doubles (version 3).
        QVERIFY(m_model.singlePrecisionBases && back.singlePrecisionBases);
        QVERIFY(back.textureBasis == m_model.textureBasis);
        QVERIFY(back.levels[0].basis == m_model.levels[0].basis);
        QCOMPARE(int(readWholeFile(path)[8]), 4);
        const size_t singleBytes = readWholeFile(path).size();
        // The lowest version that holds the content: 3 with exemplars, 1 for a grey model
        // without detector calibration or exemplars (as files written before exemplars existed).
        AamModel plain = m_model;
        plain.singlePrecisionBases = false;
        plain.identifier = plain.computeIdentifier();
        plain.save(path);
        QCOMPARE(int(readWholeFile(path)[8]), 3);
        QVERIFY(!AamModel::load(path).singlePrecisionBases);
        QVERIFY(AamModel::load(path).textureBasis == m_model.textureBasis); // doubles hold floats
        QVERIFY2(double(singleBytes) < 0.65 * double(readWholeFile(path).size()), "bases are most of the file");
        plain.exemplarParams.resize(0, 0);
        plain.exemplarDetail.resize(0, 0);
        plain.exemplarScales.resize(0);
        plain.identifier = plain.computeIdentifier();
        plain.save(path);
        QCOMPARE(int(readWholeFile(path)[8]), 1);
        QCOMPARE(AamModel::load(path).exemplarCount(), 0);
        m_model.save(path);
        // Truncated, wrong magic and wrong version are clear errors.
        std::string bytes = readWholeFile(path);
        const std::string original = bytes;
        writeFileAtomically(path, bytes.substr(0, bytes.size() / 2));
        QVERIFY_THROWS_EXCEPTION(Error, AamModel::load(path));
        writeFileAtomically(path, "not a model");
        QVERIFY_THROWS_EXCEPTION(Error, AamModel::load(path));
        bytes[8] = 99;
        writeFileAtomically(path, bytes);
        try {
            AamModel::load(path);
            QFAIL("loaded a wrong version");
        } catch (const Error &e) {
            QVERIFY2(QString(e.what()).contains("version"), e.what());
        }
        // Damaged numbers that still parse: the content no longer matches its identifier.
        std::string damaged = original;
        damaged[damaged.size() / 2] = char(~damaged[damaged.size() / 2]);
        writeFileAtomically(path, damaged);
        try {
            AamModel::load(path);
            QFAIL("loaded a damaged model");
        } catch (const Error &e) {
            QVERIFY2(QString(e.what()).contains("corrupt AAM file") && QString(e.what()).contains("m.aam"), e.what());
        }
    }

    void fitConvergesOnHeldOutFrame_data()
    {
        QTest::addColumn<int>("algorithm");
        QTest::addColumn<bool>("gradientOrientation");
        QTest::newRow("project-out") << int(AamFitAlgorithm::ProjectOut) << false;
        QTest::newRow("wiberg") << int(AamFitAlgorithm::Wiberg) << false;
        QTest::newRow("wiberg-igo") << int(AamFitAlgorithm::Wiberg) << true;
    }

    // The warp Jacobian the fitter precomputes (dW/dp per pixel, Matthews & Baker §4.1.1) equals
    // central finite differences of where the piecewise-affine warp puts each reference pixel
    // as the shape moves along each basis displacement, at every level.
    void warpJacobianMatchesFiniteDifferences()
    {
        const AamFitter fitter(m_model);
        for (int l = 0; l < int(m_model.levels.size()); ++l) {
            const AamFitLevel &level = fitter.level(l);
            const PiecewiseAffineWarp &warp = m_model.warp(l);
            const int N = warp.pixelCount(), P = int(level.basis.cols());
            QCOMPARE(int(level.warpX.rows()), N);
            QCOMPARE(int(level.warpX.cols()), P);
            const double h = 0.5; // pixels of the level frame; the warp is linear in the vertices
            std::vector<float> plus(size_t(2 * N)), minus(size_t(2 * N));
            double worst = 0, scale = 0;
            for (int j = 0; j < P; ++j) {
                warp.pixelPositions(level.reference + h * level.basis.col(j), plus.data());
                warp.pixelPositions(level.reference - h * level.basis.col(j), minus.data());
                for (int i = 0; i < N; ++i) {
                    const double dx = (double(plus[size_t(2 * i)]) - minus[size_t(2 * i)]) / (2 * h);
                    const double dy = (double(plus[size_t(2 * i + 1)]) - minus[size_t(2 * i + 1)]) / (2 * h);
                    worst = std::max({worst, std::abs(dx - level.warpX(i, j)), std::abs(dy - level.warpY(i, j))});
                    scale = std::max({scale, std::abs(double(level.warpX(i, j))), std::abs(double(level.warpY(i, j)))});
                }
            }
            qInfo("level %d: %d pixels x %d parameters, largest difference %.2g (largest entry %.2g)", l, N, P,
                  worst, scale);
            QVERIFY2(scale > 0.05 && worst < 1e-3 * scale, qPrintable(QString::number(worst)));
        }
    }

    // The Wiberg step as Ceres's GradientChecker would check it, at every level:
    //  - its Jacobian (steepestDescent: texture gradient times dW/dp, appearance projected out)
    //    equals central finite differences of a smooth texture T sampled through the warp,
    //    d T(W(x; p)) / dp at p = 0, with the same projection;
    //  - the step it returns minimises its objective |e - J dp|^2 + s2 (b - M dp)^T L^-1 (b - M dp)
    //    (Tzimiropoulos & Pantic 2013, the MAP form of eq. 15): the objective's finite-difference
    //    gradient vanishes there and is the analytic one at dp = 0;
    //  - a stronger prior moves the shape less.
    void wibergStepMatchesFiniteDifferences()
    {
        const AamFitter fitter(m_model);
        std::mt19937 random(7);
        std::normal_distribution<double> gauss;
        for (int l = 0; l < int(m_model.levels.size()); ++l) {
            const AamFitLevel &level = fitter.level(l);
            const PiecewiseAffineWarp &warp = m_model.warp(l);
            const int N = warp.pixelCount(), P = int(level.basis.cols());
            const int channels = int(level.templateMean.size() / N);
            // A smooth texture with a known closed form, one phase per channel.
            auto texture = [&](double x, double y, int c) {
                return std::sin(x / 6.0 + c) + std::cos(y / 5.0 - c) + 1e-3 * x * y;
            };
            Eigen::VectorXf t(Eigen::Index(channels) * N);
            for (int c = 0; c < channels; ++c)
                for (int i = 0; i < N; ++i)
                    t[Eigen::Index(c) * N + i] = float(texture(warp.pixelX(i), warp.pixelY(i), c));
            const Eigen::MatrixXf sd = steepestDescent(level, warp, t);
            QCOMPARE(int(sd.rows()), int(t.size()));
            QCOMPARE(int(sd.cols()), P);
            const double h = 1e-3;
            std::vector<float> plus(size_t(2 * N)), minus(size_t(2 * N));
            Eigen::MatrixXd numeric(t.size(), P);
            for (int j = 0; j < P; ++j) {
                warp.pixelPositions(level.reference + h * level.basis.col(j), plus.data());
                warp.pixelPositions(level.reference - h * level.basis.col(j), minus.data());
                for (int c = 0; c < channels; ++c)
                    for (int i = 0; i < N; ++i)
                        numeric(Eigen::Index(c) * N + i, j)
                            = (texture(plus[size_t(2 * i)], plus[size_t(2 * i + 1)], c)
                               - texture(minus[size_t(2 * i)], minus[size_t(2 * i + 1)], c)) / (2 * h);
            }
            const Eigen::MatrixXd a = level.appearance.cast<double>();
            if (a.cols() > 0)
                numeric -= a * (a.transpose() * numeric);
            // The texture's gradient is central differences on the pixel grid (error ~ T''' / 6)
            // and one-sided at the frame's edge: compare whole columns, not single pixels.
            double worst = 0;
            for (int j = 0; j < P; ++j)
                worst = std::max(worst, (sd.col(j).cast<double>() - numeric.col(j)).norm() / numeric.col(j).norm());
            qInfo("level %d: steepest-descent columns within %.3g of finite differences (relative)", l, worst);
            QVERIFY2(worst < 0.1, qPrintable(QString::number(worst)));

            // The step minimises its own objective.
            Eigen::VectorXf error(t.size());
            for (Eigen::Index i = 0; i < error.size(); ++i)
                error[i] = float(0.05 * gauss(random));
            Eigen::VectorXd shapeParams(m_model.shapeVariances.size());
            for (Eigen::Index i = 0; i < shapeParams.size(); ++i)
                shapeParams[i] = 0.5 * std::sqrt(m_model.shapeVariances[i]) * gauss(random);
            const double residual = 0.01, weight = 2.0;
            const WibergStep step(m_model.shapeVariances, weight);
            const Eigen::VectorXd dp = step.step(level, warp, error, residual, shapeParams);
            QCOMPARE(int(dp.size()), P);
            QVERIFY(dp.allFinite() && dp.norm() > 0);
            const Eigen::VectorXf instance
                = level.templateMean + level.appearance * (level.appearance.transpose() * error);
            const Eigen::MatrixXd j = steepestDescent(level, warp, instance).cast<double>();
            const Eigen::VectorXd e = error.cast<double>(), inverse = m_model.shapeVariances.cwiseMax(1e-12).cwiseInverse();
            const Eigen::MatrixXd &M = level.toShapeParams;
            const double s2 = weight * residual;
            auto objective = [&](const Eigen::VectorXd &d) {
                const Eigen::VectorXd shape = shapeParams - M * d;
                return (e - j * d).squaredNorm() + s2 * shape.dot(inverse.asDiagonal() * shape);
            };
            auto numericGradient = [&](const Eigen::VectorXd &at) {
                Eigen::VectorXd g(P);
                const double step = 1e-4 * std::max(1.0, at.norm());
                for (int k = 0; k < P; ++k) {
                    Eigen::VectorXd u = Eigen::VectorXd::Zero(P);
                    u[k] = step;
                    g[k] = (objective(at + u) - objective(at - u)) / (2 * step);
                }
                return g;
            };
            const Eigen::VectorXd analyticAtZero = -2.0 * (j.transpose() * e + s2 * M.transpose() * (inverse.asDiagonal() * shapeParams));
            const Eigen::VectorXd atZero = numericGradient(Eigen::VectorXd::Zero(P));
            QVERIFY2((atZero - analyticAtZero).norm() < 1e-5 * analyticAtZero.norm(),
                     qPrintable(QString::number((atZero - analyticAtZero).norm() / analyticAtZero.norm())));
            // At the step the gradient vanishes (up to the solver's 1e-6 Levenberg damping).
            const double atStep = numericGradient(dp).norm();
            qInfo("level %d: objective gradient %.3g at 0, %.3g at the step", l, atZero.norm(), atStep);
            QVERIFY2(atStep < 1e-3 * atZero.norm(), qPrintable(QString::number(atStep / atZero.norm())));
            QVERIFY(objective(dp) < objective(Eigen::VectorXd::Zero(P)));
            // A prior a hundred times as strong leaves the shape nearer the model's mean.
            const Eigen::VectorXd strong = WibergStep(m_model.shapeVariances, 100 * weight).step(level, warp, error, residual, shapeParams);
            auto mahalanobis = [&](const Eigen::VectorXd &d) {
                const Eigen::VectorXd shape = shapeParams - M * d;
                return shape.dot(inverse.asDiagonal() * shape);
            };
            QVERIFY(mahalanobis(strong) < mahalanobis(dp));
        }
    }

    void fitConvergesOnHeldOutFrame()
    {
        QFETCH(int, algorithm);
        QFETCH(bool, gradientOrientation);
        AamFitOptions options;
        options.algorithm = AamFitAlgorithm(algorithm);
        AamModel igo;
        if (gradientOrientation) {
            // Gradient-orientation textures: two values (cos, sin) per reference pixel per level,
            // kept through a save and load (format version 2).
            Feedback feedback;
            AamBuildOptions build;
            build.combinedVariance = 0.98;
            build.fitFeatures = AamFitFeatures::GradientOrientation;
            build.maxExemplars = 0;
            build.singlePrecisionBases = false;
            const AamModel built = buildAam(gridExamples(false), build, feedback);
            QCOMPARE(built.levels[0].mean.size(), Eigen::Index(2 * built.warp(0).pixelCount()));
            QTemporaryDir dir;
            const std::string path = (dir.path() + "/igo.aam").toStdString();
            built.save(path);
            QCOMPARE(int(readWholeFile(path)[8]), 2);
            igo = AamModel::load(path);
            QCOMPARE(igo.identifier, built.identifier);
            QVERIFY(igo.fitFeatures == AamFitFeatures::GradientOrientation);
        }
        const AamFitter fitter(gradientOrientation ? igo : m_model);
        int improved = 0;
        for (const auto &e : gridExamples(true)) {
            const cv::Mat image = cv::imread(e.imagePath);
            QVERIFY(!image.empty());
            // Perturb the labelled shape: shift 4 px, scale 6 %, rotate 3 degrees.
            Similarity pose;
            Eigen::VectorXd params;
            fitter.projectShape(e.shape, pose, params);
            Similarity perturb{1.06 * std::cos(0.05), 1.06 * std::sin(0.05), 0, 0};
            const Eigen::Vector2d c = shapeCentroid(e.shape);
            Similarity move = Similarity{1, 0, c.x() + 4, c.y() - 3}.compose(perturb.compose(Similarity{1, 0, -c.x(), -c.y()}));
            const Eigen::VectorXd start = move.apply(e.shape);
            const double before = normalisedMeanError(start, e.shape);
            AamFitOptions withHistory = options;
            withHistory.keepHistory = true;
            const AamFitResult fit = fitter.fit(image, start, withHistory);
            const double after = normalisedMeanError(fit.shape, e.shape);
            qInfo("%s: NME %.4f -> %.4f, error %.4f, %d iterations", e.name.c_str(), before, after,
                  fit.error, fit.iterations);
            // The history: the start projected on the model, then every accepted step to the
            // result, coarse levels first, each level's residual falling.
            QVERIFY(fit.history.size() >= 2);
            QVERIFY((fit.history.back().shape - fit.shape).cwiseAbs().maxCoeff() < 1e-9);
            QCOMPARE(fit.history.back().residual, fit.error);
            QVERIFY(normalisedMeanError(fit.history.front().shape, start) < 0.05);
            for (size_t i = 1; i < fit.history.size(); ++i) {
                QVERIFY(fit.history[i].level <= fit.history[i - 1].level);
                if (fit.history[i].level == fit.history[i - 1].level)
                    QVERIFY(fit.history[i].residual < fit.history[i - 1].residual);
            }
            QVERIFY(fitter.fit(image, start, options).history.empty()); // not kept unless asked
            QVERIFY(before > 0.06);
            QVERIFY2(after < 0.04, qPrintable(QString::number(after)));
            improved += after < before;
        }
        QCOMPARE(improved, 2);
    }

    void fixedPointsStayPut()
    {
        const AamFitter fitter(m_model);
        const auto held = gridExamples(true);
        const cv::Mat image = cv::imread(held.front().imagePath);
        AamFitOptions options;
        options.fixedShape = held.front().shape;
        options.fixedShape.segment<2>(2 * 20) += Eigen::Vector2d(0, 6); // user pulled the chin down
        options.fixedMask.assign(23, false);
        options.fixedMask[20] = true;
        const AamFitResult fit = fitter.fit(image, held.front().shape, options);
        QVERIFY((fit.shape.segment<2>(40) - options.fixedShape.segment<2>(40)).norm() < 1e-9);
        // The rest of the face still fits.
        QVERIFY(normalisedMeanError(fit.shape, held.front().shape) < 0.06);
    }

    void featuresAndSynthesis()
    {
        const AamFitter fitter(m_model);
        const auto held = gridExamples(true);
        const cv::Mat image = cv::imread(held.front().imagePath);
        const AamFitResult fit = fitter.fit(image, held.front().shape);
        const Eigen::VectorXd c = fitter.features(image, fit);
        QCOMPARE(c.size(), Eigen::Index(m_model.combinedModes()));
        QVERIFY(c.allFinite());

        const AamSynthesizer synth(m_model);
        // The synthesised shape of the fitted parameters is close to the fit.
        const Eigen::VectorXd shape = fit.pose.apply(synth.shape(c));
        QVERIFY2(normalisedMeanError(shape, fit.shape) < 0.03,
                 qPrintable(QString::number(normalisedMeanError(shape, fit.shape))));
        // Compositing changes pixels inside the face and none far outside it.
        cv::Mat frame(image.size(), CV_8UC3, cv::Scalar(0, 255, 0));
        synth.composite(c, fit.pose, frame);
        const Eigen::Vector2d mouth = fit.shape.segment<2>(2 * 14);
        const cv::Vec3b inside = frame.at<cv::Vec3b>(int(mouth.y()) - 3, int(mouth.x()));
        QVERIFY(inside != cv::Vec3b(0, 255, 0));
        QCOMPARE(frame.at<cv::Vec3b>(2, 2), cv::Vec3b(0, 255, 0));
        // The composite resembles the real frame inside the face (reconstruction, not noise).
        cv::Mat real = image.clone();
        synth.composite(c, fit.pose, real);
        cv::Mat diff;
        cv::absdiff(real, image, diff);
        const cv::Rect box(int(fit.shape[36]) + 5, int(fit.shape[1]), 30, 40);
        QVERIFY2(cv::mean(diff(box))[1] < 25.0, qPrintable(QString::number(cv::mean(diff(box))[1])));
    }

    // The exemplar detail gives a training image back (up to its 8-bit quantisation) at its own
    // parameters, blends continuously between exemplars, and makes the drawn mouth sharper.
    void exemplarDetailRestoresWhatTheModesSmooth()
    {
        QCOMPARE(m_model.exemplarCount(), m_model.trainingImages);
        const AamSynthesizer synth(m_model);
        const auto training = gridExamples(false);
        const int i = 7;
        const cv::Mat image = cv::imread(training[size_t(i)].imagePath);
        Eigen::VectorXf g(m_model.textureMean.size());
        m_model.warp(0).sampleColour(image, training[size_t(i)].shape, g.data());
        normaliseTexture(g.data(), size_t(g.size()));
        const Eigen::VectorXd ci = m_model.exemplarParams.col(i);
        const auto own = synth.detailWeights(ci);
        QCOMPARE(int(own.size()), 1);
        QCOMPARE(own.front().first, i);
        QCOMPARE(own.front().second, 1.f);
        // The detail added is the fine part of what the synthesis at the image's own parameters
        // misses, up to 8 bits; what is still missing then is mostly smooth.
        const Eigen::VectorXf smooth = synth.texture(ci), detailed = synth.texture(ci, true);
        const PiecewiseAffineWarp &warp = m_model.warp(0);
        const Eigen::VectorXd missing = (g - smooth).cast<double>();
        const Eigen::VectorXf added = detailed - smooth;
        const double quantum = 0.51 * m_model.exemplarScales[i] + 1e-6;
        QVERIFY2((added.cast<double>() - textureDetail(warp, missing)).cwiseAbs().maxCoeff() <= quantum,
                 qPrintable(QString::number((added.cast<double>() - textureDetail(warp, missing)).cwiseAbs().maxCoeff())));
        const Eigen::VectorXd stillMissing = (g - detailed).cast<double>();
        QVERIFY2(textureDetail(warp, stillMissing).norm() < 0.5 * textureDetail(warp, missing).norm(),
                 qPrintable(QString("%1 vs %2").arg(textureDetail(warp, stillMissing).norm())
                                .arg(textureDetail(warp, missing).norm())));
        QVERIFY2(textureDetail(warp, missing).norm() > 0.3 * missing.norm(), "the synthesis misses fine structure");
        QVERIFY2((detailed - g).norm() < 0.95 * (smooth - g).norm(),
                 qPrintable(QString("%1 vs %2").arg((detailed - g).norm()).arg((smooth - g).norm())));
        // The detail of a smooth residual (a ramp across the face) is next to nothing.
        Eigen::VectorXd ramp(missing.size());
        for (int p = 0; p < warp.pixelCount(); ++p)
            for (int c = 0; c < 3; ++c)
                ramp[3 * p + c] = 0.01 * warp.pixelX(p);
        QVERIFY2(textureDetail(warp, ramp).cwiseAbs().maxCoeff() < 0.05 * ramp.cwiseAbs().maxCoeff() + 1e-3,
                 qPrintable(QString::number(textureDetail(warp, ramp).cwiseAbs().maxCoeff())));

        // Between two exemplars: two weights of unit norm that move continuously with c.
        const Eigen::VectorXd cj = m_model.exemplarParams.col(3);
        auto weightOf = [&](const std::vector<std::pair<int, float>> &w, int k) {
            for (const auto &[index, weight] : w)
                if (index == k)
                    return weight;
            return 0.f;
        };
        float previous = 1.f;
        for (double t = 0.0; t <= 1.0; t += 0.05) {
            const auto w = synth.detailWeights((1 - t) * ci + t * cj);
            QVERIFY(!w.empty() && w.size() <= 2);
            double norm = 0;
            for (const auto &[k, weight] : w)
                norm += double(weight) * weight;
            QVERIFY2(std::abs(norm - 1.0) < 1e-5, qPrintable(QString::number(norm)));
            const float mine = weightOf(w, i);
            QVERIFY2(std::abs(mine - previous) < 0.35f, qPrintable(QString("t=%1: %2 after %3").arg(t).arg(mine).arg(previous)));
            previous = mine;
        }
        QCOMPARE(weightOf(synth.detailWeights(cj), 3), 1.f);

        // Drawn into the frame, the mouth has the image's fine structure (Laplacian energy) with
        // the detail, far closer to the recording's than without.
        const Eigen::VectorXd &shape = training[size_t(i)].shape;
        const Similarity pose = alignSimilarity(synth.shape(ci), shape);
        auto sharpness = [&](const cv::Mat &frame) {
            const cv::Rect box = cv::Rect(cv::Point(int(shape[2 * scheme23::kMouthLeft]), int(shape[2 * 16 + 1]) - 6),
                                          cv::Point(int(shape[2 * scheme23::kMouthRight]), int(shape[2 * 16 + 1]) + 10));
            cv::Mat grey, lap;
            cv::cvtColor(frame(box), grey, cv::COLOR_BGR2GRAY);
            cv::Laplacian(grey, lap, CV_32F);
            return cv::mean(lap.mul(lap))[0];
        };
        cv::Mat plain = image.clone(), withDetail = image.clone();
        synth.composite(ci, pose, plain, {FaceRegion::Lower, true, false});
        synth.composite(ci, pose, withDetail, {FaceRegion::Lower, true, true});
        qInfo("mouth sharpness: recording %.1f, with detail %.1f, without %.1f", sharpness(image),
              sharpness(withDetail), sharpness(plain));
        QVERIFY2(std::abs(sharpness(withDetail) - sharpness(image)) < 0.25 * std::abs(sharpness(plain) - sharpness(image)),
                 qPrintable(QString("%1 vs %2 (recording %3)").arg(sharpness(withDetail)).arg(sharpness(plain)).arg(sharpness(image))));

        // Fewer exemplars than images: a farthest-point subset of distinct images.
        Feedback feedback;
        AamBuildOptions options;
        options.maxExemplars = 5;
        const AamModel few = buildAam(gridExamples(false), options, feedback);
        QCOMPARE(few.exemplarCount(), 5);
        for (int a = 0; a < 5; ++a)
            for (int b = a + 1; b < 5; ++b)
                QVERIFY((few.exemplarParams.col(a) - few.exemplarParams.col(b)).norm() > 1e-6);
        options.maxExemplars = 0;
        QCOMPARE(buildAam(gridExamples(false), options, feedback).exemplarCount(), 0);
    }

    void lowerFaceKeepsTheEyesAndMatchesTheColour()
    {
        const AamFitter fitter(m_model);
        const auto held = gridExamples(true);
        const cv::Mat image = cv::imread(held.front().imagePath);
        const AamFitResult fit = fitter.fit(image, held.front().shape);
        const Eigen::VectorXd c = fitter.features(image, fit);
        const AamSynthesizer synth(m_model);
        const auto pixel = [](const Eigen::VectorXd &shape, int point) {
            return cv::Point(int(std::lround(shape[2 * point])), int(std::lround(shape[2 * point + 1])));
        };
        // The mesh's upper edge runs through the eyes: below them it is fully the model's.
        const cv::Point eye = pixel(fit.shape, 3); // left eye, bottom
        const cv::Point lip = pixel(fit.shape, 16);                          // inner lip, top

        // The synthesised share: none at the eyes, all at the lips, for the lower face; the
        // whole face otherwise.
        const cv::Mat lower = synth.compositeWeight(c, fit.pose, image.size(), FaceRegion::Lower);
        const cv::Mat full = synth.compositeWeight(c, fit.pose, image.size(), FaceRegion::Full);
        QCOMPARE(lower.at<float>(eye), 0.f);
        QVERIFY(full.at<float>(eye) > 0.5f);
        QVERIFY(lower.at<float>(lip) > 0.99f);
        double minWeight = 0, maxWeight = 0;
        cv::minMaxLoc(lower, &minWeight, &maxWeight);
        QVERIFY(minWeight >= 0.0 && maxWeight <= 1.0);

        // Composited by default: the eye's pixels are the recording's, the lips are drawn.
        cv::Mat composite = image.clone();
        synth.composite(c, fit.pose, composite);
        QCOMPARE(composite.at<cv::Vec3b>(eye), image.at<cv::Vec3b>(eye));
        cv::Mat fullFace = image.clone();
        synth.composite(c, fit.pose, fullFace, {FaceRegion::Full, true});
        QVERIFY(fullFace.at<cv::Vec3b>(eye) != image.at<cv::Vec3b>(eye));

        // Colour matching follows the frame's lighting: in a frame 30 levels brighter the drawn
        // mouth is about 30 levels brighter too; without matching it stays as it was.
        cv::Mat brighter;
        image.convertTo(brighter, -1, 1.0, 30.0);
        const cv::Rect mouth = cv::Rect(pixel(fit.shape, scheme23::kMouthLeft), pixel(fit.shape, scheme23::kMouthRight))
                               + cv::Size(1, 1);
        const cv::Rect box(mouth.x, lip.y - 4, std::max(4, mouth.width), 8);
        auto drawn = [&](const cv::Mat &background, bool match) {
            cv::Mat frame = background.clone();
            synth.composite(c, fit.pose, frame, {FaceRegion::Lower, match});
            return cv::mean(frame(box));
        };
        const cv::Scalar base = drawn(image, true), lit = drawn(brighter, true), unmatched = drawn(brighter, false);
        for (int ch = 0; ch < 3; ++ch) {
            QVERIFY2(std::abs(lit[ch] - base[ch] - 30.0) < 6.0, qPrintable(QString::number(lit[ch] - base[ch])));
            QVERIFY2(std::abs(unmatched[ch] - drawn(image, false)[ch]) < 1.0, qPrintable(QString::number(ch)));
        }
    }

    void tracksAVideoWithFixedPoints()
    {
        FaceDetector detector(FaceDetectorPaths::boxesOnly());
        const std::string clip = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
        Feedback feedback;
        const VideoTrackingResult plain = trackVideo(m_model, clip, detector, feedback);
        QCOMPARE(int(plain.features.rows()), 75);
        QCOMPARE(int(plain.features.cols()), m_model.combinedModes());
        QVERIFY(plain.framesWithoutFace.empty());
        QVERIFY(plain.errors.allFinite());
        QVERIFY(plain.errors.maxCoeff() < 0.1);
        const std::vector<int> worst = plain.worstFrames(3);
        QCOMPARE(int(worst.size()), 3);
        QVERIFY(plain.errors[worst[0]] >= plain.errors[worst[1]]);
        QVERIFY(plain.errors[worst[1]] >= plain.errors[worst[2]]);
        // A user fixed the chin 5 pixels lower in frame 30: the track keeps it there.
        Eigen::VectorXd corrected = plain.shapes.row(30).transpose();
        corrected[41] += 5.0;
        LandmarkSet set = landmarkSetFromShape(corrected, PointState::Automatic);
        set.points[20].state = PointState::Fixed;
        const VideoTrackingResult fixed = trackVideo(m_model, clip, detector, feedback, {{30, set}});
        QVERIFY(std::abs(fixed.shapes(30, 40) - corrected[40]) < 1e-9);
        QVERIFY(std::abs(fixed.shapes(30, 41) - corrected[41]) < 1e-9);
        QVERIFY((fixed.features.row(30) - plain.features.row(30)).norm() > 1e-6);
    }

    void badInput()
    {
        Feedback feedback;
        auto examples = gridExamples(false);
        // Fewer than 3 usable images.
        std::vector<AamTrainingExample> two(examples.begin(), examples.begin() + 2);
        QVERIFY_THROWS_EXCEPTION(Error, buildAam(two, {}, feedback));
        // Points outside the image and a degenerate shape are skipped with a warning.
        std::vector<AamTrainingExample> some(examples.begin(), examples.begin() + 6);
        some[0].shape[0] = -50;
        some[1].shape = Eigen::VectorXd::Constant(46, 100.0);
        // Images of different sizes are fine.
        some[2].image = cv::imread(some[2].imagePath);
        cv::resize(some[2].image, some[2].image, cv::Size(), 1.5, 1.5);
        some[2].shape = (some[2].shape.array() + 0.5) * 1.5 - 0.5;
        std::vector<std::string> warnings;
        const AamModel m = buildAam(some, {}, feedback, &warnings);
        QCOMPARE(m.trainingImages, 4);
        QCOMPARE(int(warnings.size()), 2);
        QVERIFY(QString::fromStdString(warnings[0]).contains("outside"));
        QVERIFY(QString::fromStdString(warnings[1]).contains("degenerate"));
        // Fewer frames than modes: the model keeps at most n-1 modes.
        QVERIFY(m.shapeModes() <= 3 && m.combinedModes() <= 3);
        // Unreadable directory.
        QVERIFY_THROWS_EXCEPTION(Error, loadTrainingDirectory("/nonexistent/faces"));
        // Cancel.
        feedback.cancel();
        QVERIFY_THROWS_EXCEPTION(Canceled, buildAam(examples, {}, feedback));
    }
};

QTEST_GUILESS_MAIN(TestAam)
#include "tst_aam.moc"
