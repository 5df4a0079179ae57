// A starting point learnt from other speakers for a new person with little footage
// (animation/MouthShapePrior, learnt on a prior project such as GRID s1). Leave one clip of the
// person out: generated from the held-out clip's phones (HMM-mean: per-frame phone means, here
// smoothed over three frames), its inner-lip opening against the tracked one within the speech, for
// the person's own means, the prior alone and the two combined (prior weight: kappa frames). LIPSYNC_BENCH_PRIOR_PROJECT and LIPSYNC_BENCH_PERSON_PROJECT name the two
// projects (tracked and aligned, each with its AAM); skipped without them.
#include "aam/AamModel.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "animation/MouthTrack.h"
#include "eval/RealismMetrics.h"
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

bool speech(int phone)
{
    return phone != PhoneSet::kSilence && phone != PhoneSet::kBreath && phone >= 0;
}

// Pearson's r, 0 where it is undefined (a constant generation: no opening follows the speech).
double correlation(const std::vector<double> &a, const std::vector<double> &b)
{
    const double r = pearsonOverFrames(a, b);
    return std::isfinite(r) ? r : 0.0;
}

void BM_CrossSpeakerPrior(benchmark::State &state)
{
    const QString priorFolder = qEnvironmentVariable("LIPSYNC_BENCH_PRIOR_PROJECT");
    const QString personFolder = qEnvironmentVariable("LIPSYNC_BENCH_PERSON_PROJECT");
    if (priorFolder.isEmpty() || personFolder.isEmpty()) {
        state.SkipWithError("LIPSYNC_BENCH_PRIOR_PROJECT and LIPSYNC_BENCH_PERSON_PROJECT not set");
        return;
    }
    const double kappa = double(state.range(0));
    const auto prior = loadSpeaker(priorFolder);
    const auto person = loadSpeaker(personFolder);
    const MouthShapePrior mouths = MouthShapePrior::learn(prior->tracks);
    double own = 0, priorOnly = 0, combined = 0;
    const int clips = int(person->tracks.size());
    for (auto _ : state) {
        for (int held = 0; held < clips; ++held) {
            std::vector<MouthTrack> training = person->tracks;
            training.erase(training.begin() + held);
            const MouthTrack &track = person->tracks[size_t(held)];
            int first = -1, last = -1;
            for (int f = 0; f < track.frameCount(); ++f)
                if (speech(track.phones[size_t(f)])) {
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

} // namespace
