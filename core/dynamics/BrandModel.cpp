#include "dynamics/BrandModel.h"

#include "dynamics/BrandStreamer.h"

#include "dynamics/GaussianMath.h"
#include "dynamics/JsonEigen.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <random>

namespace lipsync {

void BrandModel::shiftMeans(const Eigen::MatrixXd &shift)
{
    checkMeanShift(shift, staticMean.rows());
    staticMean += shift;
    if (fullCovariance())
        jointMean.leftCols(shift.cols()) += shift;
}

void BrandModel::fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    feedback.throwIfCanceled();
    const int P = stateCount();
    const FrameStatistics st = computeFrameStatistics(sequences, P);
    const Eigen::Index d = st.mean.cols();
    // Delta statistics over the transition frames T_n (the delta of frame t takes t's label).
    Eigen::MatrixXd dm = Eigen::MatrixXd::Zero(P, d), dv = Eigen::MatrixXd::Zero(P, d);
    Eigen::VectorXd gm = Eigen::VectorXd::Zero(d), gv = Eigen::VectorXd::Zero(d);
    long long transitions = 0;
    for (const LabelledSequence &s : sequences)
        for (Eigen::Index t = 1; t < s.features.rows(); ++t) {
            const Eigen::RowVectorXd delta = s.features.row(t) - s.features.row(t - 1);
            dm.row(s.labels[size_t(t)]) += delta;
            gm += delta.transpose();
            ++transitions;
        }
    if (transitions > 0)
        gm /= double(transitions);
    for (int n = 0; n < P; ++n)
        if (st.transitionCount[n] > 0)
            dm.row(n) /= double(st.transitionCount[n]);
    for (const LabelledSequence &s : sequences)
        for (Eigen::Index t = 1; t < s.features.rows(); ++t) {
            const int n = s.labels[size_t(t)];
            const Eigen::RowVectorXd delta = s.features.row(t) - s.features.row(t - 1);
            dv.row(n) += (delta - dm.row(n)).array().square().matrix();
            gv += (delta.transpose() - gm).array().square().matrix();
        }
    // [choice] Back-off for phones without transition frames: the global delta statistics; with
    // no transition frames at all, zero mean and twice the static variance.
    if (transitions > 0)
        gv = (gv / double(transitions)).cwiseMax(st.floor);
    else
        gv = 2.0 * st.globalVariance;
    for (int n = 0; n < P; ++n) {
        if (st.transitionCount[n] >= kMinimumVarianceFrames) {
            dv.row(n) = (dv.row(n) / double(st.transitionCount[n])).cwiseMax(st.floor.transpose());
        } else if (st.transitionCount[n] > 0) {
            dv.row(n) = gv.transpose(); // a rare phone (§0): its own delta mean, the global variance
        } else {
            dm.row(n) = gm.transpose();
            dv.row(n) = gv.transpose();
        }
    }
    staticMean = st.mean;
    staticVariance = st.variance;
    deltaMean = dm;
    deltaVariance = dv;
    jointMean.resize(0, 0);
    jointCovariance.clear();
    m_dimension = int(d);
    bool full = m_options.covariance == BrandCovariance::Full;
    m_choice = {};
    if (m_options.covariance == BrandCovariance::CrossValidated) {
        m_choice = crossValidateCovariance(sequences, feedback);
        full = m_choice.folds > 0 && m_choice.fullL1 < m_choice.diagonalL1;
    }
    if (full)
        fitFull(sequences, st.floor);
    m_chosenLag = 0;
    if (m_options.lag <= 0)
        m_chosenLag = chooseStreamingLag(sequences, feedback);
    feedback.setProgress(1.0);
}

