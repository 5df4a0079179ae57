// The study tally in the form of the paper's Table 1: exact sign-test p-values (checked against
// binomial values computed independently with exact rational arithmetic), the Bradley-Terry
// ranking (Hunter's MM algorithm) and the paper's own counts and ranking line.
#include "eval/Statistics.h"
#include "eval/StudyTally.h"

#include "util/Error.h"

#include <QJsonArray>
#include <QTest>

#include <random>

using namespace lipsync;

namespace {

// Table 1 of Englebienne, Cootes & Rattray (2007): A, prefer A, undecided, prefer B, B.
StudyTally paperTable1()
{
    const std::vector<std::string> methods{"Brand", "DPDS", "reality", "SLDS"};
    return StudyTally::fromCounts(methods, {{0, 1, 5, 7, 54},
                                            {0, 2, 4, 7, 55},
                                            {0, 3, 36, 21, 9},
                                            {1, 2, 29, 11, 26},
                                            {1, 3, 60, 5, 1},
                                            {2, 3, 58, 5, 3}});
}

bool close(double a, double b, double relative)
{
    return std::abs(a - b) <= relative * std::abs(b);
}

} // namespace

class TestStudyTally : public QObject
{
    Q_OBJECT

private slots:
    // Two-sided exact binomial (p = 1/2) tails; the references are 2 sum_{i<=k} C(n,i) / 2^n
    // evaluated with Python's fractions.Fraction (exact), rounded to double.
    void signTest_data()
    {
        QTest::addColumn<int>("k");
        QTest::addColumn<int>("n");
        QTest::addColumn<double>("p");
        QTest::newRow("0 of 10") << 0 << 10 << 0.001953125;
        QTest::newRow("10 of 10") << 10 << 10 << 0.001953125;
        QTest::newRow("2 of 12") << 2 << 12 << 0.03857421875;
        QTest::newRow("5 of 25") << 5 << 25 << 0.0040773153305053711;
        QTest::newRow("10 of 30") << 10 << 30 << 0.098737146705389023;
        QTest::newRow("20 of 29") << 20 << 29 << 0.061428345739841461;
        // n in the thousands and a tail far below double epsilon: no cancellation, no overflow.
        QTest::newRow("1000 of 2100") << 1000 << 2100 << 0.030720707864242296;
        QTest::newRow("40 of 200") << 40 << 200 << 3.3840159775152892e-18;
        QTest::newRow("3 of 6 (even split)") << 3 << 6 << 1.0;
        QTest::newRow("0 of 1") << 0 << 1 << 1.0;
        QTest::newRow("no decided answers") << 0 << 0 << 1.0;
    }
    void signTest()
    {
        QFETCH(int, k);
        QFETCH(int, n);
        QFETCH(double, p);
        QVERIFY2(close(stats::signTestPValue(k, n), p, 1e-10),
                 qPrintable(QString("%1 vs %2").arg(stats::signTestPValue(k, n), 0, 'g', 17).arg(p, 0, 'g', 17)));
    }

    // The paper reports no p-values; these are the exact ones for its counts (undecided
    // excluded), computed independently as above.
    void paperTable1PValues()
    {
        const StudyTally tally = paperTable1();
        QCOMPARE(int(tally.pairs.size()), 6);
        const double expected[6] = {1.9067358802971057e-11, 1.6979681549678105e-12,
                                    6.5746632458285603e-05, 0.78770618967004347,
                                    5.377642775528102e-17,  3.2857397358476703e-14};
        for (int i = 0; i < 6; ++i)
            QVERIFY2(close(tally.pairs[size_t(i)].pValue, expected[i], 1e-9),
                     qPrintable(QString::number(tally.pairs[size_t(i)].pValue, 'g', 17)));
        // Either order finds the pair, stored as (Brand, DPDS): Brand judged real 5 times.
        QCOMPARE(tally.pair(1, 0).a, 0);
        QCOMPARE(tally.pair(1, 0).preferA, 5);
        QCOMPARE(tally.pair(1, 0).preferB, 54);
        QCOMPARE(tally.answered, 6 * 66); // 33 volunteers x 2 presentations per pair
    }

