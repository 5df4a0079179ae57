#include "align/AlignerTrainer.h"

#include "align/BaumWelch.h"
#include "align/PhoneSet.h"
#include "align/UtteranceGraph.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QtConcurrent/QtConcurrentMap>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <numeric>

namespace lipsync {

AcousticModel AlignerTrainer::flatStart(const std::vector<TrainingUtterance> &utterances,
                                        const TrainerOptions &options)
{
    Eigen::VectorXd sum, sumSquares;
    long long frames = 0;
    for (const TrainingUtterance &u : utterances) {
        if (u.features.rows() == 0)
            continue;
        if (sum.size() == 0) {
            sum = Eigen::VectorXd::Zero(u.features.cols());
            sumSquares = Eigen::VectorXd::Zero(u.features.cols());
        }
        const Eigen::MatrixXd f = u.features.cast<double>();
        sum += f.colwise().sum().transpose();
        sumSquares += f.array().square().colwise().sum().matrix().transpose();
        frames += f.rows();
    }
    if (frames < 2)
        throw Error("no audio frames to train the aligner on");
    const Eigen::VectorXd mean = sum / double(frames);
    const Eigen::VectorXd variance = (sumSquares / double(frames) - mean.cwiseAbs2()).cwiseMax(1e-6);
    return AcousticModel(options.features, options.meanNormalize, mean.cast<float>(), variance.cast<float>());
}

double AlignerTrainer::reestimate(AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                  const TrainerOptions &options, std::vector<std::string> *failed,
                                  std::vector<double> *occupancy)
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
            const UtteranceGraph graph(u.pronunciations);
            const double logP = accumulateUtterance(model, graph, u.features, options.beam, partial[size_t(chunk)]);
            if (!(logP > -INFINITY)) {
                std::lock_guard lock(failedMutex);
                failedIndices.push_back(i);
            }
        }
    };
    if (workers == 1)
        work(0);
    else
        QtConcurrent::blockingMap(chunks, work);
    Accumulators total(model);
    for (const Accumulators &a : partial)
        total.add(a);
    if (failed) {
        std::sort(failedIndices.begin(), failedIndices.end());
        for (size_t i : failedIndices)
            failed->push_back(utterances[i].id);
    }
    if (total.frames == 0)
        throw Error("no utterance could be aligned to its transcript");

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
