#include "dynamics/SldsModel.h"

#include "dynamics/GaussianMath.h"
#include "dynamics/JsonEigen.h"
#include "tasks/BlockingMap.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

namespace slds {

Smoothed smooth(const Parameters &p, const std::vector<int> &labels, const Eigen::MatrixXd &Y)
{
    const size_t T = labels.size();
    const Eigen::Index d = p.dimension();
    std::vector<Eigen::VectorXd> mp(T), mf(T);
    std::vector<Eigen::MatrixXd> Pp(T), Pf(T);
    Smoothed out;
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(d, d);
    for (size_t t = 0; t < T; ++t) {
        const int n = labels[t];
        if (t == 0) {
            mp[0] = p.mu.row(n).transpose();
            Pp[0] = p.Sigma[size_t(n)];
        } else {
            mp[t] = p.A[size_t(n)] * mf[t - 1] + p.nu.row(n).transpose();
            Pp[t] = p.A[size_t(n)] * Pf[t - 1] * p.A[size_t(n)].transpose() + p.Q[size_t(n)];
        }
        const Eigen::MatrixXd &R = p.R[size_t(n)];
        const Eigen::MatrixXd S = Pp[t] + R;
        const Eigen::LLT<Eigen::MatrixXd> llt(S);
        if (llt.info() != Eigen::Success)
            throw Error("SLDS innovation covariance is not positive definite");
        const Eigen::VectorXd eta = Y.row(Eigen::Index(t)).transpose() - mp[t];
        const Eigen::VectorXd w = llt.matrixL().solve(eta);
        const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
        out.logLikelihood += -0.5 * (double(d) * kLog2Pi + logDet + w.squaredNorm());
        const Eigen::MatrixXd K = llt.solve(Pp[t]).transpose(); // P S^-1 (both symmetric)
        mf[t] = mp[t] + K * eta;
        // Joseph form (§3.2).
        Pf[t] = (I - K) * Pp[t] * (I - K).transpose() + K * R * K.transpose();
    }
    out.mean.resize(T);
    out.covariance.resize(T);
    out.cross.assign(T, Eigen::MatrixXd());
    out.mean[T - 1] = mf[T - 1];
    out.covariance[T - 1] = Pf[T - 1];
    for (size_t t = T - 1; t-- > 0;) {
        const Eigen::MatrixXd &A = p.A[size_t(labels[t + 1])];
        // J_t = P_{t|t} A^T P_{t+1|t}^{-1}
        const Eigen::MatrixXd J = Pp[t + 1].ldlt().solve(A * Pf[t]).transpose();
        out.mean[t] = mf[t] + J * (out.mean[t + 1] - mp[t + 1]);
        out.covariance[t] = Pf[t] + J * (out.covariance[t + 1] - Pp[t + 1]) * J.transpose();
        out.cross[t + 1] = out.covariance[t + 1] * J.transpose();
    }
    return out;
}

double kalmanLogLikelihood(const Parameters &p, const std::vector<int> &labels,
                           const Eigen::MatrixXd &Y)
{
    const Eigen::Index d = p.dimension();
    Eigen::VectorXd m;
    Eigen::MatrixXd P;
    double ll = 0.0;
    for (size_t t = 0; t < labels.size(); ++t) {
        const int n = labels[t];
        if (t == 0) {
            m = p.mu.row(n).transpose();
            P = p.Sigma[size_t(n)];
        } else {
            m = p.A[size_t(n)] * m + p.nu.row(n).transpose();
            P = p.A[size_t(n)] * P * p.A[size_t(n)].transpose() + p.Q[size_t(n)];
        }
        const Eigen::MatrixXd &R = p.R[size_t(n)];
        const Eigen::LLT<Eigen::MatrixXd> llt(P + R);
        if (llt.info() != Eigen::Success)
            throw Error("SLDS innovation covariance is not positive definite");
        const Eigen::VectorXd eta = Y.row(Eigen::Index(t)).transpose() - m;
        ll += -0.5 * (double(d) * kLog2Pi + 2.0 * llt.matrixLLT().diagonal().array().log().sum()
                      + llt.matrixL().solve(eta).squaredNorm());
        const Eigen::MatrixXd K = llt.solve(P).transpose();
        const Eigen::MatrixXd IK = Eigen::MatrixXd::Identity(d, d) - K;
        m += K * eta;
        P = IK * P * IK.transpose() + K * R * K.transpose();
    }
    return ll;
}

} // namespace slds

