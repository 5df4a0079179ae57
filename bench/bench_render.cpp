// Rendering speed (targets: rendering >= 300 frames/s at 360x288; a 3 s clip exported well under a
// second). The demo AAM and clip bbaf2n; an HMM-mean model trained once on the demo project's
// features generates the parameters.
//  - BM_RenderFrame: one generated face synthesised and composited into the clip's frame (the
//    background copy included), the renderer's per-frame work.
//  - BM_ExportRenderedClip: render + H.264/AAC encode + mux of the 3 s clip (generation and
//    tracking done once before).
//  - BM_SpeechToVideo: `lipsync render` end to end: align, generate, track, render, encode.
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "project/Project.h"
#include "render/FaceRenderer.h"
#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"

#include <benchmark/benchmark.h>

#include <QTemporaryDir>

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

} // namespace
