#include "eval/Evaluation.h"

#include "dynamics/ContextDependentModel.h"
#include "eval/CrossValidation.h"
#include "eval/Metrics.h"
#include "eval/Statistics.h"
#include "tasks/BlockingMap.h"
#include "tasks/Feedback.h"
#include "util/PhoneSet.h"

#include <QJsonArray>
#include <QThreadPool>

#include <algorithm>
#include <atomic>
#include <exception>
#include <chrono>
#include <ctime>
#include <memory>
#include <mutex>
#include <numeric>
#include <random>
#include <sstream>

namespace lipsync {

const std::vector<std::string> &evaluationMetrics()
{
    static const std::vector<std::string> names{"l1", "rms", "linf", "loglik"};
    return names;
}

const char *logLikelihoodNote()
{
    return "loglik: log p(y | labels) per frame, a density over the face trajectory for every model; "
           "Brand's is its trajectory-HMM density N(y; MLPG mean, H^-1) (docs/models.md §2.2), not its "
           "training density over [y, delta y], which is not comparable with the others";
}

namespace {

// CPU seconds of the calling thread: on a shared machine the wall time of a training says little.
double threadCpuSeconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// One model's outcome on one fold.
struct FoldOutcome
{
    double trainingSeconds = 0.0, trainingCpuSeconds = 0.0;
    double l1 = 0.0, rms = 0.0, linf = 0.0, loglik = 0.0;
};

// Trains every model on the training folds and scores it on fold `f` (§6.1-6.3). Independent of
// every other fold, so folds can run concurrently.
std::vector<FoldOutcome> runFold(const std::vector<LabelledSequence> &sequences,
                                 const std::vector<int> &test, const EvaluationOptions &options,
                                 const ModelOptions &modelOptions, int f, Feedback &feedback)
{
    std::vector<double> wall, cpu;
    const std::vector<std::shared_ptr<DynamicModel>> models
        = trainFoldModels(trainingSequences(sequences, test, options.trainingSpeechSeconds, options.seed + 1 + f),
                          options.kinds, modelOptions, feedback,
                          "fold " + std::to_string(f + 1) + "/" + std::to_string(options.folds) + ": ", &wall, &cpu);
    std::vector<FoldOutcome> out(options.kinds.size());
    for (size_t index = 0; index < models.size(); ++index) {
        const DynamicModel &model = *models[index];
        FoldOutcome &o = out[index];
        o.trainingSeconds = wall[index];
        o.trainingCpuSeconds = cpu[index];
        // Fold value = mean over the fold's test sequences, each weighted equally (§6.3).
        for (int i : test) {
            const LabelledSequence &s = sequences[size_t(i)];
            const SequenceErrors e = sequenceErrors(model.generate(s.labels), s.features);
            o.l1 += e.l1;
            o.rms += e.rms;
            o.linf += e.linf;
            // A density over y for every model (Brand's trajectory density, §2.2), so the
            // models' values are comparable.
            o.loglik += model.trajectoryLogLikelihood(s.labels, s.features) / double(s.frameCount());
        }
        const double n = double(test.size());
        o.l1 /= n;
        o.rms /= n;
        o.linf /= n;
        o.loglik /= n;
    }
    return out;
}

} // namespace

double speechSeconds(const LabelledSequence &sequence)
{
    const auto speech = std::count_if(sequence.labels.begin(), sequence.labels.end(),
                                      [](int label) { return PhoneSet::isSpeech(label); });
    return double(speech) / (sequence.frameRate > 0 ? sequence.frameRate : 25.0);
}

std::vector<LabelledSequence> trainingSequences(const std::vector<LabelledSequence> &all,
                                                const std::vector<int> &test, double speechLimit,
                                                std::uint64_t seed)
{
    std::vector<bool> isTest(all.size(), false);
    for (int i : test)
        isTest[size_t(i)] = true;
    std::vector<int> order;
    for (size_t i = 0; i < all.size(); ++i)
        if (!isTest[i])
            order.push_back(int(i));
    if (speechLimit > 0) {
        // Fisher-Yates on std::mt19937_64, as makeFolds: the same subset on every platform.
        std::mt19937_64 random(seed);
        for (size_t i = order.size(); i > 1; --i)
            std::swap(order[i - 1], order[size_t(random() % i)]);
        double taken = 0.0;
        size_t keep = 0;
        while (keep < order.size() && taken < speechLimit)
            taken += speechSeconds(all[size_t(order[keep++])]);
        order.resize(keep);
        std::sort(order.begin(), order.end());
    }
    std::vector<LabelledSequence> training;
    for (int i : order)
        training.push_back(all[size_t(i)]);
    return training;
}

std::vector<std::shared_ptr<DynamicModel>> trainFoldModels(const std::vector<LabelledSequence> &training,
                                                           const std::vector<std::string> &kinds,
                                                           const ModelOptions &modelOptions,
                                                           Feedback &feedback, const std::string &statusPrefix,
                                                           std::vector<double> *wallSeconds,
                                                           std::vector<double> *cpuSeconds)
{
    // The DPDS is trained before the SLDS, which starts from it (§3.4 initialisation) instead
    // of training its own: the SLDS training time then excludes the shared DPDS fit.
    std::vector<size_t> order(kinds.size());
    for (size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
        const auto isDpds = [&](size_t i) { return parseModelKind(kinds[i]) == ModelKind::Dpds; };
        return isDpds(a) && !isDpds(b);
    });
    std::vector<std::shared_ptr<DynamicModel>> models(kinds.size());
    if (wallSeconds)
        wallSeconds->assign(kinds.size(), 0.0);
    if (cpuSeconds)
        cpuSeconds->assign(kinds.size(), 0.0);
    std::shared_ptr<const DpdsModel> foldDpds;
    for (size_t step = 0; step < order.size(); ++step) {
        const size_t index = order[step];
        const std::string &kind = kinds[index];
        feedback.throwIfCanceled();
        feedback.setStatus(statusPrefix + kind);
        std::shared_ptr<DynamicModel> model = createDynamicModel(kind, modelOptions);
        // With context states both are inner models over the same trees (grown on the same
        // training part), so the DPDS's states are the SLDS's.
        DynamicModel *paperModel = model.get();
        if (auto *context = dynamic_cast<ContextDependentModel *>(paperModel))
            paperModel = &context->inner();
        if (auto *slds = dynamic_cast<SldsModel *>(paperModel); slds && foldDpds)
            slds->setInitialisation(foldDpds);
        const double steps = double(order.size());
        Feedback child(feedback, double(step) / steps, double(step + 1) / steps);
        const auto start = std::chrono::steady_clock::now();
        const double cpuStart = threadCpuSeconds();
        model->train(training, child);
        if (cpuSeconds)
            (*cpuSeconds)[index] = threadCpuSeconds() - cpuStart;
        if (wallSeconds)
            (*wallSeconds)[index] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (parseModelKind(kind) == ModelKind::Dpds)
            foldDpds = std::shared_ptr<const DpdsModel>(model, dynamic_cast<const DpdsModel *>(paperModel));
        models[index] = std::move(model);
        feedback.setProgress(double(step + 1) / steps);
    }
    return models;
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

