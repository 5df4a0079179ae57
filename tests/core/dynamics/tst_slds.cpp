// SLDS checks of docs/models.md §7 (items 17-21).
#include "SyntheticDynamics.h"

#include "dynamics/SldsModel.h"
#include "tasks/Feedback.h"

#include <QTest>

#include <Eigen/Cholesky>
#include <Eigen/SVD>

using namespace lipsync;
using namespace lipsync::test;

namespace {

Eigen::MatrixXd randomSpd(std::mt19937 &rng, int d, double scale)
{
    std::normal_distribution<double> normal;
    Eigen::MatrixXd M(d, d);
    for (int i = 0; i < d; ++i)
        for (int j = 0; j < d; ++j)
            M(i, j) = normal(rng);
    return scale * (M * M.transpose() / d + 0.5 * Eigen::MatrixXd::Identity(d, d));
}

slds::Parameters randomParameters(std::mt19937 &rng, int d, bool diagonal)
{
    const int P = PhoneSet::kCount;
    std::uniform_real_distribution<double> u(-0.6, 0.6);
    slds::Parameters p;
    p.mu.resize(P, d);
    p.nu.resize(P, d);
    for (int n = 0; n < P; ++n) {
        Eigen::MatrixXd A(d, d);
        for (int i = 0; i < d; ++i)
            for (int j = 0; j < d; ++j)
                A(i, j) = diagonal && i != j ? 0.0 : u(rng);
        if (diagonal)
            A.diagonal().array() += 0.3;
        p.A.push_back(A);
        auto cov = [&](double s) {
            Eigen::MatrixXd C = randomSpd(rng, d, s);
            return diagonal ? Eigen::MatrixXd(C.diagonal().asDiagonal()) : C;
        };
        p.Q.push_back(cov(0.05));
        p.R.push_back(cov(0.02));
        p.Sigma.push_back(cov(0.3));
        for (int k = 0; k < d; ++k) {
            p.mu(n, k) = 2 * u(rng);
            p.nu(n, k) = 2 * u(rng);
        }
    }
    return p;
}

LabelledSequence sample(std::mt19937 &rng, const slds::Parameters &p, const std::vector<int> &labels)
{
    const int d = p.dimension();
    std::normal_distribution<double> normal;
    auto draw = [&](const Eigen::MatrixXd &C) {
        Eigen::VectorXd z(d);
        for (int k = 0; k < d; ++k)
            z[k] = normal(rng);
        return Eigen::VectorXd(C.llt().matrixL() * z);
    };
    LabelledSequence s;
    s.labels = labels;
    s.features.resize(Eigen::Index(labels.size()), d);
    Eigen::VectorXd x;
    for (size_t t = 0; t < labels.size(); ++t) {
        const int n = labels[t];
        x = t == 0 ? Eigen::VectorXd(p.mu.row(n).transpose() + draw(p.Sigma[size_t(n)]))
                   : Eigen::VectorXd(p.A[size_t(n)] * x + p.nu.row(n).transpose() + draw(p.Q[size_t(n)]));
        s.features.row(Eigen::Index(t)) = (x + draw(p.R[size_t(n)])).transpose();
    }
    return s;
}

// The stacked state-space model: x = m_x + L w, y = x + v.
void denseMoments(const slds::Parameters &p, const std::vector<int> &labels, Eigen::VectorXd &mx,
                  Eigen::MatrixXd &Cx, Eigen::MatrixXd &Cy)
{
    const int d = p.dimension();
    const Eigen::Index T = Eigen::Index(labels.size());
    mx.resize(d * T);
    Eigen::MatrixXd L = Eigen::MatrixXd::Zero(d * T, d * T), W = L, V = L;
    for (Eigen::Index t = 0; t < T; ++t) {
        const int n = labels[size_t(t)];
        mx.segment(t * d, d) = t == 0 ? Eigen::VectorXd(p.mu.row(n).transpose())
                                      : Eigen::VectorXd(p.A[size_t(n)] * mx.segment((t - 1) * d, d) + p.nu.row(n).transpose());
        W.block(t * d, t * d, d, d) = t == 0 ? p.Sigma[size_t(n)] : p.Q[size_t(n)];
        V.block(t * d, t * d, d, d) = p.R[size_t(n)];
        L.block(t * d, t * d, d, d).setIdentity();
        for (Eigen::Index s = t - 1; s >= 0; --s)
            L.block(t * d, s * d, d, d) = p.A[size_t(n)] * L.block((t - 1) * d, s * d, d, d);
    }
    Cx = L * W * L.transpose();
    Cy = Cx + V;
}

double maxAbs(const Eigen::MatrixXd &m) { return m.cwiseAbs().maxCoeff(); }

// A 1-d SLDS with small noise (Q = R = 0.01) and 120 sequences of 60 frames sampled from it.
slds::Parameters quietScalarTruth(std::mt19937 &rng)
{
    slds::Parameters truth = randomParameters(rng, 1, true);
    for (auto &Q : truth.Q)
        Q(0, 0) = 0.01;
    for (auto &R : truth.R)
        R(0, 0) = 0.01;
    return truth;
}
std::vector<LabelledSequence> scalarData(std::mt19937 &rng, const slds::Parameters &truth, int maxRun)
{
    std::vector<LabelledSequence> data;
    for (int s = 0; s < 120; ++s)
        data.push_back(sample(rng, truth, randomLabels(rng, 60, {0, 6, 21, 30}, maxRun)));
    return data;
}

// The EM objective never decreases (up to rounding).
bool nonDecreasing(const std::vector<double> &h)
{
    for (size_t i = 1; i < h.size(); ++i)
        if (h[i] < h[i - 1] - 1e-9 * std::abs(h[i - 1]))
            return false;
    return true;
}

} // namespace