namespace {

Eigen::MatrixXd floorCovariance(const Eigen::MatrixXd &C, const Eigen::VectorXd &floor, bool full)
{
    if (!full)
        return C.diagonal().cwiseMax(floor).asDiagonal();
    return floorEigenvalues(C, floor.minCoeff());
}

// The transition sums of one state (§3.3): S^xx, the augmented S^xz = [S^x- s^x] and
// S^zz = [S^-- s^-; s^-T N], and N = N^>=2.
struct TransitionSums
{
    Eigen::MatrixXd Sxx, Sxz, Szz;
    double N = 0.0;

    // Q_n given A~ = [A nu] (§3.4 process noise), before the floor.
    Eigen::MatrixXd processNoise(const Eigen::MatrixXd &At) const
    {
        return (Sxx - At * Sxz.transpose() - Sxz * At.transpose() + At * Szz * At.transpose()) / N;
    }
    // The transition part of the expected complete-data log-likelihood at A~, with Q at its
    // (floored) maximiser given A~, up to a constant: -N/2 (log|Q| + tr(Q^-1 S(A~))).
    double objective(const Eigen::MatrixXd &At, const Eigen::VectorXd &floor, bool full) const
    {
        const Eigen::MatrixXd S = processNoise(At);
        const Eigen::LLT<Eigen::MatrixXd> llt(floorCovariance(S, floor, full));
        const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
        return -0.5 * N * (logDet + llt.solve(S).trace());
    }
};

// One dimension's parameters of the all-diagonal SLDS, per state (§3.1).
struct ScalarParameters
{
    Eigen::VectorXd a, q, r, sigma, nu, mu;
};

// One dimension's smoothed sufficient statistics per state (§3.3) and the log-likelihood of its
// features (§3.2).
struct ScalarStatistics
{
    explicit ScalarStatistics(Eigen::Index P)
        : Sxx(Eigen::VectorXd::Zero(P)), Smm(Sxx), Sxm(Sxx), sx(Sxx), sm(Sxx), N2(Sxx), Rsum(Sxx), Rn(Sxx),
          x1(Sxx), x1sq(Sxx), N1(Sxx)
    {
    }
    Eigen::VectorXd Sxx, Smm, Sxm, sx, sm, N2, Rsum, Rn, x1, x1sq, N1;
    double ll = 0.0;
};

// The E-step of dimension k: a scalar Kalman filter and RTS smoother over every sequence (§3.2-3.3).
ScalarStatistics smoothDimension(const std::vector<LabelledSequence> &sequences, Eigen::Index k,
                                 const ScalarParameters &p)
{
    const Eigen::VectorXd &a = p.a, &q = p.q, &r = p.r, &sigma = p.sigma, &nu = p.nu, &mu = p.mu;
    ScalarStatistics st(a.size());
    LogSum logS; // sum of log S_t, one log per 8 frames
    long long frames = 0;
    std::vector<double> mp, Pp, mf, Pf, ms, Ps;
    for (const LabelledSequence &s : sequences) {
        const size_t T = s.labels.size();
        mp.resize(T);
        Pp.resize(T);
        mf.resize(T);
        Pf.resize(T);
        ms.resize(T);
        Ps.resize(T);
        for (size_t t = 0; t < T; ++t) {
            const int n = s.labels[t];
            if (t == 0) {
                mp[0] = mu[n];
                Pp[0] = sigma[n];
            } else {
                mp[t] = a[n] * mf[t - 1] + nu[n];
                Pp[t] = a[n] * a[n] * Pf[t - 1] + q[n];
            }
            const double S = Pp[t] + r[n], inverseS = 1.0 / S, K = Pp[t] * inverseS;
            const double eta = s.features(Eigen::Index(t), k) - mp[t];
            st.ll -= 0.5 * eta * eta * inverseS;
            logS.add(S);
            mf[t] = mp[t] + K * eta;
            Pf[t] = (1 - K) * (1 - K) * Pp[t] + K * K * r[n];
        }
        frames += (long long)T;
        ms[T - 1] = mf[T - 1];
        Ps[T - 1] = Pf[T - 1];
        for (size_t t = T - 1; t-- > 0;) {
            const int n1 = s.labels[t + 1];
            const double J = Pf[t] * a[n1] / Pp[t + 1];
            ms[t] = mf[t] + J * (ms[t + 1] - mp[t + 1]);
            Ps[t] = Pf[t] + J * J * (Ps[t + 1] - Pp[t + 1]);
            // Sufficient statistics of transition t+1 (§3.3): P_{t+1,t|T} = P_{t+1|T} J_t.
            const double cross = Ps[t + 1] * J + ms[t + 1] * ms[t];
            st.Sxx[n1] += Ps[t + 1] + ms[t + 1] * ms[t + 1];
            st.Smm[n1] += Ps[t] + ms[t] * ms[t];
            st.Sxm[n1] += cross;
            st.sx[n1] += ms[t + 1];
            st.sm[n1] += ms[t];
            st.N2[n1] += 1.0;
        }
        for (size_t t = 0; t < T; ++t) {
            const int n = s.labels[t];
            const double e = s.features(Eigen::Index(t), k) - ms[t];
            st.Rsum[n] += e * e + Ps[t];
            st.Rn[n] += 1.0;
        }
        const int n0 = s.labels[0];
        st.x1[n0] += ms[0];
        st.x1sq[n0] += Ps[0] + ms[0] * ms[0];
        st.N1[n0] += 1.0;
    }
    st.ll -= 0.5 * (double(frames) * kLog2Pi + logS.value());
    return st;
}

// The M-step of one state's transition (§3.4): A~ = [A nu] maximising the expected complete-data
// log-likelihood given its sums, within the options' bound on A; A, nu and Q are the state's current
// parameters (the ECM step's Lambda = Q^-1; the fallback when a clipped A~ scores lower).
Eigen::MatrixXd updateTransition(const TransitionSums &sums, const Eigen::MatrixXd &A, const Eigen::VectorXd &nu,
                                 const Eigen::MatrixXd &Q, const Eigen::VectorXd &floor, const SldsOptions &options)
{
    const bool bound = options.boundA;
    const bool full = options.fullNoise;
    const Eigen::Index d = sums.Sxx.rows();
    const double N = sums.N;
    const auto Smm = sums.Szz.topLeftCorner(d, d);
    const auto Sxm = sums.Sxz.leftCols(d);
    const auto smv = sums.Szz.col(d).head(d);
    const auto sxv = sums.Sxz.col(d);
    bool clipped = false;
    Eigen::MatrixXd At(d, d + 1);
    if (options.fullA) {
        At = sums.Szz.ldlt().solve(sums.Sxz.transpose()).transpose();
        // Bound: clip the singular values at aMax (common Lyapunov function, §4.11).
        if (bound) {
            const Eigen::JacobiSVD<Eigen::MatrixXd> svd(At.leftCols(d), Eigen::ComputeFullU
                                                                            | Eigen::ComputeFullV);
            if (svd.singularValues().maxCoeff() > options.aMax) {
                const Eigen::MatrixXd clippedA = svd.matrixU()
                                                 * svd.singularValues().cwiseMin(options.aMax).asDiagonal()
                                                 * svd.matrixV().transpose();
                At.leftCols(d) = clippedA;
                At.col(d) = (sxv - clippedA * smv) / N;
                clipped = true;
            }
        }
    } else if (!full) {
        At.setZero();
        for (Eigen::Index k = 0; k < d; ++k) {
            Eigen::Matrix2d M;
            M << Smm(k, k), smv[k], smv[k], N;
            Eigen::Vector2d sol = M.lu().solve(Eigen::Vector2d(Sxm(k, k), sxv[k]));
            // Bound: the constrained maximum of the concave profile in a_k (exact).
            if (bound && std::abs(sol[0]) > options.aMax) {
                sol[0] = std::clamp(sol[0], -options.aMax, options.aMax);
                sol[1] = (sxv[k] - sol[0] * smv[k]) / N;
            }
            At(k, k) = sol[0];
            At(k, d) = sol[1];
        }
    } else {
        // Diagonal A, full Q: ECM given Lambda = Q_n^-1 (§3.4).
        const Eigen::MatrixXd Lambda = Q.ldlt().solve(Eigen::MatrixXd::Identity(d, d));
        const Eigen::MatrixXd lhs = Lambda.cwiseProduct(Smm)
                                    - smv.asDiagonal() * Lambda * smv.asDiagonal() / N;
        const Eigen::VectorXd rhs = Lambda.cwiseProduct(Sxm.transpose()) * Eigen::VectorXd::Ones(d)
                                    - smv.asDiagonal() * (Lambda * sxv) / N;
        Eigen::VectorXd av = lhs.ldlt().solve(rhs);
        if (bound && av.cwiseAbs().maxCoeff() > options.aMax) {
            av = av.cwiseMax(-options.aMax).cwiseMin(options.aMax);
            clipped = true;
        }
        At.setZero();
        At.leftCols(d) = av.asDiagonal();
        At.col(d) = (sxv - av.cwiseProduct(smv)) / N;
    }
    if (clipped) {
        // The clipped matrix is not the constrained maximiser: keep the current (feasible)
        // A~ where it scores higher, a generalised M-step, so the likelihood cannot drop.
        Eigen::MatrixXd current(d, d + 1);
        current << A, nu;
        if (sums.objective(current, floor, full) > sums.objective(At, floor, full))
            At = current;
    }
    return At;
}

} // namespace

