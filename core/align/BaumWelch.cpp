#include "align/BaumWelch.h"

#include "align/EmissionCache.h"

#include <cmath>

namespace lipsync {

Accumulators::Accumulators(const AcousticModel &model)
{
    states.resize(size_t(model.stateCount()));
    for (int j = 0; j < model.stateCount(); ++j) {
        const GaussianMixture &g = model.state(j);
        StateAccumulator &a = states[size_t(j)];
        a.componentOccupancy = Eigen::VectorXd::Zero(g.size());
        a.sum = RowMatrixXd::Zero(g.size(), model.dimension());
        a.sumSquares = RowMatrixXd::Zero(g.size(), model.dimension());
    }
}

void Accumulators::add(const Accumulators &other)
{
    for (size_t j = 0; j < states.size(); ++j) {
        StateAccumulator &a = states[j];
        const StateAccumulator &b = other.states[j];
        a.occupancy += b.occupancy;
        a.selfCount += b.selfCount;
        a.componentOccupancy += b.componentOccupancy;
        a.sum += b.sum;
        a.sumSquares += b.sumSquares;
    }
    logLikelihood += other.logLikelihood;
    frames += other.frames;
    utterances += other.utterances;
}

namespace {

constexpr double kMinGamma = 1e-5;

// The E-step's sums of frame `x` (the features of one frame): each model state's occupancy
// `gamma` and self transitions, and, where it is occupied, each mixture component's share of it
// with the weighted sums of x and x^2. `componentLog` is scratch space.
void accumulateFrame(const AcousticModel &model, const float *x, const std::vector<double> &gammaByModelState,
                     const std::vector<double> &selfByModelState, std::vector<float> &componentLog,
                     Accumulators &out)
{
    const Eigen::RowVectorXd xd = Eigen::Map<const Eigen::RowVectorXf>(x, model.dimension()).cast<double>();
    const Eigen::RowVectorXd xsq = xd.cwiseAbs2();
    for (size_t j = 0; j < gammaByModelState.size(); ++j) {
        const double gamma = gammaByModelState[j];
        StateAccumulator &acc = out.states[j];
        acc.selfCount += selfByModelState[j];
        acc.occupancy += gamma;
        if (gamma < kMinGamma)
            continue;
        const GaussianMixture &g = model.state(int(j));
        const int M = g.size();
        if (int(componentLog.size()) < M)
            componentLog.resize(size_t(M));
        const float total = g.componentLogLikelihoods(x, componentLog.data());
        for (int m = 0; m < M; ++m) {
            const double w = gamma * std::exp(double(componentLog[size_t(m)] - total));
            if (w < kMinGamma * 1e-2)
                continue;
            acc.componentOccupancy[m] += w;
            acc.sum.row(m) += w * xd;
            acc.sumSquares.row(m) += w * xsq;
        }
    }
}

} // namespace

double accumulateUtterance(const AcousticModel &model, const UtteranceGraph &graph,
                           const Eigen::MatrixXf &features, double beam, Accumulators &out)
{
    const int T = int(features.rows());
    const int S = graph.size();
    if (T == 0 || S == 0 || T < graph.minimumFrames() || double(T) * double(S) > kMaxForwardCells)
        return -INFINITY;
    const auto &states = graph.states();
    EmissionCache emission(model, features);

    std::vector<double> logSelf(static_cast<size_t>(S)), logExit(static_cast<size_t>(S));
    std::vector<std::vector<double>> logIn(static_cast<size_t>(S));
    for (int s = 0; s < S; ++s) {
        logSelf[size_t(s)] = graph.logSelf(model, s);
        logExit[size_t(s)] = graph.logExit(model, s);
        for (const GraphEdge &e : states[size_t(s)].in)
            logIn[size_t(s)].push_back(graph.logEdge(model, e));
    }

    // Forward: alpha[t][s] = log p(o_0..o_t, state_t = s), pruned to `beam` below the best.
    std::vector<double> alpha(static_cast<size_t>(T) * size_t(S), -INFINITY);
    auto A = [&](int t, int s) -> double & { return alpha[size_t(t) * size_t(S) + size_t(s)]; };
    for (int t = 0; t < T; ++t) {
        double best = -INFINITY;
        for (int s = 0; s < S; ++s) {
            double v = -INFINITY;
            const GraphState &st = states[size_t(s)];
            if (t == 0) {
                for (size_t e = 0; e < st.in.size(); ++e)
                    if (st.in[e].from < 0)
                        v = logAdd(v, logIn[size_t(s)][e]);
            } else {
                const double self = A(t - 1, s);
                if (self > -INFINITY)
                    v = self + logSelf[size_t(s)];
                for (size_t e = 0; e < st.in.size(); ++e) {
                    const int from = st.in[e].from;
                    if (from >= 0) {
                        const double p = A(t - 1, from);
                        if (p > -INFINITY)
                            v = logAdd(v, p + logIn[size_t(s)][e]);
                    }
                }
            }
            if (v > -INFINITY) {
                v += emission(t, st.modelState);
                A(t, s) = v;
                best = std::max(best, v);
            }
        }
        if (best == -INFINITY)
            return -INFINITY;
        for (int s = 0; s < S; ++s)
            if (A(t, s) < best - beam)
                A(t, s) = -INFINITY;
    }
    double logP = -INFINITY;
    for (int s = 0; s < S; ++s)
        if (A(T - 1, s) > -INFINITY)
            logP = logAdd(logP, A(T - 1, s) + logExit[size_t(s)]);
    if (!(logP > -INFINITY))
        return -INFINITY;

    // Backward sweep with two beta vectors, accumulating as we go.
    std::vector<double> beta(static_cast<size_t>(S), -INFINITY), next(size_t(S), -INFINITY);
    for (int s = 0; s < S; ++s)
        if (A(T - 1, s) > -INFINITY)
            beta[size_t(s)] = logExit[size_t(s)];
    std::vector<double> gammaByModelState(static_cast<size_t>(model.stateCount()));
    std::vector<double> selfByModelState(static_cast<size_t>(model.stateCount()));
    std::vector<float> componentLog(64);
    for (int t = T - 1; t >= 0; --t) {
        // Occupation of model states at t and self transitions into t.
        std::fill(gammaByModelState.begin(), gammaByModelState.end(), 0.0);
        std::fill(selfByModelState.begin(), selfByModelState.end(), 0.0);
        for (int s = 0; s < S; ++s) {
            const double a = A(t, s);
            if (a == -INFINITY || beta[size_t(s)] == -INFINITY)
                continue;
            const int j = states[size_t(s)].modelState;
            gammaByModelState[size_t(j)] += std::exp(a + beta[size_t(s)] - logP);
            if (t > 0 && A(t - 1, s) > -INFINITY)
                selfByModelState[size_t(j)] += std::exp(A(t - 1, s) + logSelf[size_t(s)]
                                                        + emission(t, j) + beta[size_t(s)] - logP);
        }
        accumulateFrame(model, emission.frame(t), gammaByModelState, selfByModelState, componentLog, out);
        if (t == 0)
            break;
        // beta_{t-1}(i) = log sum_j a_ij b_j(o_t) beta_t(j), over states alive in the forward pass.
        std::fill(next.begin(), next.end(), -INFINITY);
        for (int s = 0; s < S; ++s) {
            if (beta[size_t(s)] == -INFINITY)
                continue;
            const GraphState &st = states[size_t(s)];
            const double tail = emission(t, st.modelState) + beta[size_t(s)];
            if (A(t - 1, s) > -INFINITY)
                next[size_t(s)] = logAdd(next[size_t(s)], logSelf[size_t(s)] + tail);
            for (size_t e = 0; e < st.in.size(); ++e) {
                const int from = st.in[e].from;
                if (from >= 0 && A(t - 1, from) > -INFINITY)
                    next[size_t(from)] = logAdd(next[size_t(from)], logIn[size_t(s)][e] + tail);
            }
        }
        std::swap(beta, next);
    }
    out.logLikelihood += logP;
    out.frames += T;
    out.utterances += 1;
    return logP;
}

} // namespace lipsync