class TestSlds : public QObject
{
    Q_OBJECT
private slots:
    // §7.17 and §7.18
    void kalmanAndSmootherMatchDenseGaussian()
    {
        std::mt19937 rng(1);
        const int d = 2;
        const slds::Parameters p = randomParameters(rng, d, false);
        const std::vector<int> labels{39, 39, 6, 6, 21, 2, 2};
        const LabelledSequence s = sample(rng, p, labels);
        Eigen::VectorXd mx;
        Eigen::MatrixXd Cx, Cy;
        denseMoments(p, labels, mx, Cx, Cy);
        const Eigen::MatrixXd Yt = s.features.transpose();
        const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(Yt.data(), Yt.size());
        const Eigen::LLT<Eigen::MatrixXd> llt(Cy);
        const double dense = -0.5 * (double(y.size()) * std::log(2 * M_PI)
                                     + 2 * llt.matrixLLT().diagonal().array().log().sum()
                                     + llt.matrixL().solve(y - mx).squaredNorm());
        const slds::Smoothed sm = slds::smooth(p, labels, s.features);
        QVERIFY(std::abs(sm.logLikelihood - dense) < 1e-10 * std::abs(dense));
        QVERIFY(std::abs(slds::kalmanLogLikelihood(p, labels, s.features) - dense) < 1e-10 * std::abs(dense));
        const Eigen::VectorXd mean = mx + Cx * llt.solve(y - mx);
        const Eigen::MatrixXd cov = Cx - Cx * llt.solve(Cx);
        for (size_t t = 0; t < labels.size(); ++t) {
            const Eigen::Index o = Eigen::Index(t) * d;
            QVERIFY((sm.mean[t] - mean.segment(o, d)).cwiseAbs().maxCoeff() < 1e-10);
            QVERIFY(maxAbs(sm.covariance[t] - cov.block(o, o, d, d)) < 1e-10);
            if (t > 0)
                QVERIFY(maxAbs(sm.cross[t] - cov.block(o, o - d, d, d)) < 1e-10);
        }
    }

    void scalarPathEqualsMatrixPath()
    {
        std::mt19937 rng(2);
        const slds::Parameters p = randomParameters(rng, 3, true);
        const std::vector<int> labels = randomLabels(rng, 40, {0, 6, 21});
        const LabelledSequence s = sample(rng, p, labels);
        SldsModel diagonal;
        diagonal.setParameters(p);
        QVERIFY(diagonal.isDiagonal());
        const double scalar = diagonal.logLikelihood(labels, s.features);
        QVERIFY(std::abs(scalar - slds::kalmanLogLikelihood(p, labels, s.features)) < 1e-10 * std::abs(scalar));
    }

