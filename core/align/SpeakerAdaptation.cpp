#include "align/SpeakerAdaptation.h"

#include "align/BaumWelch.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <Eigen/Cholesky>

#include <array>
#include <cmath>
#include <string>

namespace lipsync {

int SpeakerAdaptation::regressionClass(int phone)
{
    if (phone == PhoneSet::kSilence || phone == PhoneSet::kBreath)
        return 0;
    static constexpr std::array<std::string_view, 15> kVowels{"AA", "AE", "AH", "AO", "AW", "AY", "EH", "ER",
                                                              "EY", "IH", "IY", "OW", "OY", "UH", "UW"};
    const std::string label = PhoneSet::label(phone);
    for (std::string_view v : kVowels)
        if (label == v)
            return 1;
    return 2;
}

namespace {

// MLLR statistics of one regression class for one block of coefficients [first, first + n):
// per row i, G_i = sum_m gamma_m / var_mi xi_m xi_m^T and k_i = sum_m sum_t gamma_m(t) o_ti / var_mi xi_m,
// with the extended mean xi_m = (1, mu_m[first..first+n)).
struct BlockStatistics
{
    std::vector<Eigen::MatrixXd> g;
    std::vector<Eigen::VectorXd> k;
    double frames = 0;

    explicit BlockStatistics(int n) : g(size_t(n), Eigen::MatrixXd::Zero(n + 1, n + 1)), k(size_t(n), Eigen::VectorXd::Zero(n + 1)) {}
    void add(const BlockStatistics &o)
    {
        for (size_t i = 0; i < g.size(); ++i) {
            g[i] += o.g[i];
            k[i] += o.k[i];
        }
        frames += o.frames;
    }
};

// The transform's rows for one block, W (n x n+1): mu'_block = W (1, mu_block). Rows whose
// statistics are singular stay the identity.
Eigen::MatrixXd solveBlock(const BlockStatistics &s)
{
    const int n = int(s.g.size());
    Eigen::MatrixXd w = Eigen::MatrixXd::Zero(n, n + 1);
    for (int i = 0; i < n; ++i) {
        Eigen::VectorXd identity = Eigen::VectorXd::Zero(n + 1);
        identity[i + 1] = 1.0;
        // A small ridge towards the identity keeps rows with little data well posed.
        const double ridge = 1e-4 * s.g[size_t(i)].diagonal().mean() + 1e-8;
        const Eigen::MatrixXd g = s.g[size_t(i)] + ridge * Eigen::MatrixXd::Identity(n + 1, n + 1);
        const Eigen::VectorXd k = s.k[size_t(i)] + ridge * identity;
        const Eigen::LDLT<Eigen::MatrixXd> ldlt(g);
        const Eigen::VectorXd row = ldlt.solve(k);
        const bool solved = ldlt.info() == Eigen::Success && row.allFinite();
        w.row(i) = (solved ? row : identity).transpose();
    }
    return w;
}

} // namespace

AcousticModel SpeakerAdaptation::transform(const AcousticModel &si, const Accumulators &statistics,
                                           const AdaptationOptions &options)
{
    const int d = si.dimension();
    // Block-diagonal over static / delta / acceleration coefficients when the layout is the
    // HTK one (each block a third); one full block otherwise.
    const int blockSize = d % 3 == 0 ? d / 3 : d;
    const int blocks = d / blockSize;
    const std::vector<BlockStatistics> empty(size_t(blocks), BlockStatistics{blockSize});
    std::vector<std::vector<BlockStatistics>> perClass(size_t(kClasses), empty);
    for (int j = 0; j < si.stateCount(); ++j) {
        const StateAccumulator &acc = statistics.states[size_t(j)];
        if (acc.occupancy <= 0)
            continue;
        const GaussianMixture &g = si.state(j);
        const int c = regressionClass(j / AcousticModel::kStatesPerPhone);
        for (int m = 0; m < g.size() && m < acc.componentOccupancy.size(); ++m) {
            const double occ = acc.componentOccupancy[m];
            if (occ <= 1e-6)
                continue;
            for (int b = 0; b < blocks; ++b) {
                BlockStatistics &s = perClass[size_t(c)][size_t(b)];
                Eigen::VectorXd xi(blockSize + 1);
                xi[0] = 1.0;
                for (int k = 0; k < blockSize; ++k)
                    xi[k + 1] = g.means(m, b * blockSize + k);
                const Eigen::MatrixXd outer = xi * xi.transpose();
                for (int i = 0; i < blockSize; ++i) {
                    const double precision = 1.0 / double(g.variances(m, b * blockSize + i));
                    s.g[size_t(i)] += (occ * precision) * outer;
                    s.k[size_t(i)] += (acc.sum(m, b * blockSize + i) * precision) * xi;
                }
                if (b == 0)
                    s.frames += occ;
            }
        }
    }
    // A class with too little data shares the transform of all the data.
    std::vector<BlockStatistics> global = empty;
    for (int c = 0; c < kClasses; ++c)
        for (int b = 0; b < blocks; ++b)
            global[size_t(b)].add(perClass[size_t(c)][size_t(b)]);
    std::vector<Eigen::MatrixXd> globalW(static_cast<size_t>(blocks));
    for (int b = 0; b < blocks; ++b)
        globalW[size_t(b)] = solveBlock(global[size_t(b)]);
    std::vector<std::vector<Eigen::MatrixXd>> classW(static_cast<size_t>(kClasses));
    for (int c = 0; c < kClasses; ++c)
        for (int b = 0; b < blocks; ++b)
            classW[size_t(c)].push_back(perClass[size_t(c)][0].frames >= options.minimumClassFrames
                                            ? solveBlock(perClass[size_t(c)][size_t(b)])
                                            : globalW[size_t(b)]);

    AcousticModel adapted = si;
    for (int j = 0; j < adapted.stateCount(); ++j) {
        GaussianMixture &g = adapted.state(j);
        const StateAccumulator &acc = statistics.states[size_t(j)];
        const int c = regressionClass(j / AcousticModel::kStatesPerPhone);
        for (int m = 0; m < g.size(); ++m) {
            Eigen::VectorXd mean = si.state(j).means.row(m).transpose().cast<double>();
            for (int b = 0; b < blocks; ++b) {
                Eigen::VectorXd xi(blockSize + 1);
                xi[0] = 1.0;
                xi.tail(blockSize) = mean.segment(b * blockSize, blockSize);
                mean.segment(b * blockSize, blockSize) = classW[size_t(c)][size_t(b)] * xi;
            }
            if (options.mapWeight > 0 && m < acc.componentOccupancy.size()) {
                const double occ = acc.componentOccupancy[m];
                mean = (options.mapWeight * mean + acc.sum.row(m).transpose()) / (options.mapWeight + occ);
            }
            g.means.row(m) = mean.cast<float>().transpose();
        }
    }
    adapted.prepare();
    return adapted;
}

AcousticModel SpeakerAdaptation::adapt(const AcousticModel &model, const std::vector<std::vector<Pronunciation>> &pronunciations,
                                       const Eigen::MatrixXf &features, const AdaptationOptions &options,
                                       Feedback *feedback, AdaptationReport *report)
{
    return adapt(model, {TrainingUtterance{{}, features, pronunciations}}, options, feedback, report);
}

AcousticModel SpeakerAdaptation::adapt(const AcousticModel &model, const std::vector<TrainingUtterance> &utterances,
                                       const AdaptationOptions &options, Feedback *feedback, AdaptationReport *report)
{
    std::vector<UtteranceGraph> graphs;
    long long frames = 0;
    for (const TrainingUtterance &u : utterances) {
        graphs.emplace_back(u.pronunciations, options.graph);
        frames += u.features.rows();
        if (double(u.features.rows()) * double(graphs.back().size()) > kMaxForwardCells)
            throw Error("speaker adaptation: the recording" + (u.id.empty() ? std::string() : " " + u.id)
                        + " is too long to adapt to in one piece (split it into shorter utterances)");
    }
    // Statistics of all the utterances under `current`; the log-likelihood per frame.
    auto accumulate = [&](const AcousticModel &current, Accumulators &statistics) {
        double total = 0;
        for (size_t i = 0; i < utterances.size(); ++i) {
            double logP = accumulateUtterance(current, graphs[i], utterances[i].features, options.beam, statistics);
            if (!(logP > -INFINITY))
                logP = accumulateUtterance(current, graphs[i], utterances[i].features, INFINITY, statistics);
            if (!(logP > -INFINITY))
                throw Error("speaker adaptation: the transcript does not fit the audio"
                            + (utterances[i].id.empty() ? std::string() : " of " + utterances[i].id));
            total += logP;
        }
        return total / double(std::max(frames, 1LL));
    };
    AcousticModel current = model;
    for (int pass = 0; pass < options.iterations; ++pass) {
        if (feedback)
            feedback->throwIfCanceled();
        Accumulators statistics(current);
        const double perFrame = accumulate(current, statistics);
        if (report)
            report->logLikelihoodPerFrame.push_back(perFrame);
        current = transform(model, statistics, options);
    }
    if (report && options.iterations > 0) {
        Accumulators statistics(current);
        report->logLikelihoodPerFrame.push_back(accumulate(current, statistics));
    }
    return current;
}

} // namespace lipsync
