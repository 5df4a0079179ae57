#include "eval/StudyTally.h"

#include "eval/Statistics.h"
#include "util/Error.h"

#include <QJsonArray>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace lipsync {

namespace {

std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

// CSV field: quoted when it holds a separator, quote or line break (RFC 4180).
std::string csvField(const std::string &text)
{
    if (text.find_first_of(",\"\n\r") == std::string::npos)
        return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"')
            out += '"';
        out += c;
    }
    return out + "\"";
}

} // namespace

Eigen::VectorXd bradleyTerry(const Eigen::MatrixXd &wins, int maxIterations, double tolerance,
                             int *iterations)
{
    const Eigen::Index m = wins.rows();
    Eigen::MatrixXd w = wins;
    w.diagonal().setZero();
    const Eigen::MatrixXd games = w + w.transpose(); // N_ij
    const Eigen::VectorXd totalWins = w.rowwise().sum(); // W_i
    Eigen::VectorXd gamma = Eigen::VectorXd::Constant(m, 1.0 / double(std::max<Eigen::Index>(m, 1)));
    int it = 0;
    for (; it < maxIterations; ++it) {
        // Hunter (2004) eq. 3: g_i <- W_i / sum_j N_ij / (g_i + g_j).
        Eigen::VectorXd next(m);
        for (Eigen::Index i = 0; i < m; ++i) {
            double denominator = 0;
            for (Eigen::Index j = 0; j < m; ++j)
                if (j != i && games(i, j) > 0 && gamma(i) + gamma(j) > 0)
                    denominator += games(i, j) / (gamma(i) + gamma(j));
            next(i) = denominator > 0 ? totalWins(i) / denominator : gamma(i);
        }
        const double sum = next.sum();
        if (sum > 0)
            next /= sum;
        const double change = (next - gamma).cwiseAbs().maxCoeff();
        gamma = next;
        if (change < tolerance) {
            ++it;
            break;
        }
    }
    if (iterations)
        *iterations = it;
    return gamma;
}

StudyTally StudyTally::fromStudy(const ForcedChoiceStudy &study)
{
    std::vector<PairTally> counts;
    int unanswered = 0;
    for (const StudySession &session : study.sessions()) {
        for (const StudyTrial &trial : session.trials) {
            if (trial.choice == StudyChoice::Unanswered) {
                ++unanswered;
                continue;
            }
            PairTally count;
            count.a = trial.left;
            count.b = trial.right;
            if (trial.choice == StudyChoice::Left)
                count.preferA = 1;
            else if (trial.choice == StudyChoice::Right)
                count.preferB = 1;
            else
                count.undecided = 1;
            counts.push_back(count);
        }
    }
    StudyTally tally = fromCounts(study.methods(), counts);
    tally.participants = int(study.sessions().size());
    tally.unanswered = unanswered;
    return tally;
}

StudyTally StudyTally::fromCounts(const std::vector<std::string> &methods,
                                  const std::vector<PairTally> &counts)
{
    StudyTally tally;
    tally.methods = methods;
    const int m = int(methods.size());
    for (int a = 0; a < m; ++a)
        for (int b = a + 1; b < m; ++b)
            tally.pairs.push_back(PairTally{a, b, 0, 0, 0, 1.0});
    for (const PairTally &c : counts) {
        if (c.a < 0 || c.b < 0 || c.a >= m || c.b >= m || c.a == c.b)
            throw Error("study tally: invalid method pair (" + std::to_string(c.a) + ", "
                        + std::to_string(c.b) + ")");
        if (c.preferA < 0 || c.preferB < 0 || c.undecided < 0)
            throw Error("study tally: negative count");
        PairTally &p = *std::find_if(tally.pairs.begin(), tally.pairs.end(), [&](const PairTally &q) {
            return q.a == std::min(c.a, c.b) && q.b == std::max(c.a, c.b);
        });
        const bool swapped = c.a > c.b;
        p.preferA += swapped ? c.preferB : c.preferA;
        p.preferB += swapped ? c.preferA : c.preferB;
        p.undecided += c.undecided;
        tally.answered += c.total();
    }
    tally.finalise();
    return tally;
}

void StudyTally::finalise()
{
    const int m = int(methods.size());
    Eigen::MatrixXd wins = Eigen::MatrixXd::Zero(m, m);
    std::vector<MethodScore> scores(static_cast<size_t>(m));
    for (int i = 0; i < m; ++i)
        scores[size_t(i)].method = i;
    for (PairTally &p : pairs) {
        p.pValue = stats::signTestPValue(p.preferA, p.decided());
        wins(p.a, p.b) += p.preferA;
        wins(p.b, p.a) += p.preferB;
        scores[size_t(p.a)].wins += p.preferA;
        scores[size_t(p.a)].losses += p.preferB;
        scores[size_t(p.b)].wins += p.preferB;
        scores[size_t(p.b)].losses += p.preferA;
        scores[size_t(p.a)].undecided += p.undecided;
        scores[size_t(p.b)].undecided += p.undecided;
    }
    std::vector<double> raw;
    for (const PairTally &p : pairs)
        raw.push_back(p.pValue);
    const std::vector<double> adjusted = stats::holmAdjusted(raw);
    for (size_t i = 0; i < pairs.size(); ++i)
        pairs[i].holmPValue = adjusted[i];
    const Eigen::VectorXd strength = bradleyTerry(wins);
    for (int i = 0; i < m; ++i) {
        MethodScore &score = scores[size_t(i)];
        score.strength = strength(i);
        // Wilson score interval at 95 % (z = 1.96) on wins out of the decided trials.
        const double n = score.wins + score.losses;
        if (n > 0) {
            const double z = 1.959963984540054, p = score.wins / n;
            const double centre = (p + z * z / (2 * n)) / (1 + z * z / n);
            const double half = z / (1 + z * z / n) * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n));
            score.realShare = p;
            score.realShareLow = std::max(0.0, centre - half);
            score.realShareHigh = std::min(1.0, centre + half);
        }
    }
    std::stable_sort(scores.begin(), scores.end(), [](const MethodScore &x, const MethodScore &y) {
        return x.strength > y.strength;
    });
    ranking = std::move(scores);
}

