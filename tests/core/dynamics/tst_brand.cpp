// Brand / MLPG checks of docs/models.md §7 (items 11-16) and the HMM-mean limit.
#include "SyntheticDynamics.h"

#include "dynamics/BrandModel.h"
#include "dynamics/HmmMeanModel.h"
#include "tasks/Feedback.h"

#include <QTest>

#include "util/Error.h"

#include <QJsonObject>

#include <Eigen/Cholesky>

#include <numeric>
#include <random>

using namespace lipsync;
using namespace lipsync::test;

namespace {

std::vector<LabelledSequence> trainingData(unsigned seed, int d, int sequences = 30, int frames = 40)
{
    std::mt19937 rng(seed);
    const DpdsTruth truth = randomDpdsTruth(rng, d, 0.1);
    return dpdsDataset(rng, truth, {0, 2, 6, 9, 21, 26, 35}, sequences, frames);
}

BrandModel trained(const std::vector<LabelledSequence> &data, bool full = false, int lag = 0)
{
    BrandOptions options;
    options.covariance = full ? BrandCovariance::Full : BrandCovariance::Diagonal;
    options.lag = lag;
    BrandModel model(options);
    Feedback feedback;
    model.train(data, feedback);
    return model;
}

double maxAbs(const Eigen::MatrixXd &m) { return m.cwiseAbs().maxCoeff(); }

// Streams `labels` through the model's fixed-lag streamer; *onTime turns false if frame t is not
// out exactly when label t + L is in.
Eigen::MatrixXd streamed(const BrandModel &model, const std::vector<int> &labels, int lag, bool *onTime)
{
    auto stream = model.streamer();
    *onTime = stream->latency() == lag;
    Eigen::MatrixXd out(Eigen::Index(labels.size()), model.dimension());
    Eigen::VectorXd frame(model.dimension());
    Eigen::Index next = 0;
    for (size_t t = 0; t < labels.size(); ++t) {
        stream->push(labels[t]);
        while (stream->pop(frame))
            out.row(next++) = frame.transpose();
        *onTime = *onTime && next == std::max<Eigen::Index>(0, Eigen::Index(t) - lag + 1);
    }
    stream->finish();
    while (stream->pop(frame))
        out.row(next++) = frame.transpose();
    *onTime = *onTime && next == out.rows();
    return out;
}

} // namespace

class TestBrand : public QObject
{
    Q_OBJECT
private slots:
    // §7.11
    void tridiagonalSystemMatchesDenseConstruction()
    {
        const auto data = trainingData(1, 3);
        const BrandModel model = trained(data);
        std::mt19937 rng(2);
        const std::vector<int> labels = randomLabels(rng, 12, {0, 6, 21, 11});
        Eigen::MatrixXd H;
        Eigen::VectorXd b;
        model.denseReferenceSystem(labels, H, b);
        const Eigen::Index T = Eigen::Index(labels.size()), d = 3;
        for (int k = 0; k < d; ++k) {
            const brand::TridiagonalSystem s = model.tridiagonalSystem(labels, k);
            for (Eigen::Index t = 0; t < T; ++t) {
                QVERIFY(std::abs(s.alpha[t] - H(t * d + k, t * d + k)) < 1e-9 * s.alpha[t]);
                QVERIFY(std::abs(s.b[t] - b[t * d + k]) < 1e-9 * (1 + std::abs(s.b[t])));
                if (t + 1 < T)
                    QVERIFY(std::abs(s.beta[t] - H(t * d + k, (t + 1) * d + k)) < 1e-9 * std::abs(s.alpha[t]));
            }
        }
        const Eigen::MatrixXd tri = model.generate(labels);
        const Eigen::MatrixXd dense = model.generateDenseReference(labels);
        QVERIFY(maxAbs(tri - dense) < 1e-9 * (1 + maxAbs(dense)));
    }

