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

// Sums of outer products of a linear recursion in O(T L) instead of O(T L^2) [implementation]:
// the rows obey v_t = alpha_t v_{t-1} + u_t with a sparse u_t (one or two slots), so
//   sum_{t>=1} v_t v_t^T = alpha_1^2 R_1 v_0 v_0^T
//                          + sum_{t>=1} R_t [alpha_t (v_{t-1} u_t^T + u_t v_{t-1}^T) + u_t u_t^T],
// with R_t = sum_{tau>=t} prod_{rho=t+1..tau} alpha_rho^2 = 1 + alpha_{t+1}^2 R_{t+1} (all terms
// positive: no cancellation). Likewise sum_t c_t v_t = sum_t u_t lambda_t (+ the v_0 term) with
// the adjoint lambda_t = c_t + alpha_{t+1} lambda_{t+1} (§4.7b).
namespace {

// R_t (t = 1..T-1) and lambda_t of c_t for one sequence; alpha_t = a[pi_t].
void backwardSums(const std::vector<int> &pi, const Eigen::VectorXd &a, const double *c,
                  std::vector<double> &R, std::vector<double> &lambda)
{
    const size_t T = pi.size();
    R.resize(T);
    lambda.resize(T);
    R[T - 1] = 1.0;
    lambda[T - 1] = c[T - 1];
    for (size_t t = T - 1; t-- > 1;) {
        const double alpha = a[pi[t + 1]];
        R[t] = 1.0 + alpha * alpha * R[t + 1];
        lambda[t] = c[t] + alpha * lambda[t + 1];
    }
}

} // namespace

NormalEquations normalEquations(const LabelLayout &layout, const Series &y, const Eigen::VectorXd &a)
{
    const int P = layout.states;
    NormalEquations ne;
    ne.transitionG = Eigen::MatrixXd::Zero(2 * P, 2 * P);
    ne.transitionH = Eigen::VectorXd::Zero(2 * P);
    ne.startCount = Eigen::VectorXd::Zero(P);
    ne.startSum = Eigen::VectorXd::Zero(P);
    Eigen::MatrixXd Gl;
    Eigen::VectorXd hl, r;
    std::vector<double> R, lambda;
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
        // Local row: slot 0 = mu_{pi_1}, slot 1 + j = nu of visited[j]; r_0 = e_0 and
        // r_t = a_{pi_t} r_{t-1} + e_{1 + local_t} (§4.3). Slots become non-zero in order, so only
        // the prefix [0, active) of r is touched.
        backwardSums(pi, a, ys.data(), R, lambda);
        Gl.setZero(L, L); // columns j: sum R_t alpha_t r_{t-1} over the t with slot j (then + transpose)
        hl.setZero(L);
        r = Eigen::VectorXd::Zero(L);
        r[0] = 1.0;
        Eigen::Index active = 1;
        for (size_t t = 1; t < pi.size(); ++t) {
            const Eigen::Index j = 1 + local[t];
            const double alpha = a[pi[t]];
            Gl.col(j).head(active) += (R[t] * alpha) * r.head(active);
            hl[j] += lambda[t];
            r.head(active) *= alpha;
            if (j >= active)
                active = j + 1;
            r[j] += 1.0;
        }
        for (size_t t = 1; t < pi.size(); ++t)
            Gl(1 + local[t], 1 + local[t]) += 0.5 * R[t]; // u u^T, halved before the symmetrisation
        const double alpha1 = a[pi[1]];
        Gl(0, 0) += 0.5 * alpha1 * alpha1 * R[1];
        hl[0] += alpha1 * lambda[1];
        Gl += Gl.transpose().eval();
        global.assign(size_t(L), 0);
        global[0] = pi[0];
        for (size_t j = 0; j < visited.size(); ++j)
            global[j + 1] = P + visited[j];
        for (Eigen::Index i = 0; i < L; ++i) {
            ne.transitionH[global[size_t(i)]] += hl[i];
            for (Eigen::Index k = 0; k < L; ++k)
                ne.transitionG(global[size_t(k)], global[size_t(i)]) += Gl(k, i);
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
    Eigen::MatrixXd Hl;
    Eigen::VectorXd z, gl;
    std::vector<double> x, e, R, lambda;
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
        // slot 2 + 2j = a of visited[j]; z_0 = e_0 and z_t = a_{pi_t} z_{t-1} + u_t with
        // u_t = e_{nu_j} + x_{t-1} e_{a_j} (§4.7a, §4.8). States are numbered in order of first
        // visit, so the non-zero slots of z_t are a prefix.
        const size_t T = pi.size();
        const Eigen::Index L = 1 + 2 * M;
        x.resize(T);
        e.resize(T);
        x[0] = theta[pi[0]];
        e[0] = 0.0;
        for (size_t t = 1; t < T; ++t) {
            x[t] = a[pi[t]] * x[t - 1] + theta[P + pi[t]];
            e[t] = ys[Eigen::Index(t)] - x[t];
        }
        backwardSums(pi, a, e.data(), R, lambda);
        Hl.setZero(L, L);
        gl.setZero(L);
        z = Eigen::VectorXd::Zero(L);
        z[0] = 1.0;
        Eigen::Index active = 1;
        for (size_t t = 1; t < T; ++t) {
            const Eigen::Index p = 1 + 2 * Eigen::Index(local[t]), q = p + 1;
            const double alpha = a[pi[t]], previous = x[t - 1], c = R[t] * alpha;
            Hl.col(p).head(active) += c * z.head(active);
            Hl.col(q).head(active) += (c * previous) * z.head(active);
            // u u^T, halved before the symmetrisation below.
            Hl(p, p) += 0.5 * R[t];
            Hl(q, q) += 0.5 * R[t] * previous * previous;
            Hl(q, p) += R[t] * previous;
            gl[q] += previous * lambda[t];
            z.head(active) *= alpha;
            if (q >= active)
                active = q + 1;
            z[p] += 1.0;
            z[q] += previous;
        }
        const double alpha1 = a[pi[1]];
        Hl(0, 0) += 0.5 * alpha1 * alpha1 * R[1];
        Hl += Hl.transpose().eval();
        Hl *= w.transitionWeight;
        global.assign(size_t(L), 0);
        global[0] = P + pi[0];
        for (Eigen::Index j = 0; j < M; ++j) {
            global[size_t(1 + 2 * j)] = 2 * P + visited[size_t(j)];
            global[size_t(2 + 2 * j)] = visited[size_t(j)];
            g[visited[size_t(j)]] += w.transitionWeight * gl[2 + 2 * j];
        }
        for (Eigen::Index i = 0; i < L; ++i)
            for (Eigen::Index k = 0; k < L; ++k)
                H(global[size_t(k)], global[size_t(i)]) += Hl(k, i);
    }
}

} // namespace lipsync::dpds
