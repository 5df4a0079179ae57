// Evaluation checks of docs/models.md §7 (items 22-25) and the cross-validation runner.
#include "../dynamics/SyntheticDynamics.h"

#include "eval/CrossValidation.h"
#include "eval/Evaluation.h"
#include "eval/StudyTally.h"
#include "eval/Metrics.h"
#include "eval/Statistics.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonArray>
#include <cmath>
#include <QTest>

#include <algorithm>
#include <set>

using namespace lipsync;

// Sequences sampled from a random DPDS of dimension d over five phones.
static std::vector<LabelledSequence> sampledData(unsigned seed, int d, int sequences, int frames)
{
    std::mt19937 rng(seed);
    const test::DpdsTruth truth = test::randomDpdsTruth(rng, d, 0.05);
    return test::dpdsDataset(rng, truth, {0, 2, 6, 9, 21}, sequences, frames);
}

class TestEvaluation : public QObject
{
    Q_OBJECT
private slots:
    // §7.22
    void metricsByHand()
    {
        Eigen::MatrixXd real = Eigen::MatrixXd::Zero(2, 2), gen(2, 2);
        gen << 1, -2, 3, 0;
        const SequenceErrors e = sequenceErrors(gen, real);
        QCOMPARE(e.l1, 3.0);
        QCOMPARE(e.rms, std::sqrt(7.0));
        QCOMPARE(e.linf, 2.5);
        gen << 0.5, 0.5, -0.5, 0.5;
        real << 0, 1, 0, 0;
        const SequenceErrors f = sequenceErrors(gen, real);
        QCOMPARE(f.l1, 1.0);
        QCOMPARE(f.rms, std::sqrt(0.5));
        QCOMPARE(f.linf, 0.5);
        QVERIFY_THROWS_EXCEPTION(Error, sequenceErrors(gen, Eigen::MatrixXd::Zero(3, 2)));
    }

