// lipsync evaluate: k-fold cross-validation of the dynamic models (docs/models.md §6).
#include "Command.h"
#include "TrainingData.h"

#include "eval/Evaluation.h"
#include "io/AtomicFile.h"
#include "tasks/Feedback.h"

#include <QJsonArray>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace lipsync::cli {
QString dynamicModelOptionsFrom(const Arguments &args, ModelOptions &options); // TrainCommand.cpp
}

namespace {

const char *kEvaluateUsage =
    "usage: lipsync evaluate (--project DIR | --features DIR --labels DIR) [--folds 10] [--seed 2007]\n"
    "                        [--kinds dpds,slds,brand,hmm] [--fps RATE] [--csv FILE] [--json]\n"
    "  model options as for train (--full-covariance, --full-a, --optimizer, --paper-mode, ...)";

int runEvaluate(const QStringList &argv)
{
    const Arguments args(argv);
    const QStringList unknown = args.unknown({"project", "features", "labels", "folds", "seed", "kinds", "fps",
                                              "csv", "json", "full-covariance", "full-a", "bound-a", "optimizer",
                                              "paper-mode", "max-iterations", "threads"});
    if (!unknown.isEmpty() || !args.positional().isEmpty())
        return fail(QStringLiteral("unknown argument %1\n").arg((unknown + args.positional()).first())
                        + QString::fromLatin1(kEvaluateUsage),
                    2);
    EvaluationOptions options;
    bool ok = false;
    options.folds = args.value(QStringLiteral("folds"), QStringLiteral("10")).toInt(&ok);
    if (!ok || options.folds < 2)
        return fail(QStringLiteral("--folds must be an integer >= 2"), 2);
    options.seed = args.value(QStringLiteral("seed"), QStringLiteral("2007")).toULongLong(&ok);
    if (!ok)
        return fail(QStringLiteral("--seed must be a non-negative integer"), 2);
    if (args.has(QStringLiteral("kinds"))) {
        options.kinds.clear();
        for (const QString &k : args.value(QStringLiteral("kinds")).split(QLatin1Char(','), Qt::SkipEmptyParts)) {
            if (!QStringList{"dpds", "slds", "brand", "hmm"}.contains(k.trimmed()))
                return fail(QStringLiteral("--kinds: unknown model '%1' (dpds, slds, brand, hmm)").arg(k), 2);
            options.kinds.push_back(k.trimmed().toStdString());
        }
        if (options.kinds.empty())
            return fail(QStringLiteral("--kinds is empty"), 2);
    }
    if (const QString error = dynamicModelOptionsFrom(args, options.modelOptions); !error.isEmpty())
        return fail(error, 2);

    std::vector<LabelledSequence> sequences;
    if (const QString error = loadTrainingData(args, sequences); !error.isEmpty())
        return fail(error + QLatin1Char('\n') + QString::fromLatin1(kEvaluateUsage), 2);
    Feedback feedback;
    const EvaluationResult result = evaluateModels(sequences, options, feedback);
    if (args.has(QStringLiteral("csv")))
        writeFileAtomically(args.value(QStringLiteral("csv")).toStdString(), result.toCsv());
    if (args.flag(QStringLiteral("json"))) {
        printJson(result.toJson());
        return 0;
    }
    std::printf("%d-fold cross-validation, %d sequences, %lld frames\n", result.folds, result.sequences,
                result.frames);
    std::printf("%-6s %22s %22s %22s %22s %10s\n", "model", "L1", "RMS", "Linf", "loglik/frame", "train s");
    for (const ModelEvaluation &m : result.models) {
        double seconds = 0;
        for (double s : m.trainingSeconds)
            seconds += s;
        std::printf("%-6s", m.kind.c_str());
        for (const std::string &metric : evaluationMetrics())
            std::printf(" %12.5g ± %-7.3g", m.metrics.at(metric).mean, m.metrics.at(metric).ci95);
        std::printf(" %10.3f\n", seconds);
    }
    std::printf("%s\n", logLikelihoodNote());
    return 0;
}

const CommandRegistration registration{
    QStringLiteral("evaluate"), QStringLiteral("cross-validate the dynamic models (L1, RMS, Linf, log-likelihood)"),
    &runEvaluate};

} // namespace