    // §7.19
    void emIsMonotone_data()
    {
        QTest::addColumn<bool>("fullA");
        QTest::addColumn<bool>("fullNoise");
        QTest::addColumn<bool>("boundA");
        for (bool bound : {false, true}) {
            const char *suffix = bound ? ", A bounded" : "";
            QTest::addRow("diagonal A, diagonal Q R%s", suffix) << false << false << bound;
            QTest::addRow("full A, full Q R%s", suffix) << true << true << bound;
            QTest::addRow("full A, diagonal Q R%s", suffix) << true << false << bound;
            QTest::addRow("diagonal A, full Q R (ECM)%s", suffix) << false << true << bound;
        }
    }
    void emIsMonotone()
    {
        QFETCH(bool, fullA);
        QFETCH(bool, fullNoise);
        QFETCH(bool, boundA);
        std::mt19937 rng(3);
        const slds::Parameters truth = randomParameters(rng, 2, false);
        std::vector<LabelledSequence> data;
        for (int s = 0; s < 25; ++s)
            data.push_back(sample(rng, truth, randomLabels(rng, 30, {0, 6, 21})));
        SldsOptions options;
        options.fullA = fullA;
        options.fullNoise = fullNoise;
        options.kappa = 0; // pure ML: the likelihood itself must not decrease
        options.maxIterations = 25;
        options.tolerance = 0;
        // Bounded: a bound the ML estimates of this truth exceed, so the constrained steps act.
        options.boundA = boundA;
        options.aMax = 0.35;
        SldsModel model(options);
        Feedback feedback;
        model.train(data, feedback);
        const auto &h = model.objectiveHistory();
        QVERIFY(h.size() >= 10);
        for (size_t i = 1; i < h.size(); ++i)
            QVERIFY2(h[i] >= h[i - 1] - 1e-9 * std::abs(h[i - 1]),
                     qPrintable(QStringLiteral("iteration %1: %2 < %3").arg(i).arg(h[i], 0, 'g', 15).arg(h[i - 1], 0, 'g', 15)));
        QVERIFY(h.back() > h.front());
        double largest = 0.0; // ||A_n||_2 over the trained phones
        for (int n : {0, 6, 21})
            largest = std::max(largest, model.parameters().A[size_t(n)].jacobiSvd().singularValues().maxCoeff());
        if (boundA)
            QVERIFY2(largest <= options.aMax + 1e-12, qPrintable(QString::number(largest)));
        else
            QVERIFY2(largest > options.aMax, qPrintable(QString::number(largest)));
    }

    // The default M-step is the paper's plain ML (§3.4): a phone whose true a exceeds 1 (short
    // runs keep the data bounded) is recovered above 1; boundA holds it at aMax.
    void defaultIsUnconstrainedMaximumLikelihood()
    {
        std::mt19937 rng(8);
        slds::Parameters truth = quietScalarTruth(rng);
        truth.A[6](0, 0) = 1.1;
        const std::vector<LabelledSequence> data = scalarData(rng, truth, 4);
        Feedback feedback;
        SldsModel plain;
        QVERIFY(!plain.options().boundA);
        plain.train(data, feedback);
        const double a = plain.parameters().A[6](0, 0);
        QVERIFY2(std::abs(a - 1.1) < 0.05, qPrintable(QString::number(a)));
        const auto &h = plain.objectiveHistory();
        QVERIFY(nonDecreasing(h));

        SldsOptions options;
        options.boundA = true;
        SldsModel bounded(options);
        bounded.train(data, feedback);
        QCOMPARE(bounded.parameters().A[6](0, 0), options.aMax);
        for (const Eigen::MatrixXd &A : bounded.parameters().A)
            QVERIFY(std::abs(A(0, 0)) <= options.aMax);
        const auto &hb = bounded.objectiveHistory();
        QVERIFY(nonDecreasing(hb));
        // The constraint costs likelihood on data that violate it.
        QVERIFY(hb.back() < h.back());
    }

    // §7.20
    void recoversDiagonalDynamics()
    {
        std::mt19937 rng(4);
        const slds::Parameters truth = quietScalarTruth(rng);
        const std::vector<LabelledSequence> data = scalarData(rng, truth, 6);
        SldsModel model;
        Feedback feedback;
        model.train(data, feedback);
        for (int n : {0, 6, 21, 30}) {
            QVERIFY2(std::abs(model.parameters().A[size_t(n)](0, 0) - truth.A[size_t(n)](0, 0)) < 0.08,
                     qPrintable(QStringLiteral("a[%1] %2 vs %3").arg(n).arg(model.parameters().A[size_t(n)](0, 0)).arg(truth.A[size_t(n)](0, 0))));
            QVERIFY(std::abs(model.parameters().nu(n, 0) - truth.nu(n, 0)) < 0.1 + 0.1 * std::abs(truth.nu(n, 0)));
        }
        QVERIFY(nonDecreasing(model.objectiveHistory()));
    }

