// Face benchmarks (targets: docs/performance.md):
//  - BM_TrackFrame: AAM tracking of GRID frames (360x288) with the person-specific model built from
//    the 20 committed GRID s1 frames; target >= 200 frames/s per core. Counter nme_vs_dlib: mean NME
//    of the tracked 23 points against dlib's 68->23 points on the same frames (target <= 0.05).
//  - BM_Synthesis: parameters -> composited 360x288 frame; target >= 300 frames/s.
//  - BM_HelenGeneric: generic AAM built from ../shared/data/landmarks/helen-train, fitted to
//    helen-test from the YuNet initialisation; counter nme_mean (target <= 0.05). Skipped when the
//    shared data is absent.
#include "aam/AamBuilder.h"
#include "aam/AamFitter.h"
#include "aam/AamSynthesizer.h"
#include "aam/FaceDetector.h"
#include "aam/FaceTracker.h"
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"

#include <benchmark/benchmark.h>

#include <QDir>
#include <QFileInfo>

#include <opencv2/imgcodecs.hpp>

#include <algorithm>
#include <memory>

using namespace lipsync;

namespace {

const AamModel &gridModel()
{
    static const AamModel model = [] {
        Feedback feedback;
        FaceDetector detector(FaceDetectorPaths::boxesOnly());
        AamBuildOptions options;
        options.combinedVariance = 0.98;
        options.detector = &detector;
        return buildAam(loadTrainingDirectory(LIPSYNC_TEST_DATA "/faces/grid"), options, feedback);
    }();
    return model;
}

std::vector<cv::Mat> demoFrames(const std::string &clip)
{
    VideoReader video(std::string(LIPSYNC_SOURCE_DIR "/resources/demo/media/") + clip + ".mpg");
    std::vector<cv::Mat> frames;
    for (int i = 0; i < video.frameCount(); ++i)
        frames.push_back(video.frame(i).clone());
    return frames;
}

const std::vector<std::string> kClips{"bbaf2n", "bgin3a", "bwbg8n", "lbwy6n", "lrik4p",
                                      "pbav2n", "pgwe6n", "pwbk1s", "sbwo1s", "srbu6n"};

void BM_TrackFrame(benchmark::State &state)
{
    const AamModel &model = gridModel();
    FaceDetectorPaths paths;
    FaceDetector detector(paths);
    const std::vector<cv::Mat> frames = demoFrames(kClips[size_t(state.range(0))]);
    // dlib's points for every frame, the reference for the accuracy counter.
    std::vector<Eigen::VectorXd> reference;
    for (const auto &f : frames) {
        const auto faces = detector.detect(f);
        Eigen::VectorXd r;
        if (!faces.empty()) {
            const Eigen::VectorXd ibug = detector.dlibLandmarks(f, faces.front());
            if (ibug.size() == 136)
                r = mapIbug68To23(ibug);
        }
        reference.push_back(r);
    }
    double nmeSum = 0.0;
    int nmeCount = 0;
    int64_t processed = 0;
    for (auto _ : state) {
        state.PauseTiming();
        FaceTracker tracker(model, &detector);
        // The first frame's detection is not tracking: initialise outside the timed loop.
        tracker.track(frames.front());
        state.ResumeTiming();
        for (size_t i = 1; i < frames.size(); ++i) {
            const TrackedFrame t = tracker.track(frames[i]);
            benchmark::DoNotOptimize(t.features.data());
            if (reference[i].size() && t.found) {
                nmeSum += normalisedMeanError(t.fit.shape, reference[i]);
                ++nmeCount;
            }
        }
        processed += int64_t(frames.size() - 1);
    }
    state.SetItemsProcessed(processed);
    state.counters["nme_vs_dlib"] = nmeCount ? nmeSum / nmeCount : -1.0;
}
BENCHMARK(BM_TrackFrame)->DenseRange(0, 9)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_Synthesis(benchmark::State &state)
{
    const AamModel &model = gridModel();
    const AamSynthesizer synth(model);
    const std::vector<cv::Mat> frames = demoFrames("bbaf2n");
    Similarity pose;
    pose.a = model.referenceScale;
    pose.tx = 180;
    pose.ty = 150;
    Eigen::VectorXd c = Eigen::VectorXd::Zero(model.combinedModes());
    cv::Mat frame;
    int i = 0;
    for (auto _ : state) {
        frames[size_t(i % int(frames.size()))].copyTo(frame);
        c[0] = 0.02 * std::sin(0.3 * i);
        synth.composite(c, pose, frame);
        benchmark::DoNotOptimize(frame.data);
        ++i;
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Synthesis);

// One committed GRID frame with its hand-placed 23 points.
struct AnnotatedFrame
{
    cv::Mat image;
    Eigen::VectorXd shape;
};
AnnotatedFrame annotatedFrame()
{
    const std::string stem = LIPSYNC_TEST_DATA "/faces/grid/bbaf3s_22";
    return {cv::imread(stem + ".jpg"), readFaceShape(stem + ".pts")};
}

// The piecewise-affine warp alone: colour texture of a 360x288 frame sampled under a 23-point
// shape into the level-0 reference frame (what texture extraction and features() do per frame).
void BM_AamWarp(benchmark::State &state)
{
    const AamModel &model = gridModel();
    const AnnotatedFrame f = annotatedFrame();
    const PiecewiseAffineWarp &warp = model.warp(0);
    std::vector<float> texture(size_t(3 * warp.pixelCount()));
    for (auto _ : state) {
        warp.sampleColour(f.image, f.shape, texture.data());
        benchmark::DoNotOptimize(texture.data());
    }
    state.SetItemsProcessed(state.iterations());
    state.counters["pixels"] = warp.pixelCount();
}
BENCHMARK(BM_AamWarp)->Unit(benchmark::kMicrosecond);

// One AAM fit (all levels) from the hand-placed shape moved 4 px right and 3 px down: the
// inverse-compositional search a tracker runs per frame, without the detector.
void BM_AamFit(benchmark::State &state)
{
    const AamModel &model = gridModel();
    const AamFitter fitter(model);
    const AnnotatedFrame f = annotatedFrame();
    Eigen::VectorXd start = f.shape;
    for (Eigen::Index i = 0; i < start.size(); i += 2) {
        start[i] += 4.0;
        start[i + 1] += 3.0;
    }
    AamFitResult result;
    for (auto _ : state)
        benchmark::DoNotOptimize(result = fitter.fit(f.image, start));
    state.SetItemsProcessed(state.iterations());
    state.counters["fit_iterations"] = result.iterations;
    state.counters["nme_vs_hand"] = normalisedMeanError(result.shape, f.shape);
}
BENCHMARK(BM_AamFit)->Unit(benchmark::kMillisecond);

void BM_HelenGeneric(benchmark::State &state)
{
    const QString train = QStringLiteral(LIPSYNC_SOURCE_DIR "/../shared/data/landmarks/helen-train");
    const QString test = QStringLiteral(LIPSYNC_SOURCE_DIR "/../shared/data/landmarks/helen-test");
    if (!QFileInfo::exists(train) || !QFileInfo::exists(test)) {
        state.SkipWithError("../shared/data/landmarks/helen-* not present");
        return;
    }
    Feedback feedback;
    FaceDetector detector(FaceDetectorPaths::boxesOnly());
    // The generic settings and fit chosen by cross-validation on helen-train (docs/performance.md).
    AamBuildOptions options = AamBuildOptions::generic();
    options.detector = &detector;
    const AamModel model = buildAam(loadTrainingDirectory(train.toStdString()), options, feedback);
    const AamFitter fitter(model);
    AamFitOptions fitOptions;
    fitOptions.algorithm = AamFitAlgorithm::Wiberg;
    fitOptions.multiStart = true;
    std::vector<AamTrainingExample> tests = loadTrainingDirectory(test.toStdString());
    std::vector<cv::Mat> images;
    std::vector<Eigen::VectorXd> starts;
    for (auto &e : tests) {
        images.push_back(cv::imread(e.imagePath));
        const auto faces = detector.detect(images.back());
        starts.push_back(faces.empty() ? Eigen::VectorXd() : initialShapeFromDetection(model, faces.front()));
    }
    std::vector<double> nmes;
    for (auto _ : state) {
        nmes.clear();
        for (size_t i = 0; i < tests.size(); ++i) {
            if (starts[i].size() == 0)
                continue;
            const AamFitResult fit = fitter.fit(images[i], starts[i], fitOptions);
            nmes.push_back(normalisedMeanError(fit.shape, tests[i].shape));
        }
    }
    std::sort(nmes.begin(), nmes.end());
    double sum = 0;
    for (double v : nmes)
        sum += v;
    state.counters["images"] = double(nmes.size());
    state.counters["nme_mean"] = nmes.empty() ? -1 : sum / double(nmes.size());
    state.counters["nme_median"] = nmes.empty() ? -1 : nmes[nmes.size() / 2];
    state.SetItemsProcessed(int64_t(state.iterations()) * int64_t(nmes.size()));
}
BENCHMARK(BM_HelenGeneric)->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