    // §7.12
    void fullCovarianceBlockSolve()
    {
        const auto data = trainingData(3, 2, 60, 50);
        const BrandModel model = trained(data, true);
        QVERIFY(!model.jointCovariance.empty());
        std::mt19937 rng(4);
        const std::vector<int> labels = randomLabels(rng, 15, {0, 6, 21, 26});
        const Eigen::MatrixXd block = model.generate(labels);
        const Eigen::MatrixXd dense = model.generateDenseReference(labels);
        QVERIFY(maxAbs(block - dense) < 1e-9 * (1 + maxAbs(dense)));
        // Also the assembled block system equals the explicit W^T Lambda W.
        Eigen::MatrixXd H;
        Eigen::VectorXd b;
        model.denseReferenceSystem(labels, H, b);
        const brand::BlockTridiagonalSystem s = model.blockSystem(labels);
        QVERIFY(maxAbs(brand::denseMatrix(s) - H) < 1e-9 * maxAbs(H));
        QVERIFY((brand::denseRhs(s) - b).cwiseAbs().maxCoeff() < 1e-9 * b.cwiseAbs().maxCoeff());
        QVERIFY(maxAbs(brand::solveDense(s).transpose() - dense) < 1e-9 * (1 + maxAbs(dense)));
        // The gradient of the objective vanishes at the solution (central differences).
        const double h = 1e-5;
        for (Eigen::Index t = 0; t < block.rows(); t += 3)
            for (Eigen::Index k = 0; k < 2; ++k) {
                Eigen::MatrixXd up = block, down = block;
                up(t, k) += h;
                down(t, k) -= h;
                const double g = (model.logLikelihood(labels, up) - model.logLikelihood(labels, down)) / (2 * h);
                QVERIFY2(std::abs(g) < 1e-4 * H(t * 2 + k, t * 2 + k), qPrintable(QString::number(g)));
            }
        // The objective is -(1/2 Y^T H Y - b^T Y) + c: c is the same for any Y.
        auto constant = [&](const Eigen::MatrixXd &Y) {
            const Eigen::MatrixXd Yt = Y.transpose();
            const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(Yt.data(), Yt.size());
            return model.logLikelihood(labels, Y) + 0.5 * y.dot(H * y) - b.dot(y);
        };
        Eigen::MatrixXd other = block;
        other.array() += 0.3;
        other(3, 1) -= 1.0;
        QVERIFY(std::abs(constant(block) - constant(other)) < 1e-8 * (1 + std::abs(constant(block))));
    }

    // §7.13
    void blockSolverWithDiagonalCovarianceEqualsTridiagonal()
    {
        const auto data = trainingData(5, 4);
        const BrandModel model = trained(data);
        std::mt19937 rng(6);
        const std::vector<int> labels = randomLabels(rng, 100, {0, 2, 6, 21, 35});
        QVERIFY(maxAbs(model.generateBlock(labels) - model.generate(labels)) < 1e-10 * (1 + maxAbs(model.generate(labels))));
    }

    // §7.14
    void limitsGiveHmmMean()
    {
        const auto data = trainingData(7, 2);
        BrandModel model = trained(data);
        HmmMeanModel hmm;
        Feedback feedback;
        hmm.train(data, feedback);
        QVERIFY(maxAbs(model.staticMean - hmm.means()) < 1e-12);
        std::mt19937 rng(8);
        const std::vector<int> labels = randomLabels(rng, 50, {0, 6, 21});
        model.deltaVariance.setConstant(1e14); // q -> 0
        QVERIFY(maxAbs(model.generate(labels) - hmm.generate(labels)) < 1e-6);
        // Constant labels with zero delta mean reproduce the static mean exactly.
        model = trained(data);
        model.deltaMean.setZero();
        const std::vector<int> constant(30, 6);
        const Eigen::MatrixXd Y = model.generate(constant);
        for (Eigen::Index t = 0; t < Y.rows(); ++t)
            QVERIFY((Y.row(t) - model.staticMean.row(6)).cwiseAbs().maxCoeff() < 1e-10);
    }