BrandModel::CovarianceChoice BrandModel::crossValidateCovariance(const std::vector<LabelledSequence> &sequences,
                                                                  Feedback &feedback) const
{
    CovarianceChoice choice;
    const int S = int(sequences.size());
    choice.folds = std::min(kCovarianceFolds, S);
    if (choice.folds < 2) {
        choice.folds = 0; // nothing to hold out: the paper's diagonal
        return choice;
    }
    std::vector<int> order(static_cast<size_t>(S));
    std::iota(order.begin(), order.end(), 0);
    std::mt19937 random(kCovarianceSeed);
    std::shuffle(order.begin(), order.end(), random);
    // Mean over held-out sequences of their mean per-frame L1 (§6.2, sequences weigh equally).
    double l1[2] = {0.0, 0.0};
    for (int fold = 0; fold < choice.folds; ++fold) {
        std::vector<LabelledSequence> training, heldOut;
        for (int i = 0; i < S; ++i)
            (i % choice.folds == fold ? heldOut : training).push_back(sequences[size_t(order[size_t(i)])]);
        for (int full = 0; full < 2; ++full) {
            const double step = 1.0 / double(2 * choice.folds + 1), from = double(2 * fold + full) * step;
            Feedback part(feedback, from, from + step);
            BrandOptions options = m_options;
            options.covariance = full ? BrandCovariance::Full : BrandCovariance::Diagonal;
            options.lag = 1; // only the exact solve is used: no lag to choose
            BrandModel model(options);
            model.setStateCount(stateCount());
            model.train(training, part);
            for (const LabelledSequence &s : heldOut)
                l1[full] += (model.generateMostLikely(s.labels) - s.features).cwiseAbs().rowwise().sum().mean();
        }
    }
    choice.diagonalL1 = l1[0] / double(S);
    choice.fullL1 = l1[1] / double(S);
    return choice;
}

void BrandModel::fitFull(const std::vector<LabelledSequence> &sequences,
                         const Eigen::VectorXd &floor)
{
    // [choice, §2.1] Mean and ML covariance of o_t over T_n only.
    const int P = stateCount();
    const Eigen::Index d = m_dimension, D = 2 * d;
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(P, D);
    std::vector<Eigen::MatrixXd> outer(size_t(P), Eigen::MatrixXd::Zero(D, D));
    Eigen::VectorXi count = Eigen::VectorXi::Zero(P);
    Eigen::VectorXd o(D);
    for (const LabelledSequence &s : sequences)
        for (Eigen::Index t = 1; t < s.features.rows(); ++t) {
            const int n = s.labels[size_t(t)];
            o.head(d) = s.features.row(t).transpose();
            o.tail(d) = (s.features.row(t) - s.features.row(t - 1)).transpose();
            sum.row(n) += o.transpose();
            outer[size_t(n)].selfadjointView<Eigen::Lower>().rankUpdate(o);
            ++count[n];
        }
    Eigen::VectorXd jointFloor(D);
    jointFloor << floor, floor;
    jointMean.resize(P, D);
    jointCovariance.assign(size_t(P), Eigen::MatrixXd());
    for (int n = 0; n < P; ++n) {
        Eigen::VectorXd mean(D);
        mean << staticMean.row(n).transpose(), deltaMean.row(n).transpose();
        Eigen::MatrixXd C;
        // [choice] With fewer transition frames than 2d + 1 the ML covariance is singular: use
        // the diagonal statistics (the back-off of the diagonal model) instead.
        if (count[n] > D) {
            mean = sum.row(n).transpose() / double(count[n]);
            C = outer[size_t(n)].selfadjointView<Eigen::Lower>();
            C = C / double(count[n]) - mean * mean.transpose();
            C = floorEigenvalues(C, jointFloor.minCoeff());
        } else {
            Eigen::VectorXd diag(D);
            diag << staticVariance.row(n).transpose(), deltaVariance.row(n).transpose();
            C = diag.asDiagonal();
        }
        jointMean.row(n) = mean.transpose();
        jointCovariance[size_t(n)] = C;
    }
}

Eigen::MatrixXd BrandModel::jointPrecision(int n) const
{
    const Eigen::Index d = m_dimension;
    if (jointCovariance.empty()) {
        Eigen::VectorXd precision(2 * d);
        precision << staticVariance.row(n).transpose().cwiseInverse(),
            deltaVariance.row(n).transpose().cwiseInverse();
        return precision.asDiagonal();
    }
    const Eigen::MatrixXd &C = jointCovariance[size_t(n)];
    return C.llt().solve(Eigen::MatrixXd::Identity(C.rows(), C.cols()));
}

