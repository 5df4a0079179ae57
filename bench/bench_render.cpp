// Rendering speed (targets: rendering >= 300 frames/s at 360x288; a 3 s clip exported well under a
// second). The demo AAM and clip bbaf2n; an HMM-mean model trained once on the demo project's
// features generates the parameters.
//  - BM_RenderFrame: one generated face synthesised and composited into the clip's frame (the
//    background copy included), the renderer's per-frame work.
//  - BM_ExportRenderedClip: render + H.264/AAC encode + mux of the 3 s clip (generation and
//    tracking done once before).
//  - BM_SpeechToVideo: `lipsync render` end to end: align, generate, track, render, encode.
//  - BM_RenderFrameHD: the same per-frame work at 1280x720 (tests/data/media/hd: an AAM built from
//    the clip's own frames with dlib's points, the face tracked; every frame rendered with another
//    mouth): the recording's lower face warped, the mouth's inside drawn, on one thread.
//  - BM_ExportRenderedHD: the 3.8 s HD clip rendered that way and encoded (H.264 + AAC).
#include "aam/AamBuilder.h"
#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "dynamics/ModelFile.h"
#include "io/VideoReader.h"
#include "dynamics/PhoneLabels.h"
#include "project/Project.h"
#include "render/FaceRenderer.h"
#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"

#include <benchmark/benchmark.h>

#include <QTemporaryDir>

#include <cmath>
#include <ctime>

