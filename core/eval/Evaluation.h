#pragma once
// The cross-validated comparison of the dynamic models (docs/models.md §6.1-6.3): every model is
// trained on the same k-1 folds and tested on the held-out one; per test sequence L1, RMS, Linf
// (§6.2) of the generated trajectory and the log-likelihood per frame (log p(y | labels), a density
// over the face trajectory for every model: Brand's trajectory-HMM density, not its [y; Δy]
// objective, which is not comparable, §2.2 and §6.2); fold value = mean over the fold's sequences
// (equal weight); reported as the mean over folds with a 95 % t interval, plus paired t-tests
// between models. Results serialise to JSON and CSV.
#include "dynamics/LabelledSequence.h"
#include "dynamics/ModelFile.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;

struct EvaluationOptions
{
    int folds = 10;
    std::uint64_t seed = 2007;
    std::vector<std::string> kinds = dynamicModelKinds(); // ids (dynamics/ModelKind.h)
    ModelOptions modelOptions;
    // Train each fold's models on only this many seconds of speech (0: all of the training
    // folds): the training sequences in a random order (seeded by the fold), taken until their
    // speech (frames not labelled silence or breath) reaches it. For learning curves.
    double trainingSpeechSeconds = 0.0;
    // Folds are independent: run them concurrently on the global thread pool, each model
    // single-threaded. false: one fold at a time, models threaded as modelOptions say.
    bool parallelFolds = true;
};

// A figure for the JSON reports: finite values as numbers, NaN and infinities (a metric that
// could not be computed) as null, which JSON can hold.
QJsonValue jsonNumber(double value);
QJsonArray jsonNumbers(const std::vector<double> &values);

struct MetricSummary
{
    std::vector<double> folds; // fold values e_f
    double mean = 0.0;
    double ci95 = 0.0; // half-width

    // {"mean", "ci95", "folds"}; values that are not finite are null.
    QJsonObject toJson() const;
};

struct ModelEvaluation
{
    std::string kind;
    std::map<std::string, MetricSummary> metrics; // "l1", "rms", "linf", "loglik"
    std::vector<double> trainingSeconds;           // per fold, wall
    // Per fold, CPU of the training thread: the whole training when folds run in parallel (models
    // single-threaded); without the per-dimension worker threads otherwise.
    std::vector<double> trainingCpuSeconds;
};

struct MetricComparison
{
    std::string metric, a, b;
    double meanDifference = 0.0, t = 0.0, p = 1.0;
    bool intervalsOverlap = true;
};

struct EvaluationResult
{
    int folds = 0;
    std::uint64_t seed = 0;
    int sequences = 0;
    long long frames = 0;
    std::vector<std::vector<int>> foldMembers;
    std::vector<ModelEvaluation> models;
    std::vector<MetricComparison> comparisons;

    QJsonObject toJson() const;
    // One row per model and metric: model,metric,mean,ci95,fold1..foldK (and training seconds).
    std::string toCsv() const;
};

const std::vector<std::string> &evaluationMetrics();
// What the "loglik" metric is, for the reports (JSON, the CLI table).
const char *logLikelihoodNote();

// The sequences of `all` not in `test` (a fold's training set, in order); with
// `speechSeconds` > 0, only as many of them, in an order drawn with `seed`, as hold that much
// speech (EvaluationOptions::trainingSpeechSeconds).
std::vector<LabelledSequence> trainingSequences(const std::vector<LabelledSequence> &all,
                                                const std::vector<int> &test, double speechSeconds = 0.0,
                                                std::uint64_t seed = 0);
// Seconds of speech in `sequence`: its frames not labelled silence or breath.
double speechSeconds(const LabelledSequence &sequence);

// One fold's models, trained on `training` (§6.1): one per entry of `kinds`, in that order; the
// DPDS is trained before the SLDS, which starts from it (§3.4). `wallSeconds` and `cpuSeconds`
// (if given) receive each model's training time (CPU of the calling thread). The status names
// each model after `statusPrefix`.
std::vector<std::shared_ptr<DynamicModel>> trainFoldModels(const std::vector<LabelledSequence> &training,
                                                           const std::vector<std::string> &kinds,
                                                           const ModelOptions &modelOptions,
                                                           Feedback &feedback,
                                                           const std::string &statusPrefix = {},
                                                           std::vector<double> *wallSeconds = nullptr,
                                                           std::vector<double> *cpuSeconds = nullptr);

// Throws lipsync::Error for invalid sequences (validateSequences) or too few sequences.
EvaluationResult evaluateModels(const std::vector<LabelledSequence> &sequences,
                                const EvaluationOptions &options, Feedback &feedback);

} // namespace lipsync