Eigen::MatrixXd BrandModel::staticPrecision(int n) const
{
    const Eigen::Index d = m_dimension;
    if (jointCovariance.empty())
        return staticVariance.row(n).transpose().cwiseInverse().asDiagonal();
    const Eigen::MatrixXd C = jointCovariance[size_t(n)].topLeftCorner(d, d);
    return C.llt().solve(Eigen::MatrixXd::Identity(d, d));
}

brand::TridiagonalSystem BrandModel::tridiagonalSystem(const std::vector<int> &labels, int k) const
{
    const Eigen::Index T = Eigen::Index(labels.size());
    Eigen::VectorXd p(T), m(T), q(T), delta(T);
    for (Eigen::Index t = 0; t < T; ++t) {
        const int n = labels[size_t(t)];
        p[t] = 1.0 / staticVariance(n, k);
        m[t] = staticMean(n, k);
        q[t] = t > 0 ? 1.0 / deltaVariance(n, k) : 0.0;
        delta[t] = t > 0 ? deltaMean(n, k) : 0.0;
    }
    return brand::buildTridiagonal(p, m, q, delta);
}

Eigen::MatrixXd BrandModel::generateMostLikely(const std::vector<int> &labels) const
{
    checkGenerationInput(labels);
    if (!jointCovariance.empty())
        return generateBlock(labels);
    // The d tridiagonal LDL^T solves of §2.2, run side by side (one column of d values per frame,
    // contiguous, so the per-frame arithmetic vectorises). Same operations as solveTridiagonal.
    const Eigen::Index T = Eigen::Index(labels.size()), d = m_dimension;
    const Eigen::ArrayXXd p = staticVariance.array().inverse().transpose();  // d x P
    const Eigen::ArrayXXd pm = p * staticMean.array().transpose();
    const Eigen::ArrayXXd q = deltaVariance.array().inverse().transpose();
    const Eigen::ArrayXXd qd = q * deltaMean.array().transpose();
    Eigen::ArrayXXd pivot(d, T), l(d, T), z(d, T), y(d, T);
    Eigen::ArrayXd alpha(d), b(d);
    for (Eigen::Index t = 0; t < T; ++t) {
        const int n = labels[size_t(t)];
        // alpha_t = p_t + q_t + q_{t+1}, b_t = p_t m_t + q_t delta_t - q_{t+1} delta_{t+1}
        alpha = p.col(n);
        b = pm.col(n);
        if (t + 1 < T) {
            const int next = labels[size_t(t + 1)];
            alpha += q.col(next);
            b -= qd.col(next);
        }
        if (t == 0) {
            pivot.col(0) = alpha;
            z.col(0) = b;
            continue;
        }
        alpha += q.col(n);
        b += qd.col(n);
        // beta_{t-1} = -q_t
        l.col(t) = -q.col(n) / pivot.col(t - 1);
        pivot.col(t) = alpha + l.col(t) * q.col(n);
        z.col(t) = b - l.col(t) * z.col(t - 1);
    }
    y.col(T - 1) = z.col(T - 1) / pivot.col(T - 1);
    for (Eigen::Index t = T - 2; t >= 0; --t)
        y.col(t) = z.col(t) / pivot.col(t) - l.col(t + 1) * y.col(t + 1);
    return y.matrix().transpose();
}

brand::BlockTerms BrandModel::blockTerms(int n, bool first) const
{
    // §2.2, general full-covariance form: the static term of y_t and the delta term of
    // y_t - y_{t-1}, both under state n's precision.
    const Eigen::Index d = m_dimension;
    const Eigen::VectorXd my = jointCovariance.empty() ? Eigen::VectorXd(staticMean.row(n).transpose())
                                                       : Eigen::VectorXd(jointMean.row(n).head(d).transpose());
    brand::BlockTerms terms;
    if (first) {
        terms.diagonal = staticPrecision(n);
        terms.rhs = terms.diagonal * my;
        terms.previousDiagonal = Eigen::MatrixXd::Zero(d, d);
        terms.lower = Eigen::MatrixXd::Zero(d, d);
        terms.previousRhs = Eigen::VectorXd::Zero(d);
        return terms;
    }
    const Eigen::VectorXd md = jointCovariance.empty() ? Eigen::VectorXd(deltaMean.row(n).transpose())
                                                       : Eigen::VectorXd(jointMean.row(n).tail(d).transpose());
    const Eigen::MatrixXd L = jointPrecision(n);
    const auto Lyy = L.topLeftCorner(d, d), LyD = L.topRightCorner(d, d);
    const auto LDy = L.bottomLeftCorner(d, d), LDD = L.bottomRightCorner(d, d);
    terms.diagonal = Lyy + LyD + LDy + LDD;
    terms.previousDiagonal = LDD;
    terms.lower = -(LyD + LDD); // H_{t,t-1}
    terms.rhs = (Lyy + LDy) * my + (LyD + LDD) * md;
    terms.previousRhs = -(LDy * my + LDD * md);
    return terms;
}

