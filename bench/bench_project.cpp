// Saving a project the size of the GRID s1 corpus: the demo's ten tracked sequences repeated to
// 400 (75 frames of 32 features each), saved once into a temporary folder; each iteration saves
// it again, as the studio's autosave and Save do, with no features changed (arg 0) or one
// sequence's changed (arg 1). Features unchanged on disk are compared in memory and not written.
#include "project/Project.h"

#include <benchmark/benchmark.h>

#include <QTemporaryDir>

#include <filesystem>

namespace {

lipsync::Project corpusSizedProject()
{
    const std::string demo = LIPSYNC_SOURCE_DIR "/resources/demo";
    const lipsync::Project source = lipsync::Project::load(demo);
    lipsync::Project project = source;
    project.sequences.clear();
    for (int copy = 0; project.sequences.size() < 400; ++copy)
        for (lipsync::Sequence s : source.sequences) {
            s.id += "_" + std::to_string(copy);
            s.mediaFile = std::filesystem::absolute(std::filesystem::path(demo) / s.mediaFile).string();
            project.sequences.push_back(std::move(s));
        }
    return project;
}

void BM_ProjectSave(benchmark::State &state)
{
    lipsync::Project project = corpusSizedProject();
    QTemporaryDir dir;
    const std::string folder = dir.path().toStdString();
    project.save(folder);
    const bool change = state.range(0) != 0;
    int step = 0;
    for (auto _ : state) {
        if (change)
            project.sequences[size_t(step++ % 400)].features(0, 0) += 1e-3;
        project.save(folder);
    }
    state.counters["sequences"] = double(project.sequences.size());
}

} // namespace

BENCHMARK(BM_ProjectSave)->ArgName("changed")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
