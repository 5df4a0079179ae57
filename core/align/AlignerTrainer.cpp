#include "align/AlignerTrainer.h"

#include "align/BaumWelch.h"
#include "align/ForcedAligner.h"
#include "util/PhoneSet.h"
#include "align/UtteranceGraph.h"
#include "tasks/BlockingMap.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QThread>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>

namespace lipsync {

void FlatStartStatistics::add(const FlatStartStatistics &other)
{
    for (int k = 0; k < 2; ++k) {
        if (other.sum[k].size() == 0)
            continue;
        if (sum[k].size() == 0) {
            sum[k] = other.sum[k];
            sumSquares[k] = other.sumSquares[k];
        } else {
            if (sum[k].size() != other.sum[k].size())
                throw Error("flat-start statistics of features of another dimension");
            sum[k] += other.sum[k];
            sumSquares[k] += other.sumSquares[k];
        }
        frames[k] += other.frames[k];
    }
}

FlatStartStatistics AlignerTrainer::flatStartStatistics(const std::vector<TrainingUtterance> &utterances,
                                                        const TrainerOptions &options)
{
    // HCompV's global mean and variance, with one refinement: the quietest frames of every
    // utterance (by C0, the last static coefficient) seed the silence model and the others the
    // phones. Without it the flat start lets the first and last phones of every transcript
    // absorb the long leading and trailing silences, and re-estimation never recovers.
    const int c0 = options.features.cepstra;
    FlatStartStatistics st;
    for (const TrainingUtterance &u : utterances) {
        if (u.features.rows() == 0)
            continue;
        for (int k = 0; k < 2; ++k)
            if (st.sum[k].size() == 0) {
                st.sum[k] = Eigen::VectorXd::Zero(u.features.cols());
                st.sumSquares[k] = Eigen::VectorXd::Zero(u.features.cols());
            }
        std::vector<float> energy(u.features.col(c0).data(), u.features.col(c0).data() + u.features.rows());
        const size_t quiet = energy.size() * size_t(options.silenceSeedPercent) / 100;
        std::nth_element(energy.begin(), energy.begin() + long(quiet), energy.end());
        const float threshold = energy[quiet];
        for (int t = 0; t < u.features.rows(); ++t) {
            const Eigen::VectorXd x = u.features.row(t).transpose().cast<double>();
            const int k = u.features(t, c0) < threshold ? 1 : 0;
            st.sum[k] += x;
            st.sumSquares[k] += x.cwiseAbs2();
            ++st.frames[k];
        }
    }
    return st;
}

AcousticModel AlignerTrainer::flatStart(const std::vector<TrainingUtterance> &utterances,
                                        const TrainerOptions &options)
{
    return flatStart(flatStartStatistics(utterances, options), options);
}

AcousticModel AlignerTrainer::flatStart(const FlatStartStatistics &st, const TrainerOptions &options)
{
    if (st.frames[0] + st.frames[1] < 2 || st.sum[0].size() == 0)
        throw Error("no audio frames to train the aligner on");
    const double all = double(st.frames[0] + st.frames[1]);
    const Eigen::VectorXd mean = (st.sum[0] + st.sum[1]) / all;
    const Eigen::VectorXd variance = ((st.sumSquares[0] + st.sumSquares[1]) / all - mean.cwiseAbs2()).cwiseMax(1e-6);
    AcousticModel model(options.features, options.normalization, mean.cast<float>(), variance.cast<float>());
    if (mean.size() != model.dimension())
        throw Error("flat-start statistics of " + std::to_string(mean.size()) + " dimensions for features of "
                    + std::to_string(model.dimension()));
    for (int k = 0; k < 2; ++k) {
        if (st.frames[k] < 10)
            continue;
        const Eigen::VectorXd m = st.sum[k] / double(st.frames[k]);
        const Eigen::VectorXd v = (st.sumSquares[k] / double(st.frames[k]) - m.cwiseAbs2()).cwiseMax(0.01 * variance);
        for (int p = 0; p < PhoneSet::kCount; ++p) {
            if ((k == 1) != (p == PhoneSet::kSilence))
                continue;
            for (int s = 0; s < AcousticModel::kStatesPerPhone; ++s) {
                GaussianMixture &g = model.state(AcousticModel::stateIndex(p, s));
                g.means.row(0) = m.cast<float>().transpose();
                g.variances.row(0) = v.cast<float>().transpose();
            }
        }
    }
    model.prepare();
    return model;
}

double AlignerTrainer::reestimate(AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                  const TrainerOptions &options, std::vector<std::string> *failed,
                                  std::vector<double> *occupancy)
{
    const Accumulators total = accumulate(model, utterances, options, failed);
    return update(model, total, options, occupancy);
}

BoundaryCorrection AlignerTrainer::calibrate(const AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                             const BoundaryCorrection::Options &options,
                                             BoundaryCorrectionReport *report)
{
    std::vector<std::vector<BoundaryError>> errors(utterances.size());
    std::vector<size_t> timed;
    for (size_t i = 0; i < utterances.size(); ++i)
        if (!utterances[i].reference.intervals.empty())
            timed.push_back(i);
    const ForcedAligner aligner(model);
    lipsync::blockingMap(timed, [&](size_t i) {
        const TrainingUtterance &u = utterances[i];
        // The transcript's words, as io/Transcript takes them from a timed tier: every interval
        // but the silences (a breath is a word the aligner pronounces).
        std::vector<std::string> words;
        for (const Interval &w : u.reference.intervals)
            if (!PhoneSet::isSilence(w.label))
                words.push_back(w.label);
        if (words.size() != u.pronunciations.size())
            return;
        try {
            const double duration = double(u.features.rows()) * model.featureOptions().shiftSeconds;
            errors[i] = BoundaryCorrection::errors(aligner.align(u.features, words, u.pronunciations, duration),
                                                   u.reference);
        } catch (const Error &) {
            // The transcript does not fit the audio: nothing to learn from it.
        }
    });
    std::vector<std::vector<BoundaryError>> learned;
    for (size_t i : timed)
        learned.push_back(std::move(errors[i]));
    return BoundaryCorrection::learn(learned, options, report);
}

Accumulators AlignerTrainer::accumulate(const AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                        const TrainerOptions &options, std::vector<std::string> *failed)
{
    // Utterances are shared out to one accumulator per worker (QtConcurrent), then summed.
    const int workers = options.parallel ? std::max(1, QThread::idealThreadCount()) : 1;
    std::vector<Accumulators> partial(static_cast<size_t>(workers), Accumulators(model));
    std::vector<int> chunks(static_cast<size_t>(workers));
    std::iota(chunks.begin(), chunks.end(), 0);
    std::mutex failedMutex;
    std::vector<size_t> failedIndices;
    auto work = [&](int chunk) {
        for (size_t i = size_t(chunk); i < utterances.size(); i += size_t(workers)) {
            const TrainingUtterance &u = utterances[i];
            const UtteranceGraph graph(u.pronunciations, options.graph);
            double logP = accumulateUtterance(model, graph, u.features, options.beam, partial[size_t(chunk)]);
            if (!(logP > -INFINITY) && u.features.rows() >= graph.minimumFrames())
                logP = accumulateUtterance(model, graph, u.features, INFINITY, partial[size_t(chunk)]);
            if (!(logP > -INFINITY)) {
                std::lock_guard lock(failedMutex);
                failedIndices.push_back(i);
            }
        }
    };
    if (workers == 1)
        work(0);
    else
        lipsync::blockingMap(chunks, work);
    Accumulators total(model);
    for (const Accumulators &a : partial)
        total.add(a);
    if (failed) {
        std::sort(failedIndices.begin(), failedIndices.end());
        for (size_t i : failedIndices)
            failed->push_back(utterances[i].id);
    }
    return total;
}

double AlignerTrainer::update(AcousticModel &model, const Accumulators &total, const TrainerOptions &options,
                              std::vector<double> *occupancy)
{
    if (total.frames == 0)
        throw Error("no utterance could be aligned to its transcript");
    if (int(total.states.size()) != model.stateCount())
        throw Error("statistics of " + std::to_string(total.states.size()) + " states for a model of "
                    + std::to_string(model.stateCount()));
    for (int j = 0; j < model.stateCount(); ++j) {
        const StateAccumulator &acc = total.states[size_t(j)];
        if (acc.componentOccupancy.size() != model.state(j).size() || acc.sum.cols() != model.dimension())
            throw Error("statistics of another model's mixtures (state " + std::to_string(j) + ")");
    }

    // M-step (HERest): means, variances (floored), weights, self-loops.
    const Eigen::VectorXd floor = model.varianceFloor().cast<double>();
    if (occupancy)
        occupancy->assign(size_t(model.stateCount()), 0.0);
    for (int j = 0; j < model.stateCount(); ++j) {
        const StateAccumulator &acc = total.states[size_t(j)];
        if (occupancy)
            (*occupancy)[size_t(j)] = acc.occupancy;
        if (acc.occupancy < options.minimumStateOccupancy)
            continue; // too little data: keep the state as it is
        GaussianMixture &g = model.state(j);
        model.setSelfLoop(j, std::clamp(acc.selfCount / acc.occupancy, 0.01, 0.99));
        const double componentTotal = acc.componentOccupancy.sum();
        for (int m = 0; m < g.size(); ++m) {
            const double occ = acc.componentOccupancy[m];
            g.weights[m] = float(std::max(occ / componentTotal, 1e-5));
            if (occ < 1.0)
                continue; // a starved component keeps its Gaussian
            const Eigen::VectorXd mean = acc.sum.row(m).transpose() / occ;
            const Eigen::VectorXd var = (acc.sumSquares.row(m).transpose() / occ - mean.cwiseAbs2()).cwiseMax(floor);
            g.means.row(m) = mean.cast<float>().transpose();
            g.variances.row(m) = var.cast<float>().transpose();
        }
        g.weights /= g.weights.sum();
    }
    model.prepare();
    return total.logLikelihood / double(total.frames);
}

void AlignerTrainer::splitMixtures(AcousticModel &model, int mixtures, const std::vector<double> &occupancy,
                                   double minimumPerComponent)
{
    for (int j = 0; j < model.stateCount(); ++j) {
        GaussianMixture &g = model.state(j);
        const double occ = j < int(occupancy.size()) ? occupancy[size_t(j)] : 0.0;
        while (g.size() < mixtures && occ >= minimumPerComponent * (g.size() + 1)) {
            int heaviest = 0;
            g.weights.maxCoeff(&heaviest);
            const int m = g.size();
            const int d = int(g.means.cols());
            g.weights.conservativeResize(m + 1);
            g.means.conservativeResize(m + 1, d);
            g.variances.conservativeResize(m + 1, d);
            const Eigen::RowVectorXf offset = 0.2f * g.variances.row(heaviest).cwiseSqrt();
            g.weights[heaviest] *= 0.5f;
            g.weights[m] = g.weights[heaviest];
            g.means.row(m) = g.means.row(heaviest) - offset;
            g.means.row(heaviest) += offset;
            g.variances.row(m) = g.variances.row(heaviest);
        }
    }
    model.prepare();
}

AcousticModel AlignerTrainer::train(const std::vector<TrainingUtterance> &utterances,
                                    const TrainerOptions &options, Feedback &feedback, TrainingReport *report)
{
    feedback.setStatus("flat start");
    AcousticModel model = flatStart(utterances, options);
    const int dimension = model.dimension();
    for (const TrainingUtterance &u : utterances)
        if (u.features.rows() > 0 && u.features.cols() != dimension)
            throw Error("utterance " + u.id + " has features of another dimension");
    int totalIterations = options.firstStageIterations;
    for (size_t stage = 1; stage < options.mixtureSchedule.size(); ++stage)
        totalIterations += options.iterationsPerStage;
    int iteration = 0;
    std::vector<double> occupancy;
    std::vector<std::string> failed;
    TrainingReport local;
    TrainingReport &r = report ? *report : local;
    r = TrainingReport{};
    r.utterances = int(utterances.size());
    for (const TrainingUtterance &u : utterances)
        r.frames += u.features.rows();
    for (size_t stage = 0; stage < options.mixtureSchedule.size(); ++stage) {
        if (stage > 0)
            splitMixtures(model, options.mixtureSchedule[stage], occupancy,
                          options.minimumMixtureOccupancy * dimension);
        const int iterations = stage == 0 ? options.firstStageIterations : options.iterationsPerStage;
        for (int i = 0; i < iterations; ++i) {
            feedback.throwIfCanceled();
            feedback.setStatus("re-estimation, " + std::to_string(options.mixtureSchedule[stage])
                               + " mixture(s), iteration " + std::to_string(iteration + 1));
            failed.clear();
            const double ll = reestimate(model, utterances, options, &failed, &occupancy);
            r.logLikelihoodPerFrame.push_back(ll);
            feedback.reportIteration(iteration, ll);
            ++iteration;
            feedback.setProgress(double(iteration) / totalIterations);
        }
    }
    r.failedUtterances = failed;
    return model;
}

} // namespace lipsync