    // §7.15
    void fixedLagStreaming()
    {
        const auto data = trainingData(9, 3);
        const BrandModel reference = trained(data);
        std::mt19937 rng(10);
        const std::vector<int> labels = randomLabels(rng, 120, {0, 2, 6, 9, 21, 26, 35});
        const Eigen::MatrixXd exact = reference.generate(labels);
        // |l_t| <= q_t / (p_{t-1} + q_t)
        for (int k = 0; k < 3; ++k) {
            Eigen::VectorXd pivots, l;
            const brand::TridiagonalSystem s = reference.tridiagonalSystem(labels, k);
            brand::solveTridiagonal(s, &pivots, &l);
            for (size_t t = 1; t < labels.size(); ++t) {
                const double q = 1.0 / reference.deltaVariance(labels[t], k);
                const double p = 1.0 / reference.staticVariance(labels[t - 1], k);
                QVERIFY(std::abs(l[Eigen::Index(t)]) <= q / (p + q) * (1 + 1e-12));
            }
        }
        double previousError = INFINITY;
        for (int lag : {2, 5, 10, 20}) {
            const BrandModel model = trained(data, false, lag);
            bool onTime = false;
            const Eigen::MatrixXd streamed = ::streamed(model, labels, lag, &onTime);
            QVERIFY(onTime); // frame t is ready once label t + L is known
            // Error bound rho^{h-t} x end error; exact when h = T.
            const double rho = model.contraction();
            double maxError = 0;
            for (Eigen::Index t = 0; t < exact.rows(); ++t) {
                const double error = (streamed.row(t) - exact.row(t)).cwiseAbs().maxCoeff();
                maxError = std::max(maxError, error);
                if (t + lag >= exact.rows())
                    QVERIFY(error < 1e-9);
            }
            QVERIFY(maxError <= previousError + 1e-15);
            previousError = maxError;
            qInfo("lag %d: rho %.3f, max error %.3g", lag, rho, maxError);
        }
        QVERIFY(previousError < 1e-3);
        // The bound itself: the solve truncated at h is the exact solve of the prefix 1..h, and
        // |y^(h)_t - y_t| <= rho^(h-t) |y^(h)_h - y_h| for every t <= h.
        const double rho = reference.contraction();
        for (Eigen::Index h : {Eigen::Index(10), Eigen::Index(40), Eigen::Index(77), exact.rows() - 1}) {
            const std::vector<int> prefix(labels.begin(), labels.begin() + h + 1);
            const Eigen::MatrixXd truncated = reference.generate(prefix);
            for (int k = 0; k < 3; ++k) {
                const double endError = std::abs(truncated(h, k) - exact(h, k));
                for (Eigen::Index t = 0; t <= h; ++t)
                    QVERIFY(std::abs(truncated(t, k) - exact(t, k))
                            <= std::pow(rho, double(h - t)) * endError * (1 + 1e-9) + 1e-12);
                if (h == exact.rows() - 1)
                    QVERIFY(endError < 1e-12); // exactly 0 at h = T
            }
        }
        const BrandModel model = trained(data, false, 5);
        QVERIFY(model.streamingLag() == 5);
    }

    // §5, full covariances: the same truncation on the block system. Frame t comes out once label
    // t + L is in, and it is frame t of the exact solve of the prefix 1..t+L (the last L frames:
    // of the whole sequence); the error against the whole solve shrinks with the lag.
    void fixedLagStreamingFullCovariance()
    {
        const auto data = trainingData(9, 3);
        const BrandModel reference = trained(data, true);
        QVERIFY(reference.fullCovariance());
        std::mt19937 rng(10);
        const std::vector<int> labels = randomLabels(rng, 90, {0, 2, 6, 9, 21, 26, 35});
        const Eigen::MatrixXd exact = reference.generateMostLikely(labels);
        const Eigen::Index T = exact.rows();
        double previousError = INFINITY;
        for (int lag : {1, 2, 5, 10, 20}) {
            const BrandModel model = trained(data, true, lag);
            bool onTime = false;
            const Eigen::MatrixXd streamed = ::streamed(model, labels, lag, &onTime);
            QVERIFY(onTime);
            double maxError = 0;
            for (Eigen::Index t = 0; t < T; ++t) {
                const Eigen::Index h = std::min(t + lag, T - 1);
                const std::vector<int> prefix(labels.begin(), labels.begin() + h + 1);
                const Eigen::MatrixXd truncated = reference.generateMostLikely(prefix);
                QVERIFY2(maxAbs(streamed.row(t) - truncated.row(t)) < 1e-9,
                         qPrintable(QString("lag %1, frame %2").arg(lag).arg(t)));
                maxError = std::max(maxError, maxAbs(streamed.row(t) - exact.row(t)));
            }
            qInfo("lag %d: max error %.3g", lag, maxError);
            QVERIFY(maxError <= previousError + 1e-15);
            previousError = maxError;
        }
        QVERIFY(previousError < 1e-3);
        QVERIFY_THROWS_EXCEPTION(Error, trained(data, true, 3).streamer()->push(99));
    }

