#include "dynamics/DpdsSolver.h"

#include "util/Error.h"

#include <Eigen/Cholesky>

namespace lipsync::dpds {

LabelLayout makeLayout(const std::vector<std::vector<int>> &labels, int states)
{
    LabelLayout layout;
    layout.states = states;
    layout.labels = labels;
    layout.startCount = Eigen::VectorXi::Zero(states);
    layout.transitionCount = Eigen::VectorXi::Zero(states);
    std::vector<int> position(size_t(states), -1);
    for (const std::vector<int> &seq : labels) {
        std::vector<int> visited, local(seq.size(), -1);
        for (size_t t = 1; t < seq.size(); ++t) {
            const int n = seq[t];
            if (position[size_t(n)] < 0) {
                position[size_t(n)] = int(visited.size());
                visited.push_back(n);
            }
            local[t] = position[size_t(n)];
            layout.transitionCount[n]++;
        }
        for (int n : visited)
            position[size_t(n)] = -1;
        layout.startCount[seq[0]]++;
        layout.frames += (long long)seq.size();
        layout.transitions += (long long)seq.size() - 1;
        layout.visited.push_back(std::move(visited));
        layout.local.push_back(std::move(local));
    }
    return layout;
}

Series states(const LabelLayout &layout, const Eigen::VectorXd &a, const Eigen::VectorXd &theta)
{
    const int P = layout.states;
    Series x(layout.labels.size());
    for (size_t s = 0; s < layout.labels.size(); ++s) {
        const std::vector<int> &pi = layout.labels[s];
        Eigen::VectorXd &xs = x[s];
        xs.resize(Eigen::Index(pi.size()));
        xs[0] = theta[pi[0]];
        for (size_t t = 1; t < pi.size(); ++t)
            xs[Eigen::Index(t)] = a[pi[t]] * xs[Eigen::Index(t - 1)] + theta[P + pi[t]];
    }
    return x;
}

double weightedSquaredError(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                            const Eigen::VectorXd &theta, const Weights &w)
{
    const int P = layout.states;
    double startTerm = 0.0, transitionTerm = 0.0;
    for (size_t s = 0; s < layout.labels.size(); ++s) {
        const std::vector<int> &pi = layout.labels[s];
        const Eigen::VectorXd &ys = y[s];
        double x = theta[pi[0]];
        startTerm += w.startWeight[pi[0]] * (ys[0] - x) * (ys[0] - x);
        for (size_t t = 1; t < pi.size(); ++t) {
            x = a[pi[t]] * x + theta[P + pi[t]];
            const double e = ys[Eigen::Index(t)] - x;
            transitionTerm += e * e;
        }
    }
    return 0.5 * (startTerm + w.transitionWeight * transitionTerm);
}

Eigen::MatrixXd designRows(const LabelLayout &layout, int sequence, const Eigen::VectorXd &a)
{
    const int P = layout.states;
    const std::vector<int> &pi = layout.labels[size_t(sequence)];
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(Eigen::Index(pi.size()), 2 * P);
    R(0, pi[0]) = 1.0;
    for (size_t t = 1; t < pi.size(); ++t) {
        R.row(Eigen::Index(t)) = a[pi[t]] * R.row(Eigen::Index(t - 1));
        R(Eigen::Index(t), P + pi[t]) += 1.0;
    }
    return R;
}

Eigen::MatrixXd sensitivityRows(const LabelLayout &layout, int sequence, const Eigen::VectorXd &a,
                                const Eigen::VectorXd &theta)
{
    const int P = layout.states;
    const std::vector<int> &pi = layout.labels[size_t(sequence)];
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(Eigen::Index(pi.size()), P);
    double x = theta[pi[0]];
    for (size_t t = 1; t < pi.size(); ++t) {
        S.row(Eigen::Index(t)) = a[pi[t]] * S.row(Eigen::Index(t - 1));
        S(Eigen::Index(t), pi[t]) += x; // corrected eq. (2): x_{t-1}, not x_t
        x = a[pi[t]] * x + theta[P + pi[t]];
    }
    return S;
}

void NormalEquations::assemble(const Weights &w, Eigen::MatrixXd &G, Eigen::VectorXd &h) const
{
    const Eigen::Index P = startCount.size();
    G = w.transitionWeight * transitionG;
    h = w.transitionWeight * transitionH;
    for (Eigen::Index n = 0; n < P; ++n) {
        G(n, n) += w.startWeight[n] * startCount[n];
        h[n] += w.startWeight[n] * startSum[n];
    }
}

NormalEquations normalEquations(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a)
{
    const int P = layout.states;
    NormalEquations ne;
    ne.transitionG = Eigen::MatrixXd::Zero(2 * P, 2 * P);
    ne.transitionH = Eigen::VectorXd::Zero(2 * P);
    ne.startCount = Eigen::VectorXd::Zero(P);
    ne.startSum = Eigen::VectorXd::Zero(P);
    Eigen::MatrixXd R, Gl;
    Eigen::VectorXd hl, r;
    std::vector<int> global;
    for (size_t s = 0; s < layout.labels.size(); ++s) {
        const std::vector<int> &pi = layout.labels[s];
        const std::vector<int> &visited = layout.visited[s];
        const std::vector<int> &local = layout.local[s];
        const Eigen::VectorXd &ys = y[s];
        ne.startCount[pi[0]] += 1.0;
        ne.startSum[pi[0]] += ys[0];
        const Eigen::Index L = 1 + Eigen::Index(visited.size());
        if (L == 1)
            continue;
        // Local row: slot 0 = mu_{pi_1}, slot 1 + j = nu of visited[j]. Slots become non-zero in
        // order, so only the prefix [0, active) is touched (§4.3 sparsity). The rows r_t (t >= 2)
        // are stacked into R and G_local = R^T R, h_local = R^T y are formed by one symmetric
        // rank-k update and one product (vectorised) instead of per-frame outer products.
        const Eigen::Index rows = Eigen::Index(pi.size()) - 1;
        R.setZero(rows, L);
        r = Eigen::VectorXd::Zero(L);
        r[0] = 1.0;
        Eigen::Index active = 1;
        for (size_t t = 1; t < pi.size(); ++t) {
            const Eigen::Index j = 1 + local[t];
            r.head(active) *= a[pi[t]];
            if (j >= active)
                active = j + 1;
            r[j] += 1.0;
            R.row(Eigen::Index(t) - 1).head(active) = r.head(active).transpose();
        }
        Gl.setZero(L, L);
        Gl.selfadjointView<Eigen::Lower>().rankUpdate(R.transpose());
        hl.noalias() = R.transpose() * ys.tail(rows);
        global.assign(size_t(L), 0);
        global[0] = pi[0];
        for (size_t j = 0; j < visited.size(); ++j)
            global[j + 1] = P + visited[j];
        for (Eigen::Index i = 0; i < L; ++i) {
            ne.transitionH[global[size_t(i)]] += hl[i];
            for (Eigen::Index k = i; k < L; ++k) {
                const double v = Gl(k, i);
                ne.transitionG(global[size_t(k)], global[size_t(i)]) += v;
                if (k != i)
                    ne.transitionG(global[size_t(i)], global[size_t(k)]) += v;
            }
        }
    }
    return ne;
}

Eigen::VectorXd solveTheta(const Eigen::MatrixXd &G, const Eigen::VectorXd &h, double tau,
                           const Eigen::VectorXd &thetaBar)
{
    Eigen::MatrixXd A = G;
    A.diagonal().array() += tau;
    const Eigen::LLT<Eigen::MatrixXd> llt(A);
    if (llt.info() != Eigen::Success)
        throw Error("DPDS normal equations are not positive definite");
    return llt.solve(h + tau * thetaBar);
}

Eigen::VectorXd forwardGradient(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                                const Eigen::VectorXd &theta, const Weights &w)
{
    const int P = layout.states;
    Eigen::VectorXd grad = Eigen::VectorXd::Zero(P);
    Eigen::VectorXd sLocal, gLocal;
    for (size_t s = 0; s < layout.labels.size(); ++s) {
        const std::vector<int> &pi = layout.labels[s];
        const std::vector<int> &visited = layout.visited[s];
        const Eigen::VectorXd &ys = y[s];
        sLocal = Eigen::VectorXd::Zero(Eigen::Index(visited.size()));
        gLocal = Eigen::VectorXd::Zero(Eigen::Index(visited.size()));
        double x = theta[pi[0]];
        for (size_t t = 1; t < pi.size(); ++t) {
            // s_t = a_{pi_t} s_{t-1} + e_{pi_t} x_{t-1}   (§4.7a, eq. 2 corrected)
            sLocal *= a[pi[t]];
            sLocal[layout.local[s][t]] += x;
            x = a[pi[t]] * x + theta[P + pi[t]];
            gLocal += (w.transitionWeight * (ys[Eigen::Index(t)] - x)) * sLocal;
        }
        for (size_t j = 0; j < visited.size(); ++j)
            grad[visited[j]] += gLocal[Eigen::Index(j)];
    }
    return grad;
}

void adjointGradient(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                     const Eigen::VectorXd &theta, const Weights &w, Eigen::VectorXd &gradA,
                     Eigen::VectorXd &gradMu, Eigen::VectorXd &gradNu)
{
    const int P = layout.states;
    gradA = Eigen::VectorXd::Zero(P);
    gradMu = Eigen::VectorXd::Zero(P);
    gradNu = Eigen::VectorXd::Zero(P);
    const Series x = states(layout, a, theta);
    for (size_t s = 0; s < layout.labels.size(); ++s) {
        const std::vector<int> &pi = layout.labels[s];
        const Eigen::VectorXd &ys = y[s], &xs = x[s];
        const Eigen::Index T = ys.size();
        double lambda = 0.0;
        for (Eigen::Index t = T - 1; t >= 0; --t) {
            const double omega = t == 0 ? w.startWeight[pi[0]] : w.transitionWeight;
            // lambda_t = omega_t eps_t + a_{pi_{t+1}} lambda_{t+1}   (§4.7b)
            lambda = omega * (ys[t] - xs[t]) + (t + 1 < T ? a[pi[size_t(t + 1)]] * lambda : 0.0);
            if (t > 0) {
                gradA[pi[size_t(t)]] += lambda * xs[t - 1];
                gradNu[pi[size_t(t)]] += lambda;
            } else {
                gradMu[pi[0]] += lambda;
            }
        }
    }
}

void gaussNewton(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a,
                 const Eigen::VectorXd &theta, const Weights &w, Eigen::MatrixXd &H,
                 Eigen::VectorXd &g)
{
    const int P = layout.states;
    H = Eigen::MatrixXd::Zero(3 * P, 3 * P);
    g = Eigen::VectorXd::Zero(P);
    Eigen::MatrixXd Z, Hl;
    Eigen::VectorXd z, e, gl;
    std::vector<int> global;
    for (size_t s = 0; s < layout.labels.size(); ++s) {
        const std::vector<int> &pi = layout.labels[s];
        const std::vector<int> &visited = layout.visited[s];
        const std::vector<int> &local = layout.local[s];
        const Eigen::VectorXd &ys = y[s];
        // t = 1: s_1 = 0, r_1 = e_mu.
        H(P + pi[0], P + pi[0]) += w.startWeight[pi[0]];
        const Eigen::Index M = Eigen::Index(visited.size());
        if (M == 0)
            continue;
        // Local z = [r; s] interleaved by visit: slot 0 = mu_{pi_1}, slot 1 + 2j = nu and
        // slot 2 + 2j = a of visited[j]. States are numbered in order of first visit, so the
        // non-zero slots of z_t are always a prefix. The z_t (t >= 2) are stacked into Z and
        // H_local = Z^T Z, g_local = Z^T e come from one rank-k update and one product.
        const Eigen::Index L = 1 + 2 * M, rows = Eigen::Index(pi.size()) - 1;
        Z.setZero(rows, L);
        e.resize(rows);
        z = Eigen::VectorXd::Zero(L);
        z[0] = 1.0;
        Eigen::Index active = 1;
        double x = theta[pi[0]];
        for (size_t t = 1; t < pi.size(); ++t) {
            const int n = pi[t];
            const Eigen::Index j = local[t];
            const double an = a[n];
            z.head(active) *= an;
            if (2 + 2 * j >= active) // first visit
                active = 3 + 2 * j;
            z[1 + 2 * j] += 1.0;
            z[2 + 2 * j] += x; // s_t: e_{pi_t} x_{t-1}
            x = an * x + theta[P + n];
            e[Eigen::Index(t) - 1] = ys[Eigen::Index(t)] - x;
            Z.row(Eigen::Index(t) - 1).head(active) = z.head(active).transpose();
        }
        Hl.setZero(L, L);
        Hl.selfadjointView<Eigen::Lower>().rankUpdate(Z.transpose(), w.transitionWeight);
        gl.noalias() = Z.transpose() * e;
        global.assign(size_t(L), 0);
        global[0] = P + pi[0];
        for (Eigen::Index j = 0; j < M; ++j) {
            global[size_t(1 + 2 * j)] = 2 * P + visited[size_t(j)];
            global[size_t(2 + 2 * j)] = visited[size_t(j)];
            g[visited[size_t(j)]] += w.transitionWeight * gl[2 + 2 * j];
        }
        for (Eigen::Index i = 0; i < L; ++i)
            for (Eigen::Index k = i; k < L; ++k) {
                const double v = Hl(k, i);
                H(global[size_t(k)], global[size_t(i)]) += v;
                if (k != i)
                    H(global[size_t(i)], global[size_t(k)]) += v;
            }
    }
}

} // namespace lipsync::dpds
