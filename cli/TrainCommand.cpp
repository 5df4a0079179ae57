// lipsync train: fits one dynamic model (docs/models.md §1-4) to features + phone labels.
#include "CommandLine.h"
#include "DynamicModelOptions.h"
#include "MouthPriorOptions.h"
#include "TrainingData.h"

#include "aam/AamModel.h"
#include "align/ProjectAligner.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "dynamics/BrandModel.h"
#include "dynamics/ContextDependentModel.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneCoverage.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QJsonArray>

#include <chrono>
#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// --prior: the phone means of HMM-mean or Brand start from mouth shapes learnt on other speakers
// (the shipped GRID s1 prior, or --prior-file), MAP-combined with the project's own frames of the
// sequences trained on (animation/MouthShapePrior, docs/models.md §5.4); `used` receives the weight
// taken (--prior-weight cv: the one chosen).
Eigen::MatrixXd priorShift(const CommandLine &args, const std::vector<LabelledSequence> &sequences,
                           const MouthShapePrior &prior, double kappa, double *used)
{
    const Project project = Project::load(args.value(QStringLiteral("project")).toStdString());
    const AamModel aam = AamModel::load(project.aamPath());
    return projectPriorShift(prior, MouthMeasurer(aam), project, sequences, kappa, used);
}