    // §7.23
    void confidenceInterval()
    {
        QVERIFY(std::abs(stats::studentTQuantile(0.975, 9) - 2.2622) < 1e-4);
        QVERIFY(std::abs(stats::studentTQuantile(0.975, 1) - 12.7062) < 1e-3);
        const stats::MeanInterval m = stats::meanWithCi95({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
        QCOMPARE(m.mean, 5.5);
        QVERIFY(std::abs(m.sd - 3.0277) < 1e-4);
        QVERIFY(std::abs(m.halfWidth - 2.1659) < 1e-4);
        // Paired t-test: differences 1, 2, 3 -> t = 2 / (1 / sqrt 3) = 3.4641, p = 0.0742.
        const stats::TTest t = stats::pairedTTest({2, 4, 6}, {1, 2, 3});
        QVERIFY(std::abs(t.t - 3.4641016) < 1e-6);
        QVERIFY(std::abs(t.p - 0.07417990) < 1e-6);
        // A non-finite fold value gives a NaN p-value, not an exception that ends the evaluation.
        const stats::TTest bad = stats::pairedTTest({2, -INFINITY, 6}, {1, 2, 3});
        QVERIFY(std::isnan(bad.p));
        QVERIFY(std::isnan(stats::studentTCdf(NAN, 4)));
        QCOMPARE(stats::studentTCdf(INFINITY, 4), 1.0);
        QVERIFY(std::abs(stats::studentTCdf(-2.7764451, 4) - 0.025) < 1e-7);
    }

    // §7.24: the paper's Table 1 counts give its sign-test p-values and Bradley-Terry order.
    void forcedChoiceTable1()
    {
        const std::vector<std::string> methods{"Brand", "DPDS", "real", "SLDS"};
        std::vector<PairTally> counts(6);
        const int rows[6][5] = {{0, 1, 5, 7, 54}, {0, 2, 4, 7, 55}, {0, 3, 36, 21, 9},
                                {1, 2, 29, 11, 26}, {1, 3, 60, 5, 1}, {2, 3, 58, 5, 3}};
        for (int i = 0; i < 6; ++i) {
            counts[size_t(i)].a = rows[i][0];
            counts[size_t(i)].b = rows[i][1];
            counts[size_t(i)].preferA = rows[i][2];
            counts[size_t(i)].undecided = rows[i][3];
            counts[size_t(i)].preferB = rows[i][4];
        }
        const StudyTally tally = StudyTally::fromCounts(methods, counts);
        const double expected[6] = {1.9e-11, 1.7e-12, 6.6e-5, 0.79, 5.4e-17, 3.3e-14};
        for (int i = 0; i < 6; ++i) {
            const PairTally &p = tally.pair(rows[i][0], rows[i][1]);
            QCOMPARE(p.total(), 66);
            QVERIFY2(std::abs(p.pValue / expected[i] - 1.0) < 0.05,
                     qPrintable(QStringLiteral("%1 vs %2").arg(p.pValue).arg(expected[i])));
        }
        // Bradley-Terry with undecided answers dropped: log-strengths centred to sum 0 are
        // DPDS 1.571, real 1.451, Brand -0.879, SLDS -2.143 (docs/models.md §7.24).
        const double expectLog[4] = {-0.879, 1.571, 1.451, -2.143}; // Brand, DPDS, real, SLDS
        double meanLog = 0;
        for (const MethodScore &m : tally.ranking)
            meanLog += std::log(m.strength) / 4.0;
        for (const MethodScore &m : tally.ranking)
            QVERIFY2(std::abs(std::log(m.strength) - meanLog - expectLog[m.method]) < 2e-3,
                     qPrintable(QString::number(std::log(m.strength) - meanLog)));
        QCOMPARE(methods[size_t(tally.ranking.front().method)], std::string("DPDS"));
        QCOMPARE(methods[size_t(tally.ranking.back().method)], std::string("SLDS"));
    }

    // §7.25
    void foldsCoverDisjointBalanced_data()
    {
        QTest::addColumn<int>("sequences");
        QTest::addColumn<int>("folds");
        QTest::newRow("400/10") << 400 << 10;
        QTest::newRow("37/10") << 37 << 10;
        QTest::newRow("10/10") << 10 << 10;
        QTest::newRow("23/4") << 23 << 4;
    }
    void foldsCoverDisjointBalanced()
    {
        QFETCH(int, sequences);
        QFETCH(int, folds);
        const auto split = makeFolds(sequences, folds);
        QCOMPARE(int(split.size()), folds);
        std::set<int> seen;
        for (const auto &fold : split) {
            QVERIFY(int(fold.size()) == sequences / folds || int(fold.size()) == (sequences + folds - 1) / folds);
            for (int i : fold) {
                QVERIFY(i >= 0 && i < sequences);
                QVERIFY(seen.insert(i).second); // disjoint
            }
        }
        QCOMPARE(int(seen.size()), sequences); // cover
        QCOMPARE(makeFolds(sequences, folds), split); // deterministic
        QVERIFY(makeFolds(sequences, folds, 99) != split || sequences == folds);
        QVERIFY_THROWS_EXCEPTION(Error, makeFolds(5, 10));
        QVERIFY_THROWS_EXCEPTION(Error, makeFolds(5, 1));
        // What trains with fold 1 held out: every other fold's members, fold by fold.
        const std::vector<int> training = trainingMembers(split, 1);
        QCOMPARE(int(training.size()), sequences - int(split[1].size()));
        QCOMPARE(training.front(), split[0].front());
        for (int i : split[1])
            QVERIFY(std::find(training.begin(), training.end(), i) == training.end());
    }

    // A learning curve's training set (EvaluationOptions::trainingSpeechSeconds): only training
    // sequences, the fewest in the drawn order whose speech (frames not silence or breath)
    // reaches the limit, the same for the same seed, and all of them without a limit.
    void trainingSpeechLimit()
    {
        std::vector<LabelledSequence> all;
        for (int i = 0; i < 20; ++i) {
            LabelledSequence s;
            s.name = "s" + std::to_string(i);
            s.frameRate = 25.0;
            // 10 frames of silence, 25 + i frames of speech, 5 of breath.
            s.labels.assign(10, PhoneSet::kSilence);
            s.labels.insert(s.labels.end(), size_t(25 + i), 3);
            s.labels.insert(s.labels.end(), 5, PhoneSet::kBreath);
            s.features = Eigen::MatrixXd::Zero(s.frameCount(), 2);
            all.push_back(s);
        }
        QCOMPARE(speechSeconds(all[0]), 1.0);
        const std::vector<int> test{1, 7, 13};
        QCOMPARE(trainingSequences(all, test).size(), size_t(17));
        const std::vector<LabelledSequence> few = trainingSequences(all, test, 3.5, 11);
        double speech = 0;
        for (const LabelledSequence &s : few) {
            QVERIFY(s.name != "s1" && s.name != "s7" && s.name != "s13");
            speech += speechSeconds(s);
        }
        // No more than the limit plus one sequence (1.76 s at most).
        QVERIFY2(speech >= 3.5 && speech < 3.5 + 1.76, qPrintable(QString::number(speech)));
        QVERIFY(few.size() >= 3 && few.size() <= 4);
        std::vector<std::string> names, again;
        for (const LabelledSequence &s : few)
            names.push_back(s.name);
        for (const LabelledSequence &s : trainingSequences(all, test, 3.5, 11))
            again.push_back(s.name);
        QCOMPARE(again, names);
        // Another seed draws other sequences; more speech than there is takes them all.
        std::vector<std::string> other;
        for (const LabelledSequence &s : trainingSequences(all, test, 3.5, 12))
            other.push_back(s.name);
        QVERIFY(other != names);
        QCOMPARE(trainingSequences(all, test, 1e6, 11).size(), size_t(17));
    }

    void crossValidatesAllModelsOnIdenticalFolds()
    {
        const auto data = sampledData(1, 3, 20, 40);
        EvaluationOptions options;
        options.folds = 5;
        Feedback feedback;
        std::vector<double> progress;
        feedback.onProgress = [&](double p) { progress.push_back(p); };
        const EvaluationResult r = evaluateModels(data, options, feedback);
        QCOMPARE(r.models.size(), size_t(4));
        QCOMPARE(r.foldMembers, makeFolds(20, 5));
        QVERIFY(!progress.empty() && progress.back() == 1.0);
        for (const ModelEvaluation &m : r.models) {
            QCOMPARE(m.trainingSeconds.size(), size_t(5));
            for (const std::string &metric : evaluationMetrics()) {
                const MetricSummary &s = m.metrics.at(metric);
                QCOMPARE(s.folds.size(), size_t(5));
                const stats::MeanInterval check = stats::meanWithCi95(s.folds);
                QCOMPARE(s.mean, check.mean);
                QCOMPARE(s.ci95, check.halfWidth);
            }
        }
        // Data sampled from a DPDS: the DPDS generates better than the HMM-mean.
        QVERIFY(r.models[3].metrics.at("rms").mean < r.models[0].metrics.at("rms").mean);
        QCOMPARE(r.comparisons.size(), size_t(6 * 4));
        const QJsonObject json = r.toJson();
        QCOMPARE(json.value(QStringLiteral("folds")).toInt(), 5);
        const QJsonObject dpds = json.value(QStringLiteral("models")).toObject().value(QStringLiteral("dpds")).toObject();
        QVERIFY(dpds.value(QStringLiteral("rms")).toObject().contains(QStringLiteral("ci95")));
        QVERIFY(dpds.value(QStringLiteral("trainingSeconds")).toDouble() > 0);
        QVERIFY(dpds.value(QStringLiteral("trainingCpuSeconds")).toDouble() > 0);
        const std::string csv = r.toCsv();
        QCOMPARE(std::count(csv.begin(), csv.end(), '\n'), long(1 + 4 * 5));
        QVERIFY(csv.rfind("model,metric,mean,ci95,fold1", 0) == 0);
        // Unknown kinds and too few sequences are errors before any training.
        options.kinds = {"dpds", "lstm"};
        QVERIFY_THROWS_EXCEPTION(Error, evaluateModels(data, options, feedback));
        options.kinds = {"hmm"};
        options.folds = 30;
        QVERIFY_THROWS_EXCEPTION(Error, evaluateModels(data, options, feedback));
    }

    // §6.2: the log-likelihood compared across models is a density over y; Brand's is its
    // trajectory density (§2.2), not its density over [y, delta y] (§2.1).
    void brandLogLikelihoodIsItsTrajectoryDensity()
    {
        const auto data = sampledData(3, 2, 8, 30);
        EvaluationOptions options;
        options.folds = 2;
        options.kinds = {"brand", "hmm"};
        options.parallelFolds = false;
        Feedback feedback;
        const EvaluationResult r = evaluateModels(data, options, feedback);
        for (int f = 0; f < options.folds; ++f) {
            std::vector<LabelledSequence> training;
            for (size_t i = 0; i < data.size(); ++i)
                if (std::find(r.foldMembers[size_t(f)].begin(), r.foldMembers[size_t(f)].end(), int(i))
                    == r.foldMembers[size_t(f)].end())
                    training.push_back(data[i]);
            for (size_t m = 0; m < options.kinds.size(); ++m) {
                auto model = createDynamicModel(options.kinds[m]);
                model->train(training, feedback);
                double trajectory = 0.0, own = 0.0;
                for (int i : r.foldMembers[size_t(f)]) {
                    const LabelledSequence &s = data[size_t(i)];
                    trajectory += model->trajectoryLogLikelihood(s.labels, s.features) / double(s.frameCount());
                    own += model->logLikelihood(s.labels, s.features) / double(s.frameCount());
                }
                const double n = double(r.foldMembers[size_t(f)].size());
                const double value = r.models[m].metrics.at("loglik").folds[size_t(f)];
                QVERIFY2(std::abs(value - trajectory / n) <= 1e-9 * std::abs(value), options.kinds[m].c_str());
                if (options.kinds[m] == "brand")
                    QVERIFY(std::abs(own - trajectory) > 1e-3 * std::abs(own));
                else
                    QCOMPARE(own, trajectory);
            }
        }
        QVERIFY(r.toJson().value(QStringLiteral("loglikNote")).toString().contains(QStringLiteral("Brand")));
    }

    void parallelFoldsEqualSerialFolds()
    {
        // Folds run concurrently by default; the results must not depend on the schedule.
        auto data = sampledData(2, 2, 12, 30);
        // A one-frame test sequence of a phone never seen in training (ZH): back-off, finite scores.
        data.push_back(LabelledSequence{"single-unseen", {PhoneSet::index("ZH")}, Eigen::MatrixXd::Constant(1, 2, 0.3)});
        EvaluationOptions options;
        options.folds = 4;
        Feedback feedback;
        options.parallelFolds = false;
        const EvaluationResult serial = evaluateModels(data, options, feedback);
        options.parallelFolds = true;
        std::vector<double> progress;
        feedback.onProgress = [&](double p) { progress.push_back(p); };
        const EvaluationResult parallel = evaluateModels(data, options, feedback);
        QVERIFY(!progress.empty() && progress.back() == 1.0);
        QCOMPARE(parallel.models.size(), serial.models.size());
        for (size_t m = 0; m < serial.models.size(); ++m) {
            QCOMPARE(parallel.models[m].kind, serial.models[m].kind);
            QCOMPARE(parallel.models[m].trainingSeconds.size(), size_t(4));
            QCOMPARE(parallel.models[m].trainingCpuSeconds.size(), size_t(4));
            for (const std::string &metric : evaluationMetrics()) {
                const std::vector<double> &a = serial.models[m].metrics.at(metric).folds;
                const std::vector<double> &b = parallel.models[m].metrics.at(metric).folds;
                QCOMPARE(b.size(), a.size());
                for (size_t f = 0; f < a.size(); ++f)
                    QVERIFY(std::isfinite(b[f]));
                for (size_t f = 0; f < a.size(); ++f)
                    QVERIFY2(std::abs(a[f] - b[f]) <= 1e-9 * (1.0 + std::abs(a[f])),
                             (serial.models[m].kind + " " + metric).c_str());
            }
        }
        // A cancel before or during the folds ends the evaluation with Canceled.
        Feedback canceled;
        canceled.cancel();
        QVERIFY_THROWS_EXCEPTION(Canceled, evaluateModels(data, options, canceled));
        Feedback midway;
        midway.onProgress = [&](double p) {
            if (p > 0.3)
                midway.cancel();
        };
        QVERIFY_THROWS_EXCEPTION(Canceled, evaluateModels(data, options, midway));
    }
};

QTEST_GUILESS_MAIN(TestEvaluation)
#include "tst_evaluation.moc"