const PairTally &StudyTally::pair(int i, int j) const
{
    const int a = std::min(i, j);
    const int b = std::max(i, j);
    for (const PairTally &p : pairs)
        if (p.a == a && p.b == b)
            return p;
    throw Error("study tally: no pair (" + std::to_string(i) + ", " + std::to_string(j) + ")");
}

std::string StudyTally::summary(double alpha,
                                const std::function<std::string(const std::string &)> &methodName) const
{
    std::string text;
    for (size_t r = 0; r < ranking.size(); ++r) {
        if (r > 0) {
            const PairTally &p = pair(ranking[r - 1].method, ranking[r].method);
            text += p.decided() > 0 && p.holmPValue < alpha ? " \u227b " : " \u2248 ";
        }
        const std::string &method = methods[size_t(ranking[r].method)];
        text += methodName ? methodName(method) : method;
    }
    return text;
}

std::string StudyTally::pairsCsv() const
{
    std::string csv = "method_a,method_b,prefer_a,undecided,prefer_b,n_decided,p_value,p_holm\n";
    for (const PairTally &p : pairs)
        csv += csvField(methods[size_t(p.a)]) + "," + csvField(methods[size_t(p.b)]) + ","
               + std::to_string(p.preferA) + "," + std::to_string(p.undecided) + ","
               + std::to_string(p.preferB) + "," + std::to_string(p.decided()) + ","
               + number(p.pValue) + "," + number(p.holmPValue) + "\n";
    return csv;
}

int StudyTally::fewestDecided() const
{
    int fewest = std::numeric_limits<int>::max();
    for (const PairTally &p : pairs)
        fewest = std::min(fewest, p.decided());
    return pairs.empty() ? 0 : fewest;
}

std::string StudyTally::caution() const
{
    const int fewest = fewestDecided();
    if (pairs.empty() || fewest >= kFewAnswers)
        return {};
    return "Few answers: a pair has only " + std::to_string(fewest) + " decided (" + std::to_string(kFewAnswers)
           + " or more are needed before a ranking says much); read the intervals, not the strengths.";
}

std::string StudyTally::rankingCsv() const
{
    std::string csv = "rank,method,strength,judged_real,judged_not_real,undecided,real_share,real_share_low,"
                      "real_share_high\n";
    for (size_t r = 0; r < ranking.size(); ++r) {
        const MethodScore &s = ranking[r];
        csv += std::to_string(r + 1) + "," + csvField(methods[size_t(s.method)]) + ","
               + number(s.strength) + "," + std::to_string(s.wins) + "," + std::to_string(s.losses)
               + "," + std::to_string(s.undecided) + "," + number(s.realShare) + "," + number(s.realShareLow)
               + "," + number(s.realShareHigh) + "\n";
    }
    return csv;
}

QJsonObject StudyTally::toJson() const
{
    QJsonArray methodArray;
    for (const std::string &m : methods)
        methodArray.append(QString::fromStdString(m));
    QJsonArray pairArray;
    for (const PairTally &p : pairs)
        pairArray.append(QJsonObject{{"a", QString::fromStdString(methods[size_t(p.a)])},
                                     {"b", QString::fromStdString(methods[size_t(p.b)])},
                                     {"preferA", p.preferA},
                                     {"undecided", p.undecided},
                                     {"preferB", p.preferB},
                                     {"decided", p.decided()},
                                     {"pValue", p.pValue},
                                     {"pValueHolm", p.holmPValue}});
    QJsonArray rankingArray;
    for (size_t r = 0; r < ranking.size(); ++r) {
        const MethodScore &s = ranking[r];
        rankingArray.append(QJsonObject{{"rank", int(r + 1)},
                                        {"method", QString::fromStdString(methods[size_t(s.method)])},
                                        {"strength", s.strength},
                                        {"judgedReal", s.wins},
                                        {"judgedNotReal", s.losses},
                                        {"undecided", s.undecided},
                                        {"realShare", s.realShare},
                                        {"realShareLow", s.realShareLow},
                                        {"realShareHigh", s.realShareHigh}});
    }
    return QJsonObject{{"methods", methodArray},
                       {"pairs", pairArray},
                       {"ranking", rankingArray},
                       {"summary", QString::fromStdString(summary())},
                       {"caution", QString::fromStdString(caution())},
                       {"participants", participants},
                       {"answered", answered},
                       {"unanswered", unanswered}};
}

} // namespace lipsync