brand::BlockTridiagonalSystem BrandModel::blockSystem(const std::vector<int> &labels) const
{
    // §2.2, accumulated frame by frame from each state's terms (computed once per state).
    const Eigen::Index d = m_dimension;
    const size_t T = labels.size();
    std::vector<std::optional<brand::BlockTerms>> terms(static_cast<size_t>(stateCount()));
    brand::BlockTridiagonalSystem s;
    s.diagonal.assign(T, Eigen::MatrixXd::Zero(d, d));
    s.lower.assign(T > 0 ? T - 1 : 0, Eigen::MatrixXd::Zero(d, d));
    s.rhs = Eigen::MatrixXd::Zero(d, Eigen::Index(T));
    for (size_t t = 0; t < T; ++t) {
        const int n = labels[t];
        if (t == 0) {
            const brand::BlockTerms first = blockTerms(n, true);
            s.diagonal[0] += first.diagonal;
            s.rhs.col(0) += first.rhs;
            continue;
        }
        if (!terms[size_t(n)])
            terms[size_t(n)] = blockTerms(n, false);
        const brand::BlockTerms &f = *terms[size_t(n)];
        s.diagonal[t] += f.diagonal;
        s.diagonal[t - 1] += f.previousDiagonal;
        s.lower[t - 1] += f.lower;
        s.rhs.col(Eigen::Index(t)) += f.rhs;
        s.rhs.col(Eigen::Index(t - 1)) += f.previousRhs;
    }
    return s;
}

Eigen::MatrixXd BrandModel::generateBlock(const std::vector<int> &labels) const
{
    checkGenerationInput(labels);
    return brand::solveBlockTridiagonal(blockSystem(labels)).transpose();
}

void BrandModel::denseReferenceSystem(const std::vector<int> &labels, Eigen::MatrixXd &H,
                                      Eigen::VectorXd &b) const
{
    // Explicit W (static window [1], delta window [-1, 1]), block-diagonal Lambda and stacked
    // means M: H = W^T Lambda W, b = W^T Lambda M (§2.2).
    const Eigen::Index d = m_dimension, T = Eigen::Index(labels.size());
    const Eigen::Index rows = d + 2 * d * (T - 1);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(rows, d * T), Lambda = Eigen::MatrixXd::Zero(rows, rows);
    Eigen::VectorXd M(rows);
    const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(d, d);
    Eigen::Index r = 0;
    for (Eigen::Index t = 0; t < T; ++t) {
        const int n = labels[size_t(t)];
        Eigen::VectorXd mean(2 * d);
        if (jointCovariance.empty())
            mean << staticMean.row(n).transpose(), deltaMean.row(n).transpose();
        else
            mean = jointMean.row(n).transpose();
        if (t == 0) {
            W.block(0, 0, d, d) = I;
            Lambda.block(0, 0, d, d) = staticPrecision(n);
            M.head(d) = mean.head(d);
            r = d;
            continue;
        }
        W.block(r, t * d, d, d) = I;
        W.block(r + d, t * d, d, d) = I;
        W.block(r + d, (t - 1) * d, d, d) = -I;
        Lambda.block(r, r, 2 * d, 2 * d) = jointPrecision(n);
        M.segment(r, 2 * d) = mean;
        r += 2 * d;
    }
    H = W.transpose() * Lambda * W;
    b = W.transpose() * Lambda * M;
}