    // Holm's step-down adjustment by hand: sorted p_(i) times m - i + 1, made non-decreasing,
    // capped at 1, in the input order.
    void holmAdjustmentByHand()
    {
        const std::vector<double> adjusted = stats::holmAdjusted({0.01, 0.04, 0.03, 0.005});
        const std::vector<double> expected{0.03, 0.06, 0.06, 0.02}; // 3 x .01, max(2 x .03, .04), 2 x .03, 4 x .005
        for (size_t i = 0; i < expected.size(); ++i)
            QVERIFY2(close(adjusted[i], expected[i], 1e-14), qPrintable(QString::number(adjusted[i], 'g', 17)));
        QCOMPARE(stats::holmAdjusted({0.5, 0.6}), (std::vector<double>{1.0, 1.0}));
        QCOMPARE(stats::holmAdjusted({0.2}), std::vector<double>{0.2});
        QVERIFY(stats::holmAdjusted({}).empty());
        // The paper's Table 1 (m = 6), ranks 4, 3, 5, 6, 1, 2 of the six p-values above.
        const StudyTally tally = paperTable1();
        const double expectedTable[6] = {3 * 1.9067358802971057e-11, 4 * 1.6979681549678105e-12,
                                         2 * 6.5746632458285603e-05, 0.78770618967004347,
                                         6 * 5.377642775528102e-17,  5 * 3.2857397358476703e-14};
        for (int i = 0; i < 6; ++i)
            QVERIFY2(close(tally.pairs[size_t(i)].holmPValue, expectedTable[i], 1e-9),
                     qPrintable(QString::number(tally.pairs[size_t(i)].holmPValue, 'g', 17)));
        QVERIFY(close(tally.toJson().value("pairs").toArray()[0].toObject().value("pValueHolm").toDouble(),
                      expectedTable[0], 1e-9));
    }

    // The summary's "≻" needs the Holm-adjusted p below alpha: A beats B 14 to 4 (sign test
    // p = 0.0309 alone), but with A-C (20 to 0) and B-C (5 to 5) tested too, Holm gives
    // 2 x 0.0309 = 0.0618 for A-B.
    void summaryUsesHolmAdjustedPValues()
    {
        std::vector<PairTally> counts(3);
        counts[0] = PairTally{0, 1, 14, 0, 4};
        counts[1] = PairTally{0, 2, 20, 0, 0};
        counts[2] = PairTally{1, 2, 5, 0, 5};
        const StudyTally tally = StudyTally::fromCounts({"A", "B", "C"}, counts);
        QVERIFY(close(tally.pair(0, 1).pValue, 2 * 4048.0 / 262144.0, 1e-12));
        QVERIFY(close(tally.pair(0, 1).holmPValue, 4 * 4048.0 / 262144.0, 1e-12));
        QVERIFY(close(tally.pair(0, 2).holmPValue, 3 * 2 * std::pow(0.5, 20), 1e-12));
        QCOMPARE(tally.pair(1, 2).holmPValue, 1.0);
        QCOMPARE(QString::fromStdString(tally.summary(0.05)), QString("A ≈ B ≈ C"));
        QCOMPARE(QString::fromStdString(tally.summary(0.07)), QString("A ≻ B ≈ C"));
    }

    // The paper's conclusion line under Table 1.
    void paperTable1Ranking()
    {
        const StudyTally tally = paperTable1();
        QCOMPARE(QString::fromStdString(tally.summary()), QString("DPDS ≈ reality ≻ Brand ≻ SLDS"));
        QCOMPARE(tally.ranking[0].method, 1);
        QCOMPARE(tally.ranking[0].wins, 54 + 29 + 60);
        QCOMPARE(tally.ranking[0].losses, 5 + 26 + 1);
        QCOMPARE(tally.ranking[0].undecided, 7 + 11 + 5);
        double sum = 0;
        for (const MethodScore &s : tally.ranking)
            sum += s.strength;
        QVERIFY(std::abs(sum - 1.0) < 1e-12);
        const QString csv = QString::fromStdString(tally.pairsCsv());
        QVERIFY2(csv.startsWith("method_a,method_b,prefer_a,undecided,prefer_b,n_decided,p_value,p_holm\n"
                                "Brand,DPDS,5,7,54,59,1.90674e-11,5.72021e-11\n"),
                 qPrintable(csv));
        const QString ranking = QString::fromStdString(tally.rankingCsv());
        QVERIFY2(ranking.section('\n', 1, 1).startsWith("1,DPDS,"), qPrintable(ranking));
        QVERIFY2(ranking.section('\n', 4, 4).startsWith("4,SLDS,"), qPrintable(ranking));
    }