namespace {

const std::string kDemo = LIPSYNC_SOURCE_DIR "/resources/demo";

struct Setup
{
    QTemporaryDir dir;
    lipsync::SpeechToFaceRequest request;
    lipsync::SpeechToFaceResult generated;
    std::unique_ptr<lipsync::FaceRenderer> renderer;
};

Setup &setup()
{
    static Setup s = [] {
        Setup out;
        const lipsync::Project project = lipsync::Project::load(kDemo);
        std::vector<lipsync::LabelledSequence> sequences;
        for (const lipsync::Sequence &q : project.sequences)
            sequences.push_back({q.id, lipsync::frameLabelsFromTier(q.phones, q.frameRate, int(q.features.rows())),
                                 q.features});
        auto model = lipsync::createDynamicModel("hmm");
        lipsync::Feedback feedback;
        model->train(sequences, feedback);
        out.request.modelPath = out.dir.filePath("demo.model").toStdString();
        lipsync::saveModel(*model, out.request.modelPath, "unspecified");
        out.request.aamPath = kDemo + "/aam/demo.aam";
        out.request.mediaPath = kDemo + "/media/bbaf2n.mpg";
        out.request.transcriptPath = kDemo + "/media/bbaf2n.align";
        out.request.aligner.model = LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner";
        out.generated = lipsync::generateFromSpeech(out.request, feedback);
        out.renderer = lipsync::makeRenderer(out.generated, out.request.mediaPath, feedback);
        return out;
    }();
    return s;
}

void addCpu(benchmark::State &state, std::clock_t start)
{
    state.counters["processCpuMs"] =
        1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC / double(state.iterations());
}

void BM_RenderFrame(benchmark::State &state)
{
    Setup &s = setup();
    const int frames = s.generated.frameCount();
    int i = 0;
    const std::clock_t start = std::clock();
    for (auto _ : state) {
        cv::Mat frame = lipsync::renderFrame(s.generated, *s.renderer, i);
        benchmark::DoNotOptimize(frame.data);
        i = (i + 1) % frames;
    }
    addCpu(state, start);
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderFrame)->Unit(benchmark::kMicrosecond);

void BM_ExportRenderedClip(benchmark::State &state)
{
    Setup &s = setup();
    const std::string path = s.dir.filePath("rendered.mp4").toStdString();
    lipsync::RenderOptions options;
    options.sideBySide = state.range(0) != 0;
    const std::clock_t start = std::clock();
    for (auto _ : state) {
        lipsync::Feedback feedback;
        lipsync::exportRenderedVideo(s.generated, *s.renderer, path, feedback, options);
    }
    addCpu(state, start);
    state.counters["frames"] = s.generated.frameCount();
}
BENCHMARK(BM_ExportRenderedClip)->ArgName("sideBySide")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_SpeechToVideo(benchmark::State &state)
{
    Setup &s = setup();
    const std::string path = s.dir.filePath("speech.mp4").toStdString();
    const std::clock_t start = std::clock();
    for (auto _ : state) {
        lipsync::Feedback feedback;
        lipsync::renderSpeechVideo(s.request, path, feedback);
    }
    addCpu(state, start);
}
BENCHMARK(BM_SpeechToVideo)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(3);

struct HdSetup
{
    lipsync::AamModel aam;
    std::unique_ptr<lipsync::FaceRenderer> renderer;
    Eigen::MatrixXd generated; // the tracked parameters with another mouth
};

HdSetup &hdSetup()
{
    static HdSetup s = [] {
        HdSetup out;
        const std::string clip = LIPSYNC_SOURCE_DIR "/tests/data/media/hd/obama_weekly_address_library.mp4";
        lipsync::FaceDetector detector;
        lipsync::VideoReader video(clip);
        std::vector<lipsync::AamTrainingExample> examples;
        for (int t = 0; t < video.frameCount(); t += 4) {
            const cv::Mat frame = video.frame(t);
            const auto faces = detector.detect(frame);
            if (faces.empty())
                continue;
            const Eigen::VectorXd ibug = detector.dlibLandmarks(frame, faces.front());
            if (ibug.size() == 136)
                examples.push_back({"frame" + std::to_string(t), {}, frame, lipsync::mapIbug68To23(ibug)});
        }
        lipsync::Feedback feedback;
        out.aam = lipsync::buildAam(examples, {}, feedback);
        out.renderer = std::make_unique<lipsync::FaceRenderer>(out.aam, clip, feedback);
        out.generated = out.renderer->trackedFeatures();
        out.generated.col(0).array() += 2.0 * std::sqrt(out.aam.combinedVariances[0]);
        return out;
    }();
    return s;
}

void BM_RenderFrameHD(benchmark::State &state)
{
    HdSetup &s = hdSetup();
    lipsync::CompositeOptions options;
    options.recordedInsides = state.range(0) != 0; // the person's own open mouths, or the AAM's
    s.renderer->setCompositeOptions(options);
    const int frames = int(s.generated.rows());
    int i = 0;
    const std::clock_t start = std::clock();
    for (auto _ : state) {
        cv::Mat frame = s.renderer->render(i, s.generated.row(i).transpose());
        benchmark::DoNotOptimize(frame.data);
        i = (i + 1) % frames;
    }
    addCpu(state, start);
    state.counters["fps"] = benchmark::Counter(double(state.iterations()), benchmark::Counter::kIsRate);
    s.renderer->setCompositeOptions({});
}
BENCHMARK(BM_RenderFrameHD)->ArgName("ownInsides")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_ExportRenderedHD(benchmark::State &state)
{
    HdSetup &s = hdSetup();
    QTemporaryDir dir;
    const std::string path = dir.filePath("hd.mp4").toStdString();
    const int frames = int(s.generated.rows());
    lipsync::VideoExportOptions options;
    options.setFrameRate(30000.0 / 1001.0);
    options.threads = 1;
    const std::clock_t start = std::clock();
    for (auto _ : state) {
        lipsync::Feedback feedback;
        lipsync::exportVideo(path, frames, [&](int i) { return s.renderer->render(i, s.generated.row(i).transpose()); },
                             nullptr, feedback, options);
    }
    addCpu(state, start);
    state.counters["frames"] = frames;
    state.counters["xRealTime"] = benchmark::Counter(frames / (30000.0 / 1001.0) * double(state.iterations()),
                                                     benchmark::Counter::kIsRate);
}
BENCHMARK(BM_ExportRenderedHD)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(2);

} // namespace
