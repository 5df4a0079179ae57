// lipsync evaluate: k-fold cross-validation of the dynamic models (docs/models.md §6).
#include "Command.h"
#include "TrainingData.h"

#include "eval/Evaluation.h"
#include "eval/RealismReport.h"
#include "io/AtomicFile.h"
#include "project/Project.h"
#include "tasks/Feedback.h"

#include <QJsonArray>

#include <cmath>
#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace lipsync::cli {
QString dynamicModelOptionsFrom(const Arguments &args, ModelOptions &options); // TrainCommand.cpp
}

namespace {

// %1: the model kinds' ids.
const char *kEvaluateUsage =
    "usage: lipsync evaluate (--project DIR | --features DIR --labels DIR) [--folds 10] [--seed 2007]\n"
    "                        [--kinds %1] [--fps RATE] [--csv FILE] [--json]\n"
    "       lipsync evaluate --realism --project DIR [--folds 10] [--seed 2007] [--kinds ...]\n"
    "                        [--max-lag 5] [--dlib FILE] [--json]\n"
    "  model options as for train (--full-covariance, --full-a, --optimizer, --paper-mode, ...)";

const char *kRealismHelp =
    "  --realism: on the same held-out folds, render every model's generation (and the tracked\n"
    "    parameters' re-synthesis, \"tracked\") into the recording's frames and compare the lips\n"
    "    measured by dlib's 68-point predictor with the recording's: opening correlation,\n"
    "    articulation (s.d. ratio), /p b m/ closures (ratio), audio-visual lag (frames, generated\n"
    "    minus recorded, searched within --max-lag), mouth sharpness (ratio) and the colour step\n"
    "    across the seam (CIE Lab dE; the recording's at the same pixels beside it). Needs the\n"
    "    project's media and AAM and Debian's libdlib-data (or --dlib FILE). docs/models.md 6.5\n";

QString evaluateUsage()
{
    return QString::fromLatin1(kEvaluateUsage).arg(QString::fromStdString(modelKindIdList(",", ",")));
}

void printRealism(const RealismResult &result)
{
    std::printf("realism, %d-fold cross-validation, %d sequences, %lld frames (%lld without a face, skipped); "
                "%d of %d /p b m/ segments closed in the recordings\n",
                result.folds, result.sequences, result.frames, result.skippedFrames, result.closedRecorded,
                result.bilabials);
    std::printf("%-8s", "method");
    for (const std::string &metric : realismMetrics())
        std::printf(" %19s", metric.c_str());
    std::printf("\n");
    for (const RealismMethod &m : result.methods) {
        std::printf("%-8s", m.kind.c_str());
        for (const std::string &metric : realismMetrics()) {
            const MetricSummary &s = m.metrics.at(metric);
            if (std::isfinite(s.ci95))
                std::printf(" %9.3g ± %-7.2g", s.mean, s.ci95);
            else
                std::printf(" %9.3g %-9s", s.mean, "");
        }
        std::printf("\n");
    }
    std::printf("correlation: Pearson of the lip opening with the recording's; articulation, closure, "
                "sharpness: generated / recorded; lag: frames, generated minus recorded; seamDeltaE: "
                "CIE Lab dE across the synthesised region's edge (seamDeltaERecorded: the recording at the "
                "same pixels)\n");
}

int runRealism(const Arguments &args, const EvaluationOptions &evaluation)
{
    if (args.has(QStringLiteral("csv")) || args.has(QStringLiteral("fps")))
        return fail(QStringLiteral("--csv and --fps do not apply to --realism"), 2);
    if (!args.has(QStringLiteral("project")) || args.has(QStringLiteral("features")) || args.has(QStringLiteral("labels")))
        return fail(QStringLiteral("--realism needs --project DIR (the media and the AAM)"), 2);
    RealismOptions options;
    options.crossValidation = evaluation;
    bool ok = true;
    options.maxLag = args.value(QStringLiteral("max-lag"), QStringLiteral("5")).toInt(&ok);
    if (!ok || options.maxLag < 0)
        return fail(QStringLiteral("--max-lag must be a non-negative integer"), 2);
    options.dlibPredictor = args.value(QStringLiteral("dlib")).toStdString();
    const Project project = Project::load(args.value(QStringLiteral("project")).toStdString());
    Feedback feedback;
    const RealismResult result = evaluateRealism(project, options, feedback);
    if (args.flag(QStringLiteral("json")))
        printJson(result.toJson());
    else
        printRealism(result);
    return 0;
}

int runEvaluate(const QStringList &argv)
{
    const Arguments args(argv, Arguments::defaultBooleanFlags() << QStringLiteral("realism"));
    if (args.flag(QStringLiteral("help"))) {
        std::printf("%s\n%s", evaluateUsage().toUtf8().constData(), kRealismHelp);
        return 0;
    }
    const bool realism = args.flag(QStringLiteral("realism"));
    QStringList known{"project", "features", "labels", "folds", "seed", "kinds", "fps",
                      "csv", "json", "full-covariance", "full-a", "bound-a", "optimizer",
                      "paper-mode", "max-iterations", "threads", "compensate-variance"};
    if (realism)
        known << "realism" << "max-lag" << "dlib";
    const QStringList unknown = args.unknown(known);
    if (!unknown.isEmpty() || !args.positional().isEmpty())
        return fail(QStringLiteral("unknown argument %1\n").arg((unknown + args.positional()).first())
                        + evaluateUsage(),
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
            if (!isDynamicModelKind(k.trimmed().toStdString()))
                return fail(QStringLiteral("--kinds: unknown model '%1' (%2)")
                                .arg(k, QString::fromStdString(modelKindIdList(", "))),
                            2);
            options.kinds.push_back(k.trimmed().toStdString());
        }
        if (options.kinds.empty())
            return fail(QStringLiteral("--kinds is empty"), 2);
    }
    if (const QString error = dynamicModelOptionsFrom(args, options.modelOptions); !error.isEmpty())
        return fail(error, 2);
    if (realism)
        return runRealism(args, options);

    std::vector<LabelledSequence> sequences;
    if (const QString error = loadTrainingData(args, sequences); !error.isEmpty())
        return fail(error + QLatin1Char('\n') + evaluateUsage(), 2);
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
    QStringLiteral("evaluate"),
    QStringLiteral("cross-validate the dynamic models (L1, RMS, Linf, log-likelihood; --realism: rendered lips)"),
    &runEvaluate};

} // namespace