    // §5: without a lag given, the lag is the smallest at which the streamed frames of the
    // training sequences lie, in mean L1, within kStreamingShare of the exact solve's own distance
    // from the recorded frames; it is far below the contraction bound, kept in the model file,
    // and a damaged one is refused.
    void streamingLagChosenOnTrainingLabels()
    {
        const auto data = trainingData(9, 3, 30, 60);
        // Streamed-minus-exact L1 as a share of exact-minus-recorded L1.
        auto share = [&](const BrandModel &model, const std::vector<LabelledSequence> &sequences) {
            double streaming = 0.0, own = 0.0;
            for (const LabelledSequence &s : sequences) {
                bool onTime = false;
                const Eigen::MatrixXd exact = model.generateMostLikely(s.labels);
                streaming += (streamed(model, s.labels, model.streamingLag(), &onTime) - exact).cwiseAbs().sum();
                own += (exact - s.features).cwiseAbs().sum();
            }
            return streaming / own;
        };
        const std::vector<LabelledSequence> heldOut = trainingData(32, 3, 10, 60);
        for (bool full : {false, true}) {
            const BrandModel model = trained(data, full);
            const int lag = model.streamingLag();
            const double rho = model.contraction();
            const int bound = int(std::ceil(std::log(1e-3) / std::log(rho)));
            qInfo("%s: chosen lag %d (contraction bound %d), training share %.4f, held-out share %.4f",
                  full ? "full" : "diagonal", lag, bound, share(model, data), share(model, heldOut));
            QVERIFY(lag >= 1 && lag < bound);
            QVERIFY(share(model, data) <= BrandModel::kStreamingShare);
            if (lag > 1)
                QVERIFY(share(trained(data, full, lag - 1), data) > BrandModel::kStreamingShare);
            // New sequences of the same phones stream about as closely.
            QVERIFY(share(model, heldOut) <= 2.0 * BrandModel::kStreamingShare);

            QJsonObject json = model.parametersToJson();
            BrandModel loaded;
            loaded.parametersFromJson(json, "brand.model");
            QCOMPARE(loaded.streamingLag(), lag);
            // A file without it falls back on the bound.
            json.remove(QStringLiteral("streamingLag"));
            loaded.parametersFromJson(json, "brand.model");
            QCOMPARE(loaded.streamingLag(), std::min(bound, BrandModel::kMaximumLag));
            for (int damaged : {0, -3, BrandModel::kMaximumLag + 1}) {
                json[QStringLiteral("streamingLag")] = damaged;
                try {
                    loaded.parametersFromJson(json, "brand.model");
                    QFAIL("a damaged streaming lag was accepted");
                } catch (const Error &e) {
                    QVERIFY2(std::string(e.what()).find("streamingLag") != std::string::npos, e.what());
                }
            }
        }
    }

    // §7.16
    void trajectoryDensityEqualsDenseGaussian()
    {
        const auto data = trainingData(11, 2);
        const BrandModel model = trained(data);
        std::mt19937 rng(12);
        const std::vector<int> labels = randomLabels(rng, 10, {0, 6, 21});
        Eigen::MatrixXd Y = model.generate(labels);
        Y.array() += 0.05;
        Y(4, 1) -= 0.2;
        Eigen::MatrixXd H;
        Eigen::VectorXd b;
        model.denseReferenceSystem(labels, H, b);
        const Eigen::LLT<Eigen::MatrixXd> llt(H);
        const Eigen::MatrixXd Yt = Y.transpose();
        const Eigen::VectorXd e = Eigen::Map<const Eigen::VectorXd>(Yt.data(), Yt.size()) - llt.solve(b);
        const double logDet = 2.0 * llt.matrixLLT().diagonal().array().log().sum();
        const double dense = -0.5 * double(e.size()) * std::log(2 * M_PI) + 0.5 * logDet - 0.5 * e.dot(H * e);
        QVERIFY(std::abs(model.trajectoryLogLikelihood(labels, Y) - dense) < 1e-9 * std::abs(dense));
        // Full covariance: the block computation equals the dense one too.
        const BrandModel full = trained(trainingData(14, 2, 60, 50), true);
        full.denseReferenceSystem(labels, H, b);
        const Eigen::LLT<Eigen::MatrixXd> fullLlt(H);
        const Eigen::VectorXd ef = Eigen::Map<const Eigen::VectorXd>(Yt.data(), Yt.size()) - fullLlt.solve(b);
        const double fullDense = -0.5 * double(ef.size()) * std::log(2 * M_PI)
                                 + fullLlt.matrixLLT().diagonal().array().log().sum() - 0.5 * ef.dot(H * ef);
        QVERIFY(std::abs(full.trajectoryLogLikelihood(labels, Y) - fullDense) < 1e-9 * std::abs(fullDense));
    }