Eigen::MatrixXd BrandModel::generateDenseReference(const std::vector<int> &labels) const
{
    checkGenerationInput(labels);
    Eigen::MatrixXd H;
    Eigen::VectorXd b;
    denseReferenceSystem(labels, H, b);
    const Eigen::VectorXd y = H.llt().solve(b);
    return Eigen::Map<const Eigen::MatrixXd>(y.data(), m_dimension, Eigen::Index(labels.size()))
        .transpose();
}

double BrandModel::logLikelihood(const std::vector<int> &labels, const Eigen::MatrixXd &Y) const
{
    checkScoringInput(labels, Y);
    const Eigen::Index d = m_dimension;
    double ll = 0.0;
    if (jointCovariance.empty()) {
        for (Eigen::Index t = 0; t < Y.rows(); ++t) {
            const int n = labels[size_t(t)];
            ll += diagonalGaussianLogPdf(Y.row(t).transpose(), staticMean.row(n).transpose(),
                                         staticVariance.row(n).transpose());
            if (t > 0)
                ll += diagonalGaussianLogPdf((Y.row(t) - Y.row(t - 1)).transpose(),
                                             deltaMean.row(n).transpose(),
                                             deltaVariance.row(n).transpose());
        }
        return ll;
    }
    auto logPdf = [](const Eigen::VectorXd &z, const Eigen::VectorXd &m, const Eigen::MatrixXd &C) {
        const Eigen::LLT<Eigen::MatrixXd> llt(C);
        const Eigen::VectorXd w = llt.matrixL().solve(z - m);
        const double logDet = 2.0 * llt.matrixL().toDenseMatrix().diagonal().array().log().sum();
        return -0.5 * (double(z.size()) * kLog2Pi + logDet + w.squaredNorm());
    };
    for (Eigen::Index t = 0; t < Y.rows(); ++t) {
        const int n = labels[size_t(t)];
        const Eigen::MatrixXd &C = jointCovariance[size_t(n)];
        if (t == 0) {
            ll += logPdf(Y.row(0).transpose(), jointMean.row(n).head(d).transpose(),
                         C.topLeftCorner(d, d));
        } else {
            Eigen::VectorXd o(2 * d);
            o << Y.row(t).transpose(), (Y.row(t) - Y.row(t - 1)).transpose();
            ll += logPdf(o, jointMean.row(n).transpose(), C);
        }
    }
    return ll;
}

double BrandModel::trajectoryLogLikelihood(const std::vector<int> &labels,
                                           const Eigen::MatrixXd &Y) const
{
    checkScoringInput(labels, Y);
    const Eigen::Index T = Y.rows();
    if (!jointCovariance.empty()) {
        // Block form: log|H| = sum_t log|D_t| over the block LDL^T pivots, and e^T H e from the
        // diagonal and sub-diagonal blocks. O(d^3 T), like generation.
        const brand::BlockTridiagonalSystem s = blockSystem(labels);
        const Eigen::MatrixXd e = Y.transpose() - brand::solveBlockTridiagonal(s); // d x T
        double logDet = 0.0, quadratic = 0.0;
        Eigen::MatrixXd pivot = s.diagonal[0];
        for (Eigen::Index t = 0; t < T; ++t) {
            if (t > 0) {
                const Eigen::MatrixXd L = Eigen::LLT<Eigen::MatrixXd>(pivot)
                                              .solve(s.lower[size_t(t - 1)].transpose())
                                              .transpose();
                pivot = s.diagonal[size_t(t)] - L * s.lower[size_t(t - 1)].transpose();
                quadratic += 2.0 * e.col(t).dot(s.lower[size_t(t - 1)] * e.col(t - 1));
            }
            const Eigen::LLT<Eigen::MatrixXd> llt(pivot);
            logDet += 2.0 * llt.matrixLLT().diagonal().array().log().sum();
            quadratic += e.col(t).dot(s.diagonal[size_t(t)] * e.col(t));
        }
        return -0.5 * double(e.size()) * kLog2Pi + 0.5 * logDet - 0.5 * quadratic;
    }
    double ll = -0.5 * double(m_dimension * T) * kLog2Pi;
    for (int k = 0; k < m_dimension; ++k) {
        const brand::TridiagonalSystem s = tridiagonalSystem(labels, k);
        Eigen::VectorXd pivots;
        const Eigen::VectorXd e = Y.col(k) - brand::solveTridiagonal(s, &pivots);
        double quadratic = (s.alpha.array() * e.array().square()).sum();
        for (Eigen::Index t = 0; t + 1 < T; ++t)
            quadratic += 2.0 * s.beta[t] * e[t] * e[t + 1];
        ll += 0.5 * pivots.array().log().sum() - 0.5 * quadratic;
    }
    return ll;
}