void SldsModel::setParameters(const slds::Parameters &parameters)
{
    m_params = parameters;
    m_dimension = parameters.dimension();
}

void SldsModel::fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    const int P = stateCount();
    const FrameStatistics st = computeFrameStatistics(sequences, P);
    const Eigen::Index d = st.mean.cols();
    // Initialisation [choice, §3.4]: DPDS a, nu, mu; Q = R = r/2; Sigma_n = c_n.
    DpdsOptions dpdsOptions;
    dpdsOptions.maxIterations = m_options.initIterations;
    if (m_options.boundA)
        dpdsOptions.aMax = std::min(m_options.aMax, dpdsOptions.aMax);
    dpdsOptions.threads = m_options.threads;
    DpdsModel trainedHere(dpdsOptions);
    trainedHere.setStateCount(P);
    const bool given = m_initialisation && m_initialisation->dimension() == int(d)
                       && m_initialisation->stateCount() == P;
    if (!given) {
        Feedback child(feedback, 0.0, 0.2);
        feedback.setStatus("SLDS: DPDS initialisation");
        trainedHere.train(sequences, child);
    }
    const DpdsModel &dpds = given ? *m_initialisation : trainedHere;
    slds::Parameters p;
    p.mu = dpds.mu;
    p.nu = dpds.nu;
    // With the bound, EM starts inside it (a shared DPDS may have been trained with a looser
    // one): the constrained M-steps are monotone only from a feasible A.
    const double aLimit = m_options.boundA ? m_options.aMax : std::numeric_limits<double>::infinity();
    for (int n = 0; n < P; ++n) {
        p.A.push_back(dpds.a.row(n).transpose().cwiseMax(-aLimit).cwiseMin(aLimit).asDiagonal());
        p.Q.push_back((0.5 * dpds.r).asDiagonal());
        p.R.push_back((0.5 * dpds.r).asDiagonal());
        p.Sigma.push_back(st.variance.row(n).transpose().asDiagonal());
    }
    Eigen::VectorXd s0 = Eigen::VectorXd::Zero(d);
    for (const LabelledSequence &s : sequences)
        s0 += (s.features.row(0) - st.mean.row(s.labels[0])).transpose().array().square().matrix();
    s0 = (s0 / double(sequences.size())).cwiseMax(st.floor);

    const slds::Parameters previous = m_params;
    const int previousDimension = m_dimension;
    m_params = p;
    m_dimension = int(d);
    std::vector<double> history;
    try {
        feedback.setStatus("SLDS: EM");
        for (int it = 0; it < m_options.maxIterations; ++it) {
            feedback.throwIfCanceled();
            const double objective = isDiagonal() ? emDiagonal(sequences, st, s0)
                                                  : emMatrix(sequences, st, s0);
            history.push_back(objective);
            feedback.reportIteration(it + 1, objective);
            feedback.setProgress(0.2 + 0.8 * double(it + 1) / m_options.maxIterations);
            if (history.size() >= 2) {
                const double gain = objective - history[history.size() - 2];
                if (gain <= m_options.tolerance * std::abs(objective))
                    break;
            }
        }
    } catch (...) {
        m_params = previous;
        m_dimension = previousDimension;
        throw;
    }
    m_history = std::move(history);
    feedback.setProgress(1.0);
}