int runTrain(const CommandLine &args)
{
    const QString kind = args.value(QStringLiteral("kind"));
    const QString out = args.value(QStringLiteral("out"));
    ModelOptions options = dynamicModelOptionsFrom(args);
    if (!isDynamicModelKind(kind.toStdString()))
        throw UsageError(QStringLiteral("--kind must be %1").arg(QString::fromStdString(modelKindIdList())));
    double priorWeight = 0;
    const std::shared_ptr<const MouthShapePrior> prior = mouthPriorFrom(args, &priorWeight);
    if (prior && (!modelKindTakesPrior(*parseModelKind(kind.toStdString())) || !args.isSet(QStringLiteral("project"))))
        throw UsageError(QStringLiteral("--prior starts the phone means of HMM-mean or Brand from a project's mouths: "
                                        "--kind hmm or brand, --project DIR"));
    std::string projectAam;
    const std::vector<LabelledSequence> sequences = loadTrainingData(args, &projectAam);
    // The model records the AAM whose parameters it generates: --aam, else the content identifier of
    // the project's AAM (what `lipsync render` and the studio check a model against). Read before
    // training, so a broken AAM file costs no training time.
    std::string aam = kUnspecifiedAam;
    if (args.isSet(QStringLiteral("aam")))
        aam = modelAamIdentifier(args);
    else if (!projectAam.empty())
        aam = AamModel::load(projectAam).identifier;
    if (prior) {
        options.meanShift = priorShift(args, sequences, *prior, priorWeight, &priorWeight);
        options.priorWeight = priorWeight;
        if (priorWeight == 0)
            std::fprintf(stderr, "lipsync train: other speakers' mouths weigh 0 frames: this person's own clips "
                                 "predict their lips better (--prior-weight FRAMES gives them a weight)\n");
    }
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
    // New speech for this speaker is aligned as the phones it learnt from were (render, export).
    if (args.isSet(QStringLiteral("project")))
        model->setTrainingAligner(
            projectAlignerChoice(Project::load(args.value(QStringLiteral("project")).toStdString())));
    saveModel(*model, out.toStdString(), aam);

    // log p(y | labels), comparable between the kinds (Brand: its trajectory density, §2.2).
    long long frames = 0;
    double ll = 0.0;
    for (const LabelledSequence &s : sequences) {
        frames += s.frameCount();
        ll += model->trajectoryLogLikelihood(s.labels, s.features);
    }
    // The phones, or the tied context states (docs/models.md §5.2).
    const auto *context = dynamic_cast<const ContextDependentModel *>(model.get());
    const int states = context ? context->tree().stateCount() : model->stateCount();
    // What the footage covers, and what it lacks for these options (docs/models.md §0).
    PhoneCoverage coverage = PhoneCoverage::of(sequences, *model);
    coverage.priorTried = prior != nullptr;
    if (const std::string advice = coverage.advice(); !advice.empty())
        std::fprintf(stderr, "lipsync train: warning: %s\n", advice.c_str());
    // Brand: its covariance, and the held-out errors that chose it (docs/models.md §2.1).
    const auto *brand = dynamic_cast<const BrandModel *>(context ? &context->inner() : model.get());
    if (args.isSet(QStringLiteral("json"))) {
        QJsonObject o;
        o[QStringLiteral("kind")] = kind;
        o[QStringLiteral("states")] = states;
        o[QStringLiteral("model")] = out;
        o[QStringLiteral("aam")] = QString::fromStdString(aam);
        o[QStringLiteral("sequences")] = int(sequences.size());
        o[QStringLiteral("frames")] = double(frames);
        o[QStringLiteral("dimension")] = model->dimension();
        o[QStringLiteral("trainingSeconds")] = seconds;
        o[QStringLiteral("iterations")] = iterations;
        o[QStringLiteral("objective")] = objective;
        o[QStringLiteral("loglikPerFrame")] = ll / double(frames);
        o[QStringLiteral("coverage")] = coverage.toJson();
        if (prior)
            o[QStringLiteral("priorWeight")] = priorWeight;
        if (brand) {
            const QJsonObject covariance = brand->covarianceJson();
            for (auto it = covariance.begin(); it != covariance.end(); ++it)
                o[it.key()] = it.value();
        }
        printJson(o);
    } else {
        std::printf("trained %s on %zu sequences (%lld frames, d = %d, %d states) in %.3f s; "
                    "log-likelihood %.6f nats/frame; saved %s\n",
                    kind.toUtf8().constData(), sequences.size(), frames, model->dimension(), states, seconds,
                    ll / double(frames), out.toUtf8().constData());
        std::printf("phones: %d of %d seen in %.0f s of speech, %zu with fewer than %d frames%s\n",
                    PhoneCoverage::kSpeechPhones - int(coverage.unseen.size()), PhoneCoverage::kSpeechPhones,
                    coverage.speechSeconds, coverage.rare.size(), kMinimumVarianceFrames,
                    coverage.prior ? qPrintable(QStringLiteral("; started from other speakers' mouths (weight %1 frames)")
                                                    .arg(priorWeight))
                                   : "");
        if (brand && brand->covarianceChoice().folds > 0)
            std::printf("covariance: %s (held-out L1 in %d folds: diagonal %.4g, full %.4g)\n",
                        brand->fullCovariance() ? "full" : "diagonal", brand->covarianceChoice().folds,
                        brand->covarianceChoice().diagonalL1, brand->covarianceChoice().fullL1);
    }
    return 0;
}

const CommandRegistration registration{
    CommandSpec{QStringLiteral("train"),
                QStringLiteral("train a dynamic model (%1) on features + phone labels")
                    .arg(QString::fromStdString(modelKindIdList(", "))),
                QStringLiteral("Fits one dynamic model (docs/models.md) to face features and their phone labels: a "
                               "project's sequences (--project) or a features folder and a labels folder, and "
                               "reports its log-likelihood per frame."),
                {{QStringLiteral("kind"), QString::fromStdString(modelKindIdList("|", "|")),
                  QStringLiteral("the kind of model"), {}, CommandOption::Required},
                 {QStringLiteral("out"), QStringLiteral("MODEL"), QStringLiteral("the model file to write"), {},
                  CommandOption::Required},
                 modelAamOption(QStringLiteral("the AAM the features come from (its file or its identifier), "
                                               "recorded in the model (default: the project's AAM with --project, "
                                               "else unspecified)"))},
                {}}
        .add(trainingDataOptions())
        .add(dynamicModelOptions())
        .add(mouthPriorOptions()),
    &runTrain};

} // namespace