    // §2.1 statistics by hand: Δy_t = y_t - y_{t-1} for t >= 2 takes frame t's label; the first
    // frame of a sequence has no delta; a phone without transition frames backs off to the global
    // delta statistics; the static statistics are the HMM-mean's over all frames.
    void deltaStatisticsByHand()
    {
        // Dimension 1 is y, dimension 2 is -2 y + 1 (deltas -2x, variances 4x).
        auto sequence = [](std::vector<int> labels, std::vector<double> y) {
            LabelledSequence s{"hand", labels, Eigen::MatrixXd(Eigen::Index(y.size()), 2)};
            for (size_t t = 0; t < y.size(); ++t)
                s.features.row(Eigen::Index(t)) << y[t], -2 * y[t] + 1;
            return s;
        };
        // Five times over, so that phones 0 and 6 have the 10 frames and transition frames a
        // variance needs (docs/models.md §0, rare phones); the statistics are those of one copy.
        std::vector<LabelledSequence> data;
        for (int copy = 0; copy < 5; ++copy)
            for (LabelledSequence s : {sequence({0, 0, 6, 6}, {1, 3, 4, 8}), sequence({6, 0, 0}, {2, 5, 4}),
                                       sequence({30, 0}, {7, 9})})
                data.push_back(std::move(s));
        const BrandModel model = trained(data);
        // Phone 0: deltas 2, 3, -1, 2; phone 6: deltas 1, 4 (not the 2 of its first frame);
        // phone 30: no transition frame, so all six deltas 2, 1, 4, 3, -1, 2.
        const struct { int phone; double mean, variance; } delta[] = {
            {0, 1.5, 2.25}, {6, 2.5, 2.25}, {30, 11.0 / 6, 89.0 / 36}};
        for (const auto &e : delta) {
            QVERIFY(std::abs(model.deltaMean(e.phone, 0) - e.mean) < 1e-12);
            QVERIFY(std::abs(model.deltaMean(e.phone, 1) + 2 * e.mean) < 1e-12);
            QVERIFY(std::abs(model.deltaVariance(e.phone, 0) - e.variance) < 1e-12);
            QVERIFY(std::abs(model.deltaVariance(e.phone, 1) - 4 * e.variance) < 1e-11);
        }
        // Static: phone 0 frames 1, 3, 5, 4, 9; phone 6 frames 4, 8, 2.
        QVERIFY(std::abs(model.staticMean(0, 0) - 4.4) < 1e-12);
        QVERIFY(std::abs(model.staticVariance(0, 0) - 7.04) < 1e-12);
        QVERIFY(std::abs(model.staticMean(6, 0) - 14.0 / 3) < 1e-12);
        QVERIFY(std::abs(model.staticVariance(6, 0) - 56.0 / 9) < 1e-12);
        QVERIFY(std::abs(model.staticMean(6, 1) - (1 - 28.0 / 3)) < 1e-12);
        // The §2.1 density of the first sequence from these statistics: static terms at every
        // frame, delta terms from the second frame on.
        auto logNormal = [](double x, double m, double v) {
            return -0.5 * (std::log(2 * M_PI * v) + (x - m) * (x - m) / v);
        };
        const LabelledSequence &s = data[0];
        double expected = 0.0;
        for (Eigen::Index t = 0; t < s.features.rows(); ++t)
            for (int k = 0; k < 2; ++k) {
                const int n = s.labels[size_t(t)];
                expected += logNormal(s.features(t, k), model.staticMean(n, k), model.staticVariance(n, k));
                if (t > 0)
                    expected += logNormal(s.features(t, k) - s.features(t - 1, k), model.deltaMean(n, k),
                                          model.deltaVariance(n, k));
            }
        QVERIFY(std::abs(model.logLikelihood(s.labels, s.features) - expected) < 1e-10 * std::abs(expected));
    }

