// Export speed (target: a 3 s clip well under a second). The demo GRID clip bbaf2n
// (75 frames 360x288, 44.1 kHz sound) is decoded once; each iteration encodes H.264 + AAC and
// muxes an MP4 into a temporary folder, including the atomic rename. And decoding speed: every
// frame of a clip read in order as BGR (GRID's MPEG-1 and the 720p H.264 of tests/data/media/hd),
// the reader opened once (its timestamp scan cached) and each iteration a full pass.
#include "io/AudioDecoder.h"
#include "io/VideoReader.h"
#include "render/VideoExporter.h"
#include "tasks/Feedback.h"

#include <benchmark/benchmark.h>

#include <QTemporaryDir>

#include <ctime>

namespace {

struct Clip
{
    std::vector<cv::Mat> frames;
    lipsync::AudioBuffer audio;
};

const Clip &demoClip()
{
    static const Clip clip = [] {
        const std::string path = LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg";
        Clip c;
        lipsync::VideoReader reader(path);
        for (int i = 0; i < reader.frameCount(); ++i)
            c.frames.push_back(reader.frame(i));
        c.audio = lipsync::AudioDecoder::decode(path, 0);
        return c;
    }();
    return clip;
}

void BM_ExportMp4ThreeSeconds(benchmark::State &state)
{
    const Clip &clip = demoClip();
    QTemporaryDir dir;
    const std::string path = dir.filePath("bench.mp4").toStdString();
    lipsync::VideoExportOptions options;
    options.threads = int(state.range(0));
    const lipsync::AudioBuffer *audio = state.range(1) ? &clip.audio : nullptr;
    // std::clock() is the CPU time of the whole process (every encoder thread): the wall time an
    // idle machine would need at most, whatever other jobs share the cores.
    const std::clock_t cpuStart = std::clock();
    for (auto _ : state) {
        lipsync::Feedback feedback;
        lipsync::exportVideo(path, int(clip.frames.size()),
                             [&](int i) { return clip.frames[size_t(i)]; }, audio, feedback,
                             options);
    }
    state.counters["processCpuMs"] = 1000.0 * double(std::clock() - cpuStart) / CLOCKS_PER_SEC
                                     / double(state.iterations());
    state.counters["frames"] = double(clip.frames.size());
    state.counters["fps"] = benchmark::Counter(double(clip.frames.size()) * double(state.iterations()),
                                               benchmark::Counter::kIsRate);
}
// Arguments: encoder threads (0 = libx264's choice, 1 = single-threaded); with sound (1) or not.
BENCHMARK(BM_ExportMp4ThreeSeconds)
    ->ArgNames({"threads", "audio"})
    ->Args({0, 1})
    ->Args({1, 1})
    ->Args({1, 0})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

} // namespace

void BM_DecodeVideo(benchmark::State &state)
{
    const std::string path = state.range(0) == 0
                                 ? std::string(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg")
                                 : std::string(LIPSYNC_TEST_DATA "/media/hd/obama_weekly_address_closeup.mp4");
    lipsync::VideoReader reader(path);
    long frames = 0;
    for (auto _ : state) {
        for (int i = 0; i < reader.frameCount(); ++i)
            benchmark::DoNotOptimize(reader.frame(i).data);
        frames += reader.frameCount();
    }
    state.counters["frames/s"] = benchmark::Counter(double(frames), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DecodeVideo)->ArgName("hd")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