double SldsModel::emDiagonal(const std::vector<LabelledSequence> &sequences,
                             const FrameStatistics &st, const Eigen::VectorXd &s0)
{
    // All-diagonal default: d independent scalar Kalman filters / RTS smoothers (§3.1).
    const int P = stateCount();
    const Eigen::Index d = m_dimension;
    slds::Parameters &p = m_params;
    // Dimensions are independent: run them in parallel (each writes only its own k entries).
    std::vector<double> perDimension(static_cast<size_t>(d), 0.0);
    std::vector<Eigen::Index> dimensions(static_cast<size_t>(d));
    for (Eigen::Index k = 0; k < d; ++k)
        dimensions[size_t(k)] = k;
    auto fitDimension = [&](Eigen::Index k) {
        ScalarParameters scalar{Eigen::VectorXd(P), Eigen::VectorXd(P), Eigen::VectorXd(P), Eigen::VectorXd(P),
                                p.nu.col(k), p.mu.col(k)};
        Eigen::VectorXd &a = scalar.a, &q = scalar.q, &r = scalar.r, &sigma = scalar.sigma, &nu = scalar.nu,
                        &mu = scalar.mu;
        for (int n = 0; n < P; ++n) {
            a[n] = p.A[size_t(n)](k, k);
            q[n] = p.Q[size_t(n)](k, k);
            r[n] = p.R[size_t(n)](k, k);
            sigma[n] = p.Sigma[size_t(n)](k, k);
        }
        const ScalarStatistics stats = smoothDimension(sequences, k, scalar);
        double ll = stats.ll;
        // Log prior of Sigma (MAP, §4.5 form) for the objective.
        for (int n = 0; n < P; ++n)
            if (stats.N1[n] > 0 && m_options.kappa > 0)
                ll += -(m_options.kappa / 2 + 1) * std::log(sigma[n])
                      - m_options.kappa * s0[k] / (2 * sigma[n]);
        perDimension[size_t(k)] = ll;
        // M-step (§3.4), diagonal A and Q: the exact 2 x 2 solve per state.
        const double floor = st.floor[k];
        for (int n = 0; n < P; ++n) {
            if (stats.N2[n] > 0) {
                Eigen::Matrix2d M;
                M << stats.Smm[n], stats.sm[n], stats.sm[n], stats.N2[n];
                const Eigen::Vector2d rhs(stats.Sxm[n], stats.sx[n]);
                double an = a[n], nun = nu[n];
                if (std::abs(M.determinant()) > 1e-300) {
                    const Eigen::Vector2d sol = M.lu().solve(rhs);
                    an = sol[0];
                    nun = sol[1];
                }
                if (m_options.boundA && std::abs(an) > m_options.aMax) {
                    // Constrained maximum of the concave profile: clip, then nu given a.
                    an = std::clamp(an, -m_options.aMax, m_options.aMax);
                    nun = (stats.sx[n] - an * stats.sm[n]) / stats.N2[n];
                }
                a[n] = an;
                nu[n] = nun;
                const double qn = (stats.Sxx[n] - 2 * an * stats.Sxm[n] - 2 * nun * stats.sx[n]
                                   + an * an * stats.Smm[n] + 2 * an * nun * stats.sm[n] + nun * nun * stats.N2[n])
                                  / stats.N2[n];
                // A rare phone (§0) keeps its process noise: from a handful of frames it could
                // sit at the floor by chance.
                if (stats.N2[n] >= kMinimumVarianceFrames)
                    q[n] = std::max(qn, floor);
            }
        }
        if (m_options.sharedR) {
            const double shared = std::max(stats.Rsum.sum() / stats.Rn.sum(), floor);
            r.setConstant(shared);
        } else {
            for (int n = 0; n < P; ++n)
                if (stats.Rn[n] >= kMinimumVarianceFrames)
                    r[n] = std::max(stats.Rsum[n] / stats.Rn[n], floor);
        }
        for (int n = 0; n < P; ++n) {
            if (stats.N1[n] > 0) {
                mu[n] = stats.x1[n] / stats.N1[n];
                const double ss = stats.x1sq[n] - stats.N1[n] * mu[n] * mu[n];
                sigma[n] = std::max((m_options.kappa * s0[k] + ss) / (m_options.kappa + stats.N1[n]
                                                                      + (m_options.kappa > 0 ? 2.0 : 0.0)),
                                    floor);
            } else {
                mu[n] = st.mean(n, k);
                sigma[n] = st.variance(n, k);
            }
        }
        for (int n = 0; n < P; ++n) {
            p.A[size_t(n)](k, k) = a[n];
            p.Q[size_t(n)](k, k) = q[n];
            p.R[size_t(n)](k, k) = r[n];
            p.Sigma[size_t(n)](k, k) = sigma[n];
        }
        p.nu.col(k) = nu;
        p.mu.col(k) = mu;
    };
    if (m_options.threads == 1 || d == 1)
        std::for_each(dimensions.begin(), dimensions.end(), fitDimension);
    else
        lipsync::blockingMap(dimensions, fitDimension);
    double total = 0.0;
    for (double ll : perDimension)
        total += ll;
    return total;
}