    // With expected counts N g_i / (g_i + g_j) the maximum-likelihood strengths are exactly g.
    void bradleyTerryRecoversStrengths()
    {
        const Eigen::Vector4d truth(0.1, 0.4, 0.3, 0.2);
        Eigen::MatrixXd wins = Eigen::MatrixXd::Zero(4, 4);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j)
                if (i != j)
                    wins(i, j) = 100.0 * truth(i) / (truth(i) + truth(j));
        int iterations = 0;
        const Eigen::VectorXd g = bradleyTerry(wins, 10000, 1e-13, &iterations);
        QVERIFY2((g - truth).cwiseAbs().maxCoeff() < 1e-8, qPrintable(QString::number((g - truth).norm())));
        QVERIFY(iterations > 1 && iterations < 10000);
    }

    // Simulated participants with known strengths: the fitted order is the true order, and the
    // fit satisfies the likelihood equations W_i = sum_j N_ij g_i / (g_i + g_j).
    void bradleyTerryOrderFromSimulatedStudy()
    {
        const std::vector<double> truth{0.05, 0.35, 0.15, 0.45};
        const std::vector<std::string> methods{"hmm", "dpds", "brand", "real"};
        ForcedChoiceStudy study(methods, {"u1", "u2", "u3"}, 11, 2);
        std::mt19937_64 rng(5);
        std::uniform_real_distribution<double> uniform(0, 1);
        for (int p = 0; p < 60; ++p) {
            study.addParticipant("P" + std::to_string(p));
            StudySession &s = study.session(p);
            for (size_t t = 0; t < s.trials.size(); ++t) {
                const double gl = truth[size_t(s.trials[t].left)];
                const double gr = truth[size_t(s.trials[t].right)];
                const double u = uniform(rng);
                s.trials[t].choice = u < 0.1 ? StudyChoice::Undecided
                                   : uniform(rng) < gl / (gl + gr) ? StudyChoice::Left
                                                                   : StudyChoice::Right;
            }
        }
        const StudyTally tally = StudyTally::fromStudy(study);
        QCOMPARE(tally.participants, 60);
        QCOMPARE(tally.answered, 60 * 24);
        QCOMPARE(tally.unanswered, 0);
        for (const PairTally &p : tally.pairs)
            QCOMPARE(p.total(), 60 * 4); // each pair twice per repeat, two repeats
        const std::vector<int> expectedOrder{3, 1, 2, 0};
        for (size_t r = 0; r < 4; ++r)
            QCOMPARE(tally.ranking[r].method, expectedOrder[r]);

        Eigen::VectorXd g(4);
        for (const MethodScore &s : tally.ranking)
            g(s.method) = s.strength;
        for (int i = 0; i < 4; ++i) {
            double expectedWins = 0;
            for (int j = 0; j < 4; ++j)
                if (j != i)
                    expectedWins += tally.pair(i, j).decided() * g(i) / (g(i) + g(j));
            const MethodScore &s = *std::find_if(tally.ranking.begin(), tally.ranking.end(),
                                                 [&](const MethodScore &m) { return m.method == i; });
            QVERIFY2(std::abs(expectedWins - s.wins) < 1e-6,
                     qPrintable(QString("%1 vs %2").arg(expectedWins).arg(s.wins)));
        }
    }

    // Answers are attributed to the method on the chosen side, whichever side it sat on.
    void answersMapToMethods()
    {
        ForcedChoiceStudy study({"real", "dpds", "slds"}, {"u"}, 2);
        study.addParticipant("P1");
        StudySession &s = study.session(0);
        for (StudyTrial &t : s.trials) // always picks "real" when shown; else undecided
            t.choice = t.left == 0 ? StudyChoice::Left : t.right == 0 ? StudyChoice::Right
                                                                      : StudyChoice::Undecided;
        s.trials.back().choice = StudyChoice::Unanswered;
        const StudyTally tally = StudyTally::fromStudy(study);
        const PairTally &realDpds = tally.pair(0, 1);
        const PairTally &realSlds = tally.pair(0, 2);
        QCOMPARE(realDpds.preferA + realSlds.preferA, 4 - (s.trials.back().left == 0 || s.trials.back().right == 0));
        QCOMPARE(realDpds.preferB, 0);
        QCOMPARE(realSlds.preferB, 0);
        QCOMPARE(tally.pair(1, 2).undecided + tally.pair(1, 2).preferA + tally.pair(1, 2).preferB,
                 2 - (s.trials.back().left != 0 && s.trials.back().right != 0));
        QCOMPARE(tally.pair(1, 2).decided(), 0);
        QCOMPARE(tally.pair(1, 2).pValue, 1.0);
        QCOMPARE(tally.unanswered, 1);
        QCOMPARE(tally.ranking[0].method, 0);
        QCOMPARE(tally.ranking[0].strength, 1.0); // never beaten: all the strength
    }

    void countsInEitherOrderAddUp()
    {
        const StudyTally tally = StudyTally::fromCounts({"a", "b"}, {{0, 1, 3, 1, 2}, {1, 0, 4, 0, 5}});
        QCOMPARE(tally.pair(0, 1).preferA, 3 + 5);
        QCOMPARE(tally.pair(0, 1).preferB, 2 + 4);
        QCOMPARE(tally.pair(0, 1).undecided, 1);
        QVERIFY_THROWS_EXCEPTION(Error, StudyTally::fromCounts({"a", "b"}, {{0, 0, 1, 0, 1}}));
        QVERIFY_THROWS_EXCEPTION(Error, StudyTally::fromCounts({"a", "b"}, {{0, 2, 1, 0, 1}}));
    }

    // Each method's share judged real with its 95 % Wilson interval (by hand: 8 of 10 gives
    // 0.490-0.943), and a caution while some pair has fewer than kFewAnswers decided answers.
    void intervalsAndACautionOnFewAnswers()
    {
        const StudyTally few = StudyTally::fromCounts({"a", "b"}, {{0, 1, 5, 2, 2}});
        QVERIFY(!few.caution().empty());
        QCOMPARE(few.fewestDecided(), 7);
        const StudyTally ten = StudyTally::fromCounts({"a", "b"}, {{0, 1, 8, 0, 2}});
        QVERIFY(ten.caution().empty());
        const MethodScore &a = ten.ranking[0];
        QCOMPARE(a.method, 0);
        QCOMPARE(a.realShare, 0.8);
        QVERIFY(std::abs(a.realShareLow - 0.4902) < 1e-3 && std::abs(a.realShareHigh - 0.9433) < 1e-3);
        const MethodScore &b = ten.ranking[1];
        QVERIFY(std::abs(b.realShareLow - (1 - a.realShareHigh)) < 1e-12); // symmetric
        QVERIFY(paperTable1().caution().empty()); // the paper's 80 sequences per pair
        QVERIFY(ten.rankingCsv().find("real_share_low") != std::string::npos);
        QVERIFY(std::abs(ten.toJson().value("ranking").toArray()[0].toObject().value("realShareHigh").toDouble()
                         - a.realShareHigh) < 1e-12);
    }

    void jsonHoldsTheTable()
    {
        const QJsonObject json = paperTable1().toJson();
        QCOMPARE(json.value("summary").toString(), QString("DPDS ≈ reality ≻ Brand ≻ SLDS"));
        QCOMPARE(json.value("pairs").toArray().size(), 6);
        QCOMPARE(json.value("pairs").toArray()[0].toObject().value("preferB").toInt(), 54);
        QCOMPARE(json.value("ranking").toArray()[0].toObject().value("method").toString(), QString("DPDS"));
    }
};

QTEST_GUILESS_MAIN(TestStudyTally)
#include "tst_studytally.moc"