    // §7.21
    void generationStreamsAndIsTheMean()
    {
        std::mt19937 rng(5);
        const slds::Parameters p = randomParameters(rng, 2, false);
        for (bool fullA : {false, true}) {
            SldsOptions options;
            options.fullA = fullA;
            options.fullNoise = fullA;
            SldsModel model(options);
            model.setParameters(p);
            const std::vector<int> labels = randomLabels(rng, 20, {0, 6, 21});
            const Eigen::MatrixXd batch = model.generate(labels);
            auto stream = model.streamer();
            Eigen::VectorXd frame(2);
            for (size_t t = 0; t < labels.size(); ++t) {
                stream->push(labels[t]);
                QVERIFY(stream->pop(frame));
                QVERIFY(frame == batch.row(Eigen::Index(t)).transpose());
            }
            if (!fullA)
                continue;
            // Mean of 10^4 samples within 3 standard errors of yhat_t.
            const int samples = 10000;
            Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(batch.rows(), 2), sq = sum;
            for (int i = 0; i < samples; ++i) {
                const Eigen::MatrixXd Y = sample(rng, p, labels).features;
                sum += Y;
                sq += Y.cwiseProduct(Y);
            }
            const Eigen::MatrixXd mean = sum / samples;
            const Eigen::MatrixXd se = ((sq / samples - mean.cwiseProduct(mean)) / samples).cwiseSqrt();
            QVERIFY(((mean - batch).cwiseAbs().array() <= 3.5 * se.array() + 1e-12).all());
        }
    }

    void sharedDpdsInitialisationGivesTheSameModel()
    {
        std::mt19937 rng(7);
        const slds::Parameters p = randomParameters(rng, 2, true);
        std::vector<LabelledSequence> data;
        for (int s = 0; s < 15; ++s)
            data.push_back(sample(rng, p, randomLabels(rng, 30, {0, 6, 21})));
        Feedback feedback;
        // The iterations reported are SLDS's own EM iterations 1, 2, ... with its objective, not
        // those of the DPDS it trains for its initialisation (the studio plots them per model).
        std::vector<std::pair<int, double>> reported;
        feedback.onIteration = [&](int i, double objective) { reported.emplace_back(i, objective); };
        SldsOptions options;
        options.maxIterations = 20;
        SldsModel own(options);
        own.train(data, feedback);
        QCOMPARE(reported.size(), own.objectiveHistory().size());
        for (size_t i = 0; i < reported.size(); ++i) {
            QCOMPARE(reported[i].first, int(i) + 1);
            QCOMPARE(reported[i].second, own.objectiveHistory()[i]);
        }
        feedback.onIteration = nullptr;
        DpdsOptions dpdsOptions;
        dpdsOptions.maxIterations = options.initIterations;
        auto dpds = std::make_shared<DpdsModel>(dpdsOptions);
        dpds->train(data, feedback);
        SldsModel shared(options);
        shared.setInitialisation(dpds);
        shared.train(data, feedback);
        QCOMPARE(shared.objectiveHistory(), own.objectiveHistory());
        QVERIFY(shared.parameters().nu == own.parameters().nu);
    }

    // A shared DPDS initialisation trained with the default bound (0.999) starts a tighter-bounded
    // SLDS inside its bound: every a stays within it and EM stays monotone.
    void boundHoldsFromASharedInitialisation()
    {
        std::mt19937 rng(9);
        const slds::Parameters truth = quietScalarTruth(rng);
        const std::vector<LabelledSequence> data = scalarData(rng, truth, 6);
        Feedback feedback;
        auto dpds = std::make_shared<DpdsModel>();
        dpds->train(data, feedback);
        QVERIFY(dpds->a.cwiseAbs().maxCoeff() > 0.3);
        for (bool fullA : {false, true}) {
            SldsOptions options;
            options.boundA = true;
            options.aMax = 0.3;
            options.fullA = fullA;
            options.maxIterations = 15;
            options.kappa = 0;
            SldsModel model(options);
            model.setInitialisation(dpds);
            model.train(data, feedback);
            for (const Eigen::MatrixXd &A : model.parameters().A)
                QVERIFY(A.jacobiSvd().singularValues().maxCoeff() <= options.aMax + 1e-12);
            QVERIFY(nonDecreasing(model.objectiveHistory()));
        }
    }

    void trainsOnOneFrameSequencesAndUnseenPhones()
    {
        std::mt19937 rng(6);
        const slds::Parameters p = randomParameters(rng, 2, true);
        std::vector<LabelledSequence> data;
        for (int s = 0; s < 10; ++s)
            data.push_back(sample(rng, p, randomLabels(rng, 20, {0, 6})));
        data.push_back(sample(rng, p, {21}));
        SldsModel model;
        Feedback feedback;
        model.train(data, feedback);
        const Eigen::MatrixXd Y = model.generate({11, 11, 29, 21});
        QVERIFY(Y.allFinite());
        QVERIFY(std::isfinite(model.logLikelihood({11, 11, 29, 21}, Y)));
    }
};

QTEST_GUILESS_MAIN(TestSlds)
#include "tst_slds.moc"