double SldsModel::emMatrix(const std::vector<LabelledSequence> &sequences,
                           const FrameStatistics &st, const Eigen::VectorXd &s0)
{
    const int P = stateCount();
    const Eigen::Index d = m_dimension;
    slds::Parameters &p = m_params;
    const Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(d, d);
    std::vector<Eigen::MatrixXd> Sxx(size_t(P), Z), Smm(size_t(P), Z), Sxm(size_t(P), Z),
        Rsum(size_t(P), Z), X1(size_t(P), Z);
    Eigen::MatrixXd sx = Eigen::MatrixXd::Zero(P, d), sm = sx, x1 = sx;
    Eigen::VectorXd N2 = Eigen::VectorXd::Zero(P), Rn = N2, N1 = N2;
    double ll = 0.0;
    for (const LabelledSequence &s : sequences) {
        const slds::Smoothed sm_ = slds::smooth(p, s.labels, s.features);
        ll += sm_.logLikelihood;
        const size_t T = s.labels.size();
        for (size_t t = 0; t < T; ++t) {
            const int n = s.labels[t];
            const Eigen::VectorXd &x = sm_.mean[t];
            const Eigen::VectorXd e = s.features.row(Eigen::Index(t)).transpose() - x;
            Rsum[size_t(n)] += e * e.transpose() + sm_.covariance[t];
            Rn[n] += 1;
            if (t == 0) {
                x1.row(n) += x.transpose();
                X1[size_t(n)] += sm_.covariance[0] + x * x.transpose();
                N1[n] += 1;
                continue;
            }
            const Eigen::VectorXd &xm = sm_.mean[t - 1];
            Sxx[size_t(n)] += sm_.covariance[t] + x * x.transpose();
            Smm[size_t(n)] += sm_.covariance[t - 1] + xm * xm.transpose();
            Sxm[size_t(n)] += sm_.cross[t] + x * xm.transpose();
            sx.row(n) += x.transpose();
            sm.row(n) += xm.transpose();
            N2[n] += 1;
        }
    }
    const bool full = m_options.fullNoise;
    for (int n = 0; n < P; ++n)
        if (N1[n] > 0 && m_options.kappa > 0)
            for (Eigen::Index k = 0; k < d; ++k)
                ll += -(m_options.kappa / 2 + 1) * std::log(p.Sigma[size_t(n)](k, k))
                      - m_options.kappa * s0[k] / (2 * p.Sigma[size_t(n)](k, k));
    for (int n = 0; n < P; ++n) {
        const size_t i = size_t(n);
        if (N2[n] > 0) {
            // Augmented sums (§3.3): S^zz = [S^-- s^-; s^-T N], S^xz = [S^x- s^x].
            TransitionSums sums{Sxx[i], Eigen::MatrixXd(d, d + 1), Eigen::MatrixXd(d + 1, d + 1), N2[n]};
            sums.Szz << Smm[i], sm.row(n).transpose(), sm.row(n), N2[n];
            sums.Sxz << Sxm[i], sx.row(n).transpose();
            const Eigen::MatrixXd At = updateTransition(sums, p.A[i], p.nu.row(n).transpose(), p.Q[i], st.floor,
                                                        m_options);
            const Eigen::MatrixXd Q = sums.processNoise(At);
            p.A[i] = At.leftCols(d);
            p.nu.row(n) = At.col(d).transpose();
            if (N2[n] >= kMinimumVarianceFrames) // a rare phone (§0) keeps its process noise
                p.Q[i] = floorCovariance(Q, st.floor, full);
        }
        if (!m_options.sharedR && Rn[n] >= kMinimumVarianceFrames)
            p.R[i] = floorCovariance(Rsum[i] / Rn[n], st.floor, full);
        if (N1[n] > 0) {
            const Eigen::VectorXd m = x1.row(n).transpose() / N1[n];
            const Eigen::MatrixXd ss = X1[i] - N1[n] * m * m.transpose();
            const double denominator = m_options.kappa + N1[n] + (m_options.kappa > 0 ? 2.0 : 0.0);
            p.mu.row(n) = m.transpose();
            p.Sigma[i] = floorCovariance((Eigen::MatrixXd(m_options.kappa * s0.asDiagonal()) + ss)
                                             / denominator,
                                         st.floor, full);
        } else {
            p.mu.row(n) = st.mean.row(n);
            p.Sigma[i] = st.variance.row(n).transpose().asDiagonal();
        }
    }
    if (m_options.sharedR) {
        Eigen::MatrixXd total = Eigen::MatrixXd::Zero(d, d);
        for (const Eigen::MatrixXd &R : Rsum)
            total += R;
        const Eigen::MatrixXd shared = floorCovariance(total / Rn.sum(), st.floor, full);
        for (Eigen::MatrixXd &R : p.R)
            R = shared;
    }
    return ll;
}

