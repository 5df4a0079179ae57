#include "eval/Evaluation.h"

#include "eval/CrossValidation.h"
#include "eval/Metrics.h"
#include "eval/Statistics.h"
#include "tasks/Feedback.h"

#include <QJsonArray>

#include <algorithm>
#include <chrono>
#include <memory>
#include <sstream>

namespace lipsync {

const std::vector<std::string> &evaluationMetrics()
{
    static const std::vector<std::string> names{"l1", "rms", "linf", "loglik"};
    return names;
}

EvaluationResult evaluateModels(const std::vector<LabelledSequence> &sequences,
                                const EvaluationOptions &options, Feedback &feedback)
{
    validateSequences(sequences);
    for (const std::string &kind : options.kinds)
        createDynamicModel(kind); // reject unknown kinds before any work
    EvaluationResult result;
    result.folds = options.folds;
    result.seed = options.seed;
    result.sequences = int(sequences.size());
    for (const LabelledSequence &s : sequences)
        result.frames += s.frameCount();
    result.foldMembers = makeFolds(int(sequences.size()), options.folds, options.seed);
    for (const std::string &kind : options.kinds) {
        ModelEvaluation m;
        m.kind = kind;
        for (const std::string &metric : evaluationMetrics())
            m.metrics[metric];
        result.models.push_back(m);
    }
    const double steps = double(options.folds * options.kinds.size());
    int step = 0;
    for (int f = 0; f < options.folds; ++f) {
        std::vector<bool> isTest(sequences.size(), false);
        for (int i : result.foldMembers[size_t(f)])
            isTest[size_t(i)] = true;
        std::vector<LabelledSequence> training;
        for (size_t i = 0; i < sequences.size(); ++i)
            if (!isTest[i])
                training.push_back(sequences[i]);
        // The DPDS is trained before the SLDS, which starts from it (§3.4 initialisation) instead
        // of training its own: the SLDS training time then excludes the shared DPDS fit.
        std::vector<size_t> order(result.models.size());
        for (size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            return result.models[a].kind == "dpds" && result.models[b].kind != "dpds";
        });
        std::shared_ptr<const DpdsModel> foldDpds;
        for (size_t index : order) {
            ModelEvaluation &m = result.models[index];
            feedback.throwIfCanceled();
            feedback.setStatus("fold " + std::to_string(f + 1) + "/" + std::to_string(options.folds)
                               + ": " + m.kind);
            std::shared_ptr<DynamicModel> model = createDynamicModel(m.kind, options.modelOptions);
            if (auto *slds = dynamic_cast<SldsModel *>(model.get()); slds && foldDpds)
                slds->setInitialisation(foldDpds);
            Feedback child(feedback, step / steps, (step + 1) / steps);
            const auto start = std::chrono::steady_clock::now();
            model->train(training, child);
            if (m.kind == "dpds")
                foldDpds = std::static_pointer_cast<const DpdsModel>(model);
            m.trainingSeconds.push_back(
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
            // Fold value = mean over the fold's test sequences, each weighted equally (§6.3).
            double l1 = 0, rms = 0, linf = 0, ll = 0;
            const std::vector<int> &test = result.foldMembers[size_t(f)];
            for (int i : test) {
                const LabelledSequence &s = sequences[size_t(i)];
                const SequenceErrors e = sequenceErrors(model->generate(s.labels), s.features);
                l1 += e.l1;
                rms += e.rms;
                linf += e.linf;
                ll += model->logLikelihood(s.labels, s.features) / double(s.frameCount());
            }
            const double n = double(test.size());
            m.metrics["l1"].folds.push_back(l1 / n);
            m.metrics["rms"].folds.push_back(rms / n);
            m.metrics["linf"].folds.push_back(linf / n);
            m.metrics["loglik"].folds.push_back(ll / n);
            ++step;
            feedback.setProgress(step / steps);
        }
    }
    for (ModelEvaluation &m : result.models)
        for (auto &[name, summary] : m.metrics) {
            const stats::MeanInterval interval = stats::meanWithCi95(summary.folds);
            summary.mean = interval.mean;
            summary.ci95 = interval.halfWidth;
        }
    for (size_t a = 0; a < result.models.size(); ++a)
        for (size_t b = a + 1; b < result.models.size(); ++b)
            for (const std::string &metric : evaluationMetrics()) {
                const MetricSummary &sa = result.models[a].metrics[metric];
                const MetricSummary &sb = result.models[b].metrics[metric];
                const stats::TTest t = stats::pairedTTest(sa.folds, sb.folds);
                MetricComparison c;
                c.metric = metric;
                c.a = result.models[a].kind;
                c.b = result.models[b].kind;
                c.meanDifference = t.meanDifference;
                c.t = t.t;
                c.p = t.p;
                c.intervalsOverlap = std::abs(sa.mean - sb.mean) <= sa.ci95 + sb.ci95;
                result.comparisons.push_back(c);
            }
    return result;
}

namespace {
QJsonArray toArray(const std::vector<double> &v)
{
    QJsonArray a;
    for (double x : v)
        a.append(x);
    return a;
}
} // namespace

QJsonObject EvaluationResult::toJson() const
{
    QJsonObject o;
    o[QStringLiteral("folds")] = folds;
    o[QStringLiteral("seed")] = QString::number(seed);
    o[QStringLiteral("sequences")] = sequences;
    o[QStringLiteral("frames")] = double(frames);
    QJsonObject modelsObject;
    for (const ModelEvaluation &m : models) {
        QJsonObject mo;
        for (const auto &[name, summary] : m.metrics) {
            QJsonObject so;
            so[QStringLiteral("mean")] = summary.mean;
            so[QStringLiteral("ci95")] = summary.ci95;
            so[QStringLiteral("folds")] = toArray(summary.folds);
            mo[QString::fromStdString(name)] = so;
        }
        double total = 0;
        for (double s : m.trainingSeconds)
            total += s;
        mo[QStringLiteral("trainingSeconds")] = total;
        mo[QStringLiteral("trainingSecondsPerFold")] = toArray(m.trainingSeconds);
        modelsObject[QString::fromStdString(m.kind)] = mo;
    }
    o[QStringLiteral("models")] = modelsObject;
    QJsonArray comparisonArray;
    for (const MetricComparison &c : comparisons) {
        QJsonObject co;
        co[QStringLiteral("metric")] = QString::fromStdString(c.metric);
        co[QStringLiteral("a")] = QString::fromStdString(c.a);
        co[QStringLiteral("b")] = QString::fromStdString(c.b);
        co[QStringLiteral("meanDifference")] = c.meanDifference;
        co[QStringLiteral("t")] = std::isfinite(c.t) ? c.t : (c.t > 0 ? 1e308 : -1e308);
        co[QStringLiteral("p")] = c.p;
        co[QStringLiteral("intervalsOverlap")] = c.intervalsOverlap;
        comparisonArray.append(co);
    }
    o[QStringLiteral("comparisons")] = comparisonArray;
    return o;
}

std::string EvaluationResult::toCsv() const
{
    std::ostringstream out;
    out.precision(10);
    out << "model,metric,mean,ci95";
    for (int f = 0; f < folds; ++f)
        out << ",fold" << f + 1;
    out << "\n";
    for (const ModelEvaluation &m : models) {
        for (const std::string &name : evaluationMetrics()) {
            const MetricSummary &s = m.metrics.at(name);
            out << m.kind << "," << name << "," << s.mean << "," << s.ci95;
            for (double v : s.folds)
                out << "," << v;
            out << "\n";
        }
        const stats::MeanInterval t = stats::meanWithCi95(m.trainingSeconds);
        out << m.kind << ",trainingSeconds," << t.mean << "," << t.halfWidth;
        for (double v : m.trainingSeconds)
            out << "," << v;
        out << "\n";
    }
    return out.str();
}

} // namespace lipsync