double BrandModel::contraction() const
{
    checkTrained();
    const double qMax = deltaVariance.cwiseInverse().maxCoeff();
    const double pMin = staticVariance.cwiseInverse().minCoeff();
    return qMax / (qMax + pMin);
}

int BrandModel::streamingLag() const
{
    if (m_options.lag > 0)
        return m_options.lag;
    if (m_chosenLag > 0)
        return m_chosenLag;
    const double rho = contraction();
    if (rho <= 0.0)
        return 1;
    return int(std::clamp(std::ceil(std::log(1e-3) / std::log(rho)), 1.0, double(kMaximumLag)));
}

std::unique_ptr<StreamingGenerator> BrandModel::makeStreamer() const
{
    checkTrained();
    return FixedLagStreamers(*this).make(streamingLag());
}

int BrandModel::chooseStreamingLag(const std::vector<LabelledSequence> &sequences, Feedback &feedback) const
{
    // [choice, §5] rho bounds the error with the slowest phone's delta precision against the
    // loosest phone's static one together; on real models that bound asks for hundreds of frames
    // where a handful do. The lag is measured instead, on the training sequences (their first
    // kLagCheckFrames frames): the smallest lag at which the streamed frames lie, in mean L1
    // (§6.2), within kStreamingShare of the exact solve's own distance from the recorded frames.
    constexpr long long kLagCheckFrames = 3000;
    std::vector<const std::vector<int> *> labels;
    std::vector<Eigen::MatrixXd> exact;
    double modelL1 = 0.0;
    long long frames = 0;
    for (const LabelledSequence &s : sequences) {
        if (frames >= kLagCheckFrames)
            break;
        if (s.labels.size() < 2)
            continue;
        labels.push_back(&s.labels);
        exact.push_back(generateMostLikely(s.labels));
        modelL1 += (exact.back() - s.features).cwiseAbs().sum();
        frames += (long long)s.labels.size();
    }
    // One copy of the model and of the full covariances' terms for all the streamers tried.
    const FixedLagStreamers streamers(*this);
    auto withinTolerance = [&](int lag) {
        feedback.throwIfCanceled();
        Eigen::VectorXd frame(m_dimension);
        double streamingL1 = 0.0;
        for (size_t k = 0; k < labels.size(); ++k) {
            const std::unique_ptr<StreamingGenerator> streamer = streamers.make(lag);
            for (int label : *labels[k])
                streamer->push(label);
            streamer->finish();
            for (Eigen::Index t = 0; streamer->pop(frame); ++t)
                streamingL1 += (frame - exact[k].row(t).transpose()).cwiseAbs().sum();
        }
        return streamingL1 <= kStreamingShare * modelL1;
    };
    int fails = 0, passes = 1;
    while (passes < kMaximumLag && !withinTolerance(passes)) {
        fails = passes;
        passes = std::min(2 * passes, kMaximumLag);
    }
    while (passes - fails > 1) {
        const int mid = (fails + passes) / 2;
        (withinTolerance(mid) ? passes : fails) = mid;
    }
    return passes;
}

QJsonObject BrandModel::covarianceJson() const
{
    QJsonObject o{{QStringLiteral("covariance"), fullCovariance() ? QStringLiteral("full") : QStringLiteral("diagonal")}};
    if (m_choice.folds > 0)
        o[QStringLiteral("covarianceChoice")] = QJsonObject{{QStringLiteral("folds"), m_choice.folds},
                                                            {QStringLiteral("diagonalL1"), m_choice.diagonalL1},
                                                            {QStringLiteral("fullL1"), m_choice.fullL1}};
    return o;
}