LinearRecursion SldsModel::recursion() const
{
    LinearRecursion rec;
    rec.mu = m_params.mu;
    rec.nu = m_params.nu;
    if (m_options.fullA) {
        rec.full = m_params.A;
    } else {
        rec.a.resize(m_params.mu.rows(), m_params.mu.cols());
        for (size_t n = 0; n < m_params.A.size(); ++n)
            rec.a.row(Eigen::Index(n)) = m_params.A[n].diagonal().transpose();
    }
    return rec;
}

Eigen::MatrixXd SldsModel::generateMostLikely(const std::vector<int> &labels) const
{
    checkGenerationInput(labels);
    return recursion().generate(labels);
}

std::unique_ptr<StreamingGenerator> SldsModel::makeStreamer() const
{
    checkTrained();
    return recursion().streamer();
}

double SldsModel::logLikelihood(const std::vector<int> &labels, const Eigen::MatrixXd &Y) const
{
    checkScoringInput(labels, Y);
    if (!isDiagonal())
        return slds::kalmanLogLikelihood(m_params, labels, Y);
    // Scalar filters per dimension (§3.1 decoupling).
    double ll = 0.0;
    for (Eigen::Index k = 0; k < m_dimension; ++k) {
        double m = 0.0, P = 0.0;
        for (size_t t = 0; t < labels.size(); ++t) {
            const size_t n = size_t(labels[t]);
            if (t == 0) {
                m = m_params.mu(Eigen::Index(n), k);
                P = m_params.Sigma[n](k, k);
            } else {
                const double a = m_params.A[n](k, k);
                m = a * m + m_params.nu(Eigen::Index(n), k);
                P = a * a * P + m_params.Q[n](k, k);
            }
            const double R = m_params.R[n](k, k), S = P + R, K = P / S;
            const double eta = Y(Eigen::Index(t), k) - m;
            ll += -0.5 * (kLog2Pi + std::log(S) + eta * eta / S);
            m += K * eta;
            P = (1 - K) * (1 - K) * P + K * K * R;
        }
    }
    return ll;
}