    std::vector<std::vector<FoldOutcome>> outcomes(size_t(options.folds));
    const bool parallel = options.parallelFolds && QThreadPool::globalInstance()->maxThreadCount() > 1;
    if (!parallel) {
        for (int f = 0; f < options.folds; ++f) {
            Feedback child(feedback, double(f) / options.folds, double(f + 1) / options.folds);
            outcomes[size_t(f)] = runFold(sequences, result.foldMembers[size_t(f)], options,
                                          options.modelOptions, f, child);
        }
    } else {
        // Folds are independent (§6.1): run them concurrently, each model single-threaded (its
        // per-dimension parallelism would only add a barrier per iteration). Results are stored
        // per fold, so they do not depend on the schedule. Progress is the mean over folds;
        // a cancel of `feedback` reaches the folds through their progress reports.
        ModelOptions serial = options.modelOptions;
        serial.dpds.threads = 1;
        serial.slds.threads = 1;
        std::mutex mutex;
        std::vector<double> progress(size_t(options.folds), 0.0);
        std::vector<int> folds(size_t(options.folds));
        std::iota(folds.begin(), folds.end(), 0);
        std::exception_ptr firstError;
        std::atomic<bool> stop{false};
        lipsync::blockingMap(folds, [&](int f) {
            Feedback own;
            auto pollCancel = [&] {
                if (stop.load() || feedback.isCanceled())
                    own.cancel();
            };
            own.onProgress = [&, f](double fraction) {
                pollCancel();
                const std::lock_guard lock(mutex);
                progress[size_t(f)] = fraction;
                feedback.setProgress(std::accumulate(progress.begin(), progress.end(), 0.0) / options.folds);
            };
            own.onStatus = [&](const std::string &status) {
                pollCancel();
                const std::lock_guard lock(mutex);
                feedback.setStatus(status);
            };
            own.onIteration = [&](int, double) { pollCancel(); };
            try {
                pollCancel();
                outcomes[size_t(f)] = runFold(sequences, result.foldMembers[size_t(f)], options, serial, f, own);
            } catch (...) {
                // The first failure (an Error, or the user's cancel) stops the other folds and is
                // rethrown once all of them have returned.
                const std::lock_guard lock(mutex);
                if (!firstError)
                    firstError = std::current_exception();
                stop = true;
            }
        });
        if (firstError)
            std::rethrow_exception(firstError);
    }
    feedback.throwIfCanceled();
    for (size_t index = 0; index < options.kinds.size(); ++index) {
        ModelEvaluation m;
        m.kind = options.kinds[index];
        for (const std::vector<FoldOutcome> &fold : outcomes) {
            const FoldOutcome &o = fold[index];
            m.metrics["l1"].folds.push_back(o.l1);
            m.metrics["rms"].folds.push_back(o.rms);
            m.metrics["linf"].folds.push_back(o.linf);
            m.metrics["loglik"].folds.push_back(o.loglik);
            m.trainingSeconds.push_back(o.trainingSeconds);
            m.trainingCpuSeconds.push_back(o.trainingCpuSeconds);
        }
        result.models.push_back(std::move(m));
    }
    feedback.setProgress(1.0);
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

QJsonValue jsonNumber(double value)
{
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue();
}

QJsonArray jsonNumbers(const std::vector<double> &values)
{
    QJsonArray a;
    for (double v : values)
        a.append(jsonNumber(v));
    return a;
}

QJsonObject MetricSummary::toJson() const
{
    QJsonObject o;
    o[QStringLiteral("mean")] = jsonNumber(mean);
    o[QStringLiteral("ci95")] = jsonNumber(ci95);
    o[QStringLiteral("folds")] = jsonNumbers(folds);
    return o;
}

QJsonObject EvaluationResult::toJson() const
{
    QJsonObject o;
    o[QStringLiteral("folds")] = folds;
    o[QStringLiteral("seed")] = QString::number(seed);
    o[QStringLiteral("sequences")] = sequences;
    o[QStringLiteral("frames")] = double(frames);
    o[QStringLiteral("loglikNote")] = QString::fromUtf8(logLikelihoodNote());
    QJsonObject modelsObject;
    for (const ModelEvaluation &m : models) {
        QJsonObject mo;
        for (const auto &[name, summary] : m.metrics)
            mo[QString::fromStdString(name)] = summary.toJson();
        double total = 0;
        for (double s : m.trainingSeconds)
            total += s;
        mo[QStringLiteral("trainingSeconds")] = total;
        mo[QStringLiteral("trainingSecondsPerFold")] = toArray(m.trainingSeconds);
        mo[QStringLiteral("trainingCpuSeconds")] = std::accumulate(m.trainingCpuSeconds.begin(),
                                                                   m.trainingCpuSeconds.end(), 0.0);
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