QJsonObject BrandModel::parametersToJson() const
{
    QJsonObject o = covarianceJson();
    o[QStringLiteral("lag")] = m_options.lag;
    if (m_chosenLag > 0)
        o[QStringLiteral("streamingLag")] = m_chosenLag;
    o[QStringLiteral("staticMean")] = json::fromMatrix(staticMean);
    o[QStringLiteral("staticVariance")] = json::fromMatrix(staticVariance);
    o[QStringLiteral("deltaMean")] = json::fromMatrix(deltaMean);
    o[QStringLiteral("deltaVariance")] = json::fromMatrix(deltaVariance);
    if (!jointCovariance.empty()) {
        o[QStringLiteral("jointMean")] = json::fromMatrix(jointMean);
        QJsonArray covariances;
        for (const Eigen::MatrixXd &C : jointCovariance)
            covariances.append(json::fromMatrix(C));
        o[QStringLiteral("jointCovariance")] = covariances;
    }
    return o;
}

void BrandModel::parametersFromJson(const QJsonObject &o, const std::string &file)
{
    const int P = stateCount();
    staticMean = json::toMatrix(o, "staticMean", P, -1, file);
    const Eigen::Index d = staticMean.cols();
    staticVariance = json::toMatrix(o, "staticVariance", P, d, file);
    deltaMean = json::toMatrix(o, "deltaMean", P, d, file);
    deltaVariance = json::toMatrix(o, "deltaVariance", P, d, file);
    if ((staticVariance.array() <= 0).any() || (deltaVariance.array() <= 0).any())
        throw Error("variances must be positive", file, "staticVariance/deltaVariance");
    m_options.lag = o.value(QStringLiteral("lag")).toInt(0);
    m_chosenLag = 0;
    if (o.contains(QStringLiteral("streamingLag"))) {
        m_chosenLag = o.value(QStringLiteral("streamingLag")).toInt(0);
        if (m_chosenLag < 1 || m_chosenLag > kMaximumLag)
            throw Error("must be a whole number of frames from 1 to " + std::to_string(kMaximumLag), file,
                        "streamingLag");
    }
    m_choice = {};
    if (o.contains(QStringLiteral("covarianceChoice"))) {
        const QJsonObject c = o.value(QStringLiteral("covarianceChoice")).toObject();
        m_choice.folds = c.value(QStringLiteral("folds")).toInt(0);
        m_choice.diagonalL1 = c.value(QStringLiteral("diagonalL1")).toDouble(-1.0);
        m_choice.fullL1 = c.value(QStringLiteral("fullL1")).toDouble(-1.0);
        if (m_choice.folds < 2 || !(m_choice.diagonalL1 >= 0.0) || !(m_choice.fullL1 >= 0.0))
            throw Error("needs folds (2 or more) and the non-negative diagonalL1 and fullL1", file,
                        "covarianceChoice");
    }
    const QString covariance = o.value(QStringLiteral("covariance")).toString();
    jointMean.resize(0, 0);
    jointCovariance.clear();
    if (covariance == QLatin1String("full")) {
        m_options.covariance = BrandCovariance::Full;
        jointMean = json::toMatrix(o, "jointMean", P, 2 * d, file);
        const QJsonArray covariances = o.value(QStringLiteral("jointCovariance")).toArray();
        if (covariances.size() != P)
            throw Error("expected " + std::to_string(P) + " matrices", file, "jointCovariance");
        for (int n = 0; n < P; ++n) {
            QJsonObject wrapper;
            wrapper[QStringLiteral("c")] = covariances[n];
            Eigen::MatrixXd C = json::toMatrix(wrapper, "c", 2 * d, 2 * d, file);
            if (Eigen::LLT<Eigen::MatrixXd>(C).info() != Eigen::Success)
                throw Error("matrix " + std::to_string(n) + " is not positive definite", file,
                            "jointCovariance");
            jointCovariance.push_back(std::move(C));
        }
    } else if (covariance == QLatin1String("diagonal")) {
        m_options.covariance = BrandCovariance::Diagonal;
    } else {
        throw Error("must be \"diagonal\" or \"full\"", file, "covariance");
    }
    m_dimension = int(d);
}

} // namespace lipsync