QJsonObject SldsModel::parametersToJson() const
{
    QJsonObject o;
    o[QStringLiteral("fullA")] = m_options.fullA;
    o[QStringLiteral("fullNoise")] = m_options.fullNoise;
    o[QStringLiteral("sharedR")] = m_options.sharedR;
    o[QStringLiteral("nu")] = json::fromMatrix(m_params.nu);
    o[QStringLiteral("mu")] = json::fromMatrix(m_params.mu);
    auto list = [](const std::vector<Eigen::MatrixXd> &ms) {
        QJsonArray a;
        for (const Eigen::MatrixXd &m : ms)
            a.append(json::fromMatrix(m));
        return a;
    };
    o[QStringLiteral("A")] = list(m_params.A);
    o[QStringLiteral("Q")] = list(m_params.Q);
    o[QStringLiteral("R")] = list(m_params.R);
    o[QStringLiteral("Sigma")] = list(m_params.Sigma);
    return o;
}

void SldsModel::parametersFromJson(const QJsonObject &o, const std::string &file)
{
    const int P = stateCount();
    slds::Parameters p;
    p.nu = json::toMatrix(o, "nu", P, -1, file);
    const Eigen::Index d = p.nu.cols();
    p.mu = json::toMatrix(o, "mu", P, d, file);
    auto list = [&](const char *field, bool covariance) {
        const QJsonArray a = o.value(QLatin1String(field)).toArray();
        if (a.size() != P)
            throw Error("expected " + std::to_string(P) + " matrices", file, field);
        std::vector<Eigen::MatrixXd> ms;
        for (int n = 0; n < P; ++n) {
            QJsonObject wrapper;
            wrapper[QStringLiteral("m")] = a[n];
            Eigen::MatrixXd m = json::toMatrix(wrapper, "m", d, d, file);
            if (covariance && Eigen::LLT<Eigen::MatrixXd>(m).info() != Eigen::Success)
                throw Error("matrix " + std::to_string(n) + " is not positive definite", file, field);
            ms.push_back(std::move(m));
        }
        return ms;
    };
    p.A = list("A", false);
    p.Q = list("Q", true);
    p.R = list("R", true);
    p.Sigma = list("Sigma", true);
    m_options.fullA = o.value(QStringLiteral("fullA")).toBool();
    m_options.fullNoise = o.value(QStringLiteral("fullNoise")).toBool();
    m_options.sharedR = o.value(QStringLiteral("sharedR")).toBool();
    setParameters(p);
}

} // namespace lipsync
