// lipsync train: fits one dynamic model (docs/models.md §1-4) to features + phone labels.
#include "Command.h"
#include "TrainingData.h"

#include "aam/AamModel.h"
#include "dynamics/ModelFile.h"
#include "tasks/Feedback.h"

#include <QJsonArray>

#include <chrono>
#include <cmath>
#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// %1: the model kinds' ids.
const char *kTrainUsage =
    "usage: lipsync train --kind %1 (--project DIR | --features DIR --labels DIR)\n"
    "                     --out MODEL [--fps RATE] [--aam ID] [--json]\n"
    "  --fps: the video frame rate of feature files that record none (\"# fps=RATE\")\n"
    "  --aam: the identifier of the AAM the features come from (default: the project's AAM)\n"
    "  options: --full-covariance (brand), --full-a (slds), --optimizer lm|gradient (dpds),\n"
    "           --paper-mode (dpds), --max-iterations N (dpds, slds), --threads N (dpds),\n"
    "           --bound-a [AMAX] (slds: keep |a|, or ||A||_2 with --full-a, <= AMAX, default 0.999,\n"
    "           for generation that stays bounded; without it, the paper's plain maximum likelihood),\n"
    "           --compensate-variance (every kind: scale the generated trajectories' spread to the\n"
    "           training features', docs/models.md §5.1)";

QString trainUsage()
{
    return QString::fromLatin1(kTrainUsage).arg(QString::fromStdString(modelKindIdList("|", "|")));
}

// Shared by train and evaluate: model options from the command line. Returns an error or "".
QString modelOptionsFrom(const Arguments &args, ModelOptions &options)
{
    options.brand.fullCovariance = args.flag(QStringLiteral("full-covariance"));
    options.compensateVariance = args.flag(QStringLiteral("compensate-variance"));
    options.slds.fullA = args.flag(QStringLiteral("full-a"));
    if (args.has(QStringLiteral("bound-a"))) {
        options.slds.boundA = true;
        const QString value = args.value(QStringLiteral("bound-a"));
        if (!value.isEmpty()) {
            bool ok = false;
            options.slds.aMax = value.toDouble(&ok);
            if (!ok || !(options.slds.aMax > 0) || !std::isfinite(options.slds.aMax))
                return QStringLiteral("--bound-a must be a positive number");
        }
    }
    options.dpds.paperMode = args.flag(QStringLiteral("paper-mode"));
    const QString optimizer = args.value(QStringLiteral("optimizer"), QStringLiteral("lm"));
    if (optimizer == QLatin1String("gradient"))
        options.dpds.optimizer = DpdsOptions::Optimizer::GradientAscent;
    else if (optimizer != QLatin1String("lm"))
        return QStringLiteral("--optimizer must be lm or gradient");
    if (args.has(QStringLiteral("max-iterations"))) {
        bool ok = false;
        const int n = args.value(QStringLiteral("max-iterations")).toInt(&ok);
        if (!ok || n < 1)
            return QStringLiteral("--max-iterations must be a positive integer");
        options.dpds.maxIterations = n;
        options.slds.maxIterations = n;
    }
    if (args.has(QStringLiteral("threads"))) {
        bool ok = false;
        const int n = args.value(QStringLiteral("threads")).toInt(&ok);
        if (!ok || n < 0)
            return QStringLiteral("--threads must be a non-negative integer");
        options.dpds.threads = n;
    }
    return {};
}

int runTrain(const QStringList &argv)
{
    const Arguments args(argv);
    const QStringList unknown = args.unknown({"kind", "project", "features", "labels", "out", "fps", "aam",
                                              "json", "full-covariance", "full-a", "bound-a", "optimizer",
                                              "paper-mode", "max-iterations", "threads", "compensate-variance"});
    if (!unknown.isEmpty() || !args.positional().isEmpty())
        return fail(QStringLiteral("unknown argument %1\n").arg((unknown + args.positional()).first())
                        + trainUsage(),
                    2);
    const QString kind = args.value(QStringLiteral("kind"));
    const QString out = args.value(QStringLiteral("out"));
    if (kind.isEmpty() || out.isEmpty())
        return fail(trainUsage(), 2);
    ModelOptions options;
    if (const QString error = modelOptionsFrom(args, options); !error.isEmpty())
        return fail(error, 2);
    if (!isDynamicModelKind(kind.toStdString()))
        return fail(QStringLiteral("--kind must be %1").arg(QString::fromStdString(modelKindIdList())), 2);

    std::vector<LabelledSequence> sequences;
    std::string projectAam;
    if (const QString error = loadTrainingData(args, sequences, &projectAam); !error.isEmpty())
        return fail(error + QLatin1Char('\n') + trainUsage(), 2);
    // The model records the AAM whose parameters it generates: --aam, else the content identifier of
    // the project's AAM (what `lipsync render` and the studio check a model against). Read before
    // training, so a broken AAM file costs no training time.
    std::string aam = args.value(QStringLiteral("aam"), QStringLiteral("unspecified")).toStdString();
    if (!args.has(QStringLiteral("aam")) && !projectAam.empty())
        aam = AamModel::load(projectAam).identifier;
    auto model = createDynamicModel(kind.toStdString(), options);
    Feedback feedback;
    int iterations = 0;
    double objective = 0.0;
    feedback.onIteration = [&](int i, double value) {
        iterations = i;
        objective = value;
    };
    const auto start = std::chrono::steady_clock::now();
    model->train(sequences, feedback);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    saveModel(*model, out.toStdString(), aam);

    // log p(y | labels), comparable between the kinds (Brand: its trajectory density, §2.2).
    long long frames = 0;
    double ll = 0.0;
    for (const LabelledSequence &s : sequences) {
        frames += s.frameCount();
        ll += model->trajectoryLogLikelihood(s.labels, s.features);
    }
    if (args.flag(QStringLiteral("json"))) {
        QJsonObject o;
        o[QStringLiteral("kind")] = kind;
        o[QStringLiteral("model")] = out;
        o[QStringLiteral("aam")] = QString::fromStdString(aam);
        o[QStringLiteral("sequences")] = int(sequences.size());
        o[QStringLiteral("frames")] = double(frames);
        o[QStringLiteral("dimension")] = model->dimension();
        o[QStringLiteral("trainingSeconds")] = seconds;
        o[QStringLiteral("iterations")] = iterations;
        o[QStringLiteral("objective")] = objective;
        o[QStringLiteral("loglikPerFrame")] = ll / double(frames);
        printJson(o);
    } else {
        std::printf("trained %s on %zu sequences (%lld frames, d = %d) in %.3f s; "
                    "log-likelihood %.6f nats/frame; saved %s\n",
                    kind.toUtf8().constData(), sequences.size(), frames, model->dimension(), seconds,
                    ll / double(frames), out.toUtf8().constData());
    }
    return 0;
}

const CommandRegistration registration{
    QStringLiteral("train"),
    QStringLiteral("train a dynamic model (%1) on features + phone labels")
        .arg(QString::fromStdString(modelKindIdList(", "))),
    &runTrain};

} // namespace

namespace lipsync::cli {
// Used by EvaluateCommand.cpp.
QString dynamicModelOptionsFrom(const Arguments &args, ModelOptions &options)
{
    return modelOptionsFrom(args, options);
}
} // namespace lipsync::cli
