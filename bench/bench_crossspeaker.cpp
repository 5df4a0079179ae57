// A starting point learnt from other speakers for a new person with little footage
// (animation/MouthShapePrior, learnt on a prior project such as GRID s1). Leave one clip of the
// person out: generated from the held-out clip's phones (HMM-mean: per-frame phone means, here
// smoothed over three frames), its inner-lip opening against the tracked one within the speech, for
// the person's own means, the prior alone and the two combined (prior weight: kappa frames). The same
// for the studio's default Brand (phones in context, variance compensation, covariance by
// cross-validation) trained on the other clips with and without the prior's shift
// (ModelOptions::meanShift). LIPSYNC_BENCH_PRIOR_PROJECT and LIPSYNC_BENCH_PERSON_PROJECT name the
// two projects (tracked and aligned, each with its AAM); skipped without them.
#include "aam/AamModel.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "animation/MouthTrack.h"
#include "dynamics/LabelledFolder.h"
#include "dynamics/ModelFile.h"
#include "eval/RealismMetrics.h"
#include "tasks/Feedback.h"
#include "project/Project.h"
#include "util/PhoneSet.h"

#include <benchmark/benchmark.h>

#include <QtGlobal>

#include <Eigen/Dense>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

using namespace lipsync;

namespace {

struct Speaker
{
    Project project;
    std::unique_ptr<AamModel> aam;
    std::unique_ptr<MouthMeasurer> measurer;
    std::vector<MouthTrack> tracks;
};

std::unique_ptr<Speaker> loadSpeaker(const QString &folder)
{
    auto s = std::make_unique<Speaker>();
    s->project = Project::load(folder.toStdString());
    s->aam = std::make_unique<AamModel>(AamModel::load(s->project.aamPath()));
    s->measurer = std::make_unique<MouthMeasurer>(*s->aam);
    s->tracks = projectMouthTracks(*s->measurer, s->project);
    return s;
}

// Pearson's r, 0 where it is undefined (a constant generation: no opening follows the speech).
double correlation(const std::vector<double> &a, const std::vector<double> &b)
{
    const double r = pearsonOverFrames(a, b);
    return std::isfinite(r) ? r : 0.0;
}

// The person of LIPSYNC_BENCH_PERSON_PROJECT and the mouths learnt on LIPSYNC_BENCH_PRIOR_PROJECT's
// speakers; null (the benchmark skipped) without them.
struct PriorAndPerson
{
    std::unique_ptr<Speaker> person;
    MouthShapePrior mouths;
};
std::unique_ptr<PriorAndPerson> loadPriorAndPerson(benchmark::State &state)
{
    const QString priorFolder = qEnvironmentVariable("LIPSYNC_BENCH_PRIOR_PROJECT");
    const QString personFolder = qEnvironmentVariable("LIPSYNC_BENCH_PERSON_PROJECT");
    if (priorFolder.isEmpty() || personFolder.isEmpty()) {
        state.SkipWithError("LIPSYNC_BENCH_PRIOR_PROJECT and LIPSYNC_BENCH_PERSON_PROJECT not set");
        return nullptr;
    }
    auto out = std::make_unique<PriorAndPerson>();
    out->mouths = MouthShapePrior::learn(loadSpeaker(priorFolder)->tracks);
    out->person = loadSpeaker(personFolder);
    return out;
}

void BM_CrossSpeakerPrior(benchmark::State &state)
{
    const std::unique_ptr<PriorAndPerson> loaded = loadPriorAndPerson(state);
    if (!loaded)
        return;
    const double kappa = double(state.range(0));
    const auto &person = loaded->person;
    const MouthShapePrior &mouths = loaded->mouths;
    double own = 0, priorOnly = 0, combined = 0;
    const int clips = int(person->tracks.size());
    for (auto _ : state) {
        for (int held = 0; held < clips; ++held) {
            std::vector<MouthTrack> training = person->tracks;
            training.erase(training.begin() + held);
            const MouthTrack &track = person->tracks[size_t(held)];
            int first = -1, last = -1;
            for (int f = 0; f < track.frameCount(); ++f)
                if (PhoneSet::isSpeech(track.phones[size_t(f)])) {
                    first = first < 0 ? f : first;
                    last = f;
                }
            if (first < 0)
                continue;
            std::vector<double> recorded;
            for (int f = first; f <= last; ++f)
                recorded.push_back(track.measures[size_t(f)].opening);
            double r3[3];
            const double weights[3] = {0.0, 1e12, kappa}; // person only, prior alone, both
            for (int mode = 0; mode < 3; ++mode) {
                const Eigen::MatrixXd means = mouths.personMeans(training, weights[mode]);
                // HMM-mean's generation: each frame its phone's mean, smoothed over three frames.
                std::vector<double> opening;
                for (int f = first; f <= last; ++f) {
                    Eigen::VectorXd c = Eigen::VectorXd::Zero(means.cols());
                    for (int g = std::max(0, f - 1); g <= std::min(track.frameCount() - 1, f + 1); ++g)
                        c += means.row(std::max(0, track.phones[size_t(g)])).transpose();
                    opening.push_back(person->measurer->measure(c / double(std::min(track.frameCount() - 1, f + 1) - std::max(0, f - 1) + 1)).opening);
                }
                r3[mode] = correlation(opening, recorded);
            }
            own += r3[0] / clips;
            priorOnly += r3[1] / clips;
            combined += r3[2] / clips;
            std::printf("  held out %s: person-only %.3f, prior %.3f, MAP %.3f\n", track.sequenceId.c_str(), r3[0], r3[1],
                        r3[2]);
        }
    }
    state.counters["person_only"] = own;
    state.counters["prior"] = priorOnly;
    state.counters["map"] = combined;
    std::printf("cross-speaker prior (kappa %.0f frames), %d clips left out in turn: within-speech opening correlation "
                "person-only %.3f, prior %.3f, MAP %.3f\n",
                kappa, clips, own, priorOnly, combined);
}
BENCHMARK(BM_CrossSpeakerPrior)->Arg(5)->Arg(20)->Arg(80)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void BM_CrossSpeakerPriorBrand(benchmark::State &state)
{
    const std::unique_ptr<PriorAndPerson> loaded = loadPriorAndPerson(state);
    if (!loaded)
        return;
    const Speaker &person = *loaded->person;
    const std::vector<LabelledSequence> sequences = loadProjectSequences(person.project);
    ModelOptions options;
    options.brand.covariance = BrandCovariance::CrossValidated;
    options.compensateVariance = true;
    options.contextStates = true;
    double sums[3] = {0, 0, 0};
    int counted = 0;
    for (auto _ : state) {
        for (size_t held = 0; held < sequences.size(); ++held) {
            std::vector<LabelledSequence> training = sequences;
            training.erase(training.begin() + std::ptrdiff_t(held));
            const LabelledSequence &test = sequences[held];
            std::vector<double> recorded;
            std::vector<int> frames;
            for (int f = 0; f < test.frameCount(); ++f)
                if (PhoneSet::isSpeech(test.labels[size_t(f)])) {
                    frames.push_back(f);
                    recorded.push_back(person.measurer->measure(test.features.row(f).transpose()).opening);
                }
            if (frames.empty())
                continue;
            double r3[3];
            const double weights[3] = {0.0, 1e12, double(state.range(0))}; // person only, prior alone, both
            for (int mode = 0; mode < 3; ++mode) {
                ModelOptions own = options;
                if (mode > 0)
                    own.meanShift = projectPriorShift(loaded->mouths, *person.measurer, person.project, training, weights[mode]);
                const std::unique_ptr<DynamicModel> model = createDynamicModel(ModelKind::Brand, own);
                Feedback quiet;
                model->train(training, quiet);
                const Eigen::MatrixXd generated = model->generate(test.labels);
                std::vector<double> opening;
                for (int f : frames)
                    opening.push_back(person.measurer->measure(generated.row(f).transpose()).opening);
                r3[mode] = correlation(opening, recorded);
                sums[mode] += r3[mode];
            }
            ++counted;
            std::printf("  held out %s: person-only %.3f, prior %.3f, MAP %.3f\n", test.name.c_str(), r3[0], r3[1], r3[2]);
        }
    }
    const double n = std::max(1, counted);
    state.counters["person_only"] = sums[0] / n;
    state.counters["prior"] = sums[1] / n;
    state.counters["map"] = sums[2] / n;
    std::printf("cross-speaker prior, Brand (kappa %.0f frames), %d clips left out in turn: within-speech opening "
                "correlation person-only %.3f, prior %.3f, MAP %.3f\n",
                double(state.range(0)), counted, sums[0] / n, sums[1] / n, sums[2] / n);
}
BENCHMARK(BM_CrossSpeakerPriorBrand)->Arg(80)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

} // namespace