    // The full-covariance fit (§2.1 variant) is the ML covariance of o_t = [y_t; Δy_t] over the
    // transition frames T_n: on data whose dimensions are correlated it is not diagonal.
    void fullCovarianceKeepsCorrelations()
    {
        std::mt19937 rng(21);
        std::normal_distribution<double> normal;
        std::vector<LabelledSequence> data = trainingData(21, 1);
        for (LabelledSequence &s : data) { // y2 = 0.8 y1 + small noise
            Eigen::MatrixXd Y(s.features.rows(), 2);
            for (Eigen::Index t = 0; t < Y.rows(); ++t)
                Y.row(t) << s.features(t, 0), 0.8 * s.features(t, 0) + 0.01 * normal(rng);
            s.features = Y;
        }
        const BrandModel full = trained(data, true);
        QCOMPARE(full.jointCovariance.size(), size_t(PhoneSet::kCount));
        const int n = 6;
        Eigen::Vector4d sum = Eigen::Vector4d::Zero();
        Eigen::Matrix4d outer = Eigen::Matrix4d::Zero();
        int count = 0;
        for (const LabelledSequence &s : data)
            for (Eigen::Index t = 1; t < s.features.rows(); ++t)
                if (s.labels[size_t(t)] == n) {
                    Eigen::Vector4d o;
                    o << s.features.row(t).transpose(), (s.features.row(t) - s.features.row(t - 1)).transpose();
                    sum += o;
                    outer += o * o.transpose();
                    ++count;
                }
        QVERIFY(count > 50);
        const Eigen::Vector4d mean = sum / count;
        const Eigen::Matrix4d C = outer / count - mean * mean.transpose();
        QVERIFY(maxAbs(full.jointMean.row(n).transpose() - mean) < 1e-10);
        QVERIFY2(maxAbs(full.jointCovariance[size_t(n)] - C) < 1e-9 * maxAbs(C),
                 qPrintable(QString::number(maxAbs(full.jointCovariance[size_t(n)] - C))));
        const Eigen::MatrixXd &F = full.jointCovariance[size_t(n)];
        const Eigen::MatrixXd offDiagonal = F - Eigen::MatrixXd(F.diagonal().asDiagonal());
        QVERIFY(maxAbs(offDiagonal) > 0.5 * F.diagonal().minCoeff());
        QVERIFY(F(0, 1) / std::sqrt(F(0, 0) * F(1, 1)) > 0.95);  // y1, y2
        QVERIFY(F(2, 3) / std::sqrt(F(2, 2) * F(3, 3)) > 0.95);  // delta y1, delta y2
        QVERIFY(trained(data, false).jointCovariance.empty());
    }

    // §2.1, the covariance chosen by cross-validation: the choice re-computed from its documented
    // split (shuffled by mt19937(kCovarianceSeed), sequence i of the order in fold i mod 5), both
    // covariances trained on the other folds and scored by the held-out sequences' mean per-frame
    // L1; the model is then the chosen covariance trained on everything. The choice depends on the
    // data: coupled dimensions with many frames per phone, and few frames per phone in more
    // dimensions than they support, are decided differently.
    void covarianceChosenByCrossValidation()
    {
        std::mt19937 rng(5);
        std::normal_distribution<double> normal;
        std::vector<LabelledSequence> coupled = trainingData(21, 1, 30, 60);
        for (LabelledSequence &s : coupled) {
            Eigen::MatrixXd Y(s.features.rows(), 2);
            for (Eigen::Index t = 0; t < Y.rows(); ++t)
                Y.row(t) << s.features(t, 0), 0.8 * s.features(t, 0) + 0.01 * normal(rng);
            s.features = Y;
        }
        std::vector<LabelledSequence> sparse = trainingData(22, 6, 8, 16);
        std::vector<bool> chosen;
        for (const std::vector<LabelledSequence> *data : {&coupled, &sparse}) {
            BrandOptions options;
            options.covariance = BrandCovariance::CrossValidated;
            BrandModel model(options);
            Feedback feedback;
            model.train(*data, feedback);

            const int S = int(data->size()), folds = std::min(BrandModel::kCovarianceFolds, S);
            std::vector<int> order(static_cast<size_t>(S));
            std::iota(order.begin(), order.end(), 0);
            std::mt19937 shuffle(BrandModel::kCovarianceSeed);
            std::shuffle(order.begin(), order.end(), shuffle);
            double l1[2] = {0.0, 0.0};
            for (int fold = 0; fold < folds; ++fold) {
                std::vector<LabelledSequence> training, heldOut;
                for (int i = 0; i < S; ++i)
                    (i % folds == fold ? heldOut : training).push_back((*data)[size_t(order[size_t(i)])]);
                for (int full = 0; full < 2; ++full) {
                    const BrandModel part = trained(training, full == 1);
                    for (const LabelledSequence &h : heldOut)
                        for (Eigen::Index t = 0; t < h.features.rows(); ++t)
                            l1[full] += (part.generateMostLikely(h.labels).row(t) - h.features.row(t)).cwiseAbs().sum()
                                        / double(h.features.rows() * S);
                }
            }
            const BrandModel::CovarianceChoice &choice = model.covarianceChoice();
            QCOMPARE(choice.folds, 5);
            QVERIFY2(std::abs(choice.diagonalL1 - l1[0]) < 1e-9 * l1[0], qPrintable(QString::number(choice.diagonalL1)));
            QVERIFY2(std::abs(choice.fullL1 - l1[1]) < 1e-9 * l1[1], qPrintable(QString::number(choice.fullL1)));
            qInfo("diagonal L1 %.6f, full L1 %.6f", l1[0], l1[1]);
            const bool full = l1[1] < l1[0];
            QCOMPARE(model.fullCovariance(), full);
            const std::vector<int> &labels = data->front().labels;
            QVERIFY(maxAbs(model.generateMostLikely(labels) - trained(*data, full).generateMostLikely(labels)) < 1e-12);
            chosen.push_back(full);

            // The choice travels with the parameters; a damaged one is refused, naming the field.
            QJsonObject json = model.parametersToJson();
            BrandModel loaded;
            loaded.parametersFromJson(json, "brand.model");
            QCOMPARE(loaded.covarianceChoice().folds, 5);
            QCOMPARE(loaded.covarianceChoice().fullL1, choice.fullL1);
            QCOMPARE(loaded.fullCovariance(), full);
            json[QStringLiteral("covarianceChoice")] = QJsonObject{{QStringLiteral("folds"), 1}};
            try {
                loaded.parametersFromJson(json, "brand.model");
                QFAIL("a damaged covariance choice was accepted");
            } catch (const Error &e) {
                QVERIFY2(std::string(e.what()).find("covarianceChoice") != std::string::npos, e.what());
            }
        }
        QVERIFY2(chosen[0] != chosen[1], "both data sets got the same covariance");

        // One sequence: nothing to hold out, the paper's diagonal.
        BrandOptions options;
        options.covariance = BrandCovariance::CrossValidated;
        BrandModel single(options);
        Feedback feedback;
        single.train({sparse.front()}, feedback);
        QCOMPARE(single.covarianceChoice().folds, 0);
        QVERIFY(!single.fullCovariance());
    }

    void unseenPhonesAndOneFrame()
    {
        const auto data = trainingData(13, 2);
        const BrandModel model = trained(data);
        const Eigen::MatrixXd Y = model.generate({11, 29, 29, 38});
        QVERIFY(Y.allFinite());
        QCOMPARE(model.generate({6}).rows(), Eigen::Index(1));
        QVERIFY((model.generate({6}).row(0) - model.staticMean.row(6)).cwiseAbs().maxCoeff() < 1e-12);
        auto stream = model.streamer();
        stream->push(6);
        stream->finish();
        Eigen::VectorXd frame(2);
        QVERIFY(stream->pop(frame));
        QVERIFY(!stream->pop(frame));
    }

    void hmmMeanIsClosedFormAndStreams()
    {
        // 2 x 2 example by hand: phone 0 frames (1, 2) and (3, 6).
        LabelledSequence s{"hand", {0, 0}, (Eigen::MatrixXd(2, 2) << 1, 2, 3, 6).finished()};
        HmmMeanModel model;
        Feedback feedback;
        model.train({s}, feedback);
        QCOMPARE(model.means()(0, 0), 2.0);
        QCOMPARE(model.means()(0, 1), 4.0);
        QCOMPARE(model.variances()(0, 0), 1.0);
        QCOMPARE(model.variances()(0, 1), 4.0);
        const double expected = -0.5 * (4 * std::log(2 * M_PI) + 2 * (std::log(1.0) + std::log(4.0)) + 1 + 1 + 1 + 1);
        QVERIFY(std::abs(model.logLikelihood(s.labels, s.features) - expected) < 1e-12);
        // Unseen phone: the global mean.
        QCOMPARE(model.generate({5})(0, 1), 4.0);
        auto stream = model.streamer();
        Eigen::VectorXd frame(2);
        stream->push(0);
        QVERIFY(stream->pop(frame));
        QCOMPARE(frame[0], 2.0);
    }
};

QTEST_GUILESS_MAIN(TestBrand)
#include "tst_brand.moc"
