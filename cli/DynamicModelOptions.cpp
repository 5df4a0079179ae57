#include "DynamicModelOptions.h"

#include "CommandLine.h"

#include "aam/AamModel.h"

#include <QFileInfo>

namespace lipsync::cli {

std::vector<CommandOption> dynamicModelOptions()
{
    return {
        {QStringLiteral("covariance"), QStringLiteral("diagonal|full|cv"),
         QStringLiteral("brand: the output covariances: diagonal (the paper's), full, or whichever of the two "
                        "generates held-out training sequences with the smaller L1 in a 5-fold split of the "
                        "training part (docs/models.md 2.1)"),
         QStringLiteral("diagonal")},
        {QStringLiteral("full-a"), {}, QStringLiteral("slds: full dynamics matrices A (default: diagonal)")},
        {QStringLiteral("bound-a"), {},
         QStringLiteral("slds: keep |a|, or ||A||_2 with --full-a, <= --bound-a-max, for generation that stays "
                        "bounded (default: the paper's plain maximum likelihood)")},
        {QStringLiteral("bound-a-max"), QStringLiteral("AMAX"), QStringLiteral("slds: the bound of --bound-a (implies it)"),
         QString::number(SldsOptions{}.aMax)},
        {QStringLiteral("optimizer"), QStringLiteral("lm|gradient"),
         QStringLiteral("dpds: Levenberg-Marquardt or gradient ascent"), QStringLiteral("lm")},
        {QStringLiteral("paper-mode"), {}, QStringLiteral("dpds: the paper's procedure (unit weights in the mu/nu solve, only r re-estimated in the "
                                       "loop, sigma^2 once at the end)")},
        {QStringLiteral("max-iterations"), QStringLiteral("N"), QStringLiteral("dpds, slds: at most N iterations")},
        {QStringLiteral("threads"), QStringLiteral("N"), QStringLiteral("dpds: threads (0: all cores, 1: serial)")},
        {QStringLiteral("compensate-variance"), {},
         QStringLiteral("every kind: scale the generated trajectories to the training features' spread "
                        "(docs/models.md 5.1; default: the paper's models)")},
        {QStringLiteral("context-states"), {},
         QStringLiteral("every kind: states for phones in context (neighbours, third of the segment), tied by "
                        "decision trees (docs/models.md 5.2; default: one state per phone, as in the paper)")},
        {QStringLiteral("paper"), {},
         QStringLiteral("every kind: the paper's models exactly (docs/models.md 8, the paper preset): no "
                        "compensation or context, diagonal Brand, the DPDS by Algorithm 1 and gradient ascent "
                        "without the variance prior; with --realism also no lip closure, colour match or detail")},
        {QStringLiteral("min-occupancy"), QStringLiteral("FRAMES"),
         QStringLiteral("context states: fewest training frames per state"),
         QString::number(ContextTreeOptions{}.minOccupancy)},
        {QStringLiteral("mdl-weight"), QStringLiteral("W"),
         QStringLiteral("context states: scale of the MDL splitting threshold d log N (smaller: more states)"),
         QString::number(ContextTreeOptions{}.mdlWeight)},
    };
}

namespace {

// --max-iterations and --threads: how long and on how many cores, not which model.
void readLimits(const CommandLine &args, ModelOptions &options)
{
    if (args.isSet(QStringLiteral("max-iterations"))) {
        const int n = args.integer(QStringLiteral("max-iterations"), 1);
        options.dpds.maxIterations = n;
        options.slds.maxIterations = n;
    }
    if (args.isSet(QStringLiteral("threads")))
        options.dpds.threads = args.integer(QStringLiteral("threads"), 0);
}

} // namespace

ModelOptions dynamicModelOptionsFrom(const CommandLine &args)
{
    if (args.isSet(QStringLiteral("paper"))) {
        // The preset is whole: an option that would change one of its models is refused.
        for (const char *other : {"covariance", "full-a", "bound-a", "bound-a-max", "optimizer", "paper-mode",
                                  "compensate-variance", "context-states", "min-occupancy", "mdl-weight"})
            if (args.isSet(QString::fromLatin1(other)))
                throw UsageError(QStringLiteral("--paper cannot be combined with --%1").arg(QString::fromLatin1(other)));
        ModelOptions options = ModelOptions::paper();
        readLimits(args, options);
        return options;
    }
    ModelOptions options;
    const QString covariance = args.value(QStringLiteral("covariance"));
    if (covariance == QLatin1String("full"))
        options.brand.covariance = BrandCovariance::Full;
    else if (covariance == QLatin1String("cv"))
        options.brand.covariance = BrandCovariance::CrossValidated;
    else if (covariance != QLatin1String("diagonal"))
        throw UsageError(QStringLiteral("--covariance must be diagonal, full or cv"));
    options.compensateVariance = args.isSet(QStringLiteral("compensate-variance"));
    options.contextStates = args.isSet(QStringLiteral("context-states")) || args.isSet(QStringLiteral("min-occupancy"))
                            || args.isSet(QStringLiteral("mdl-weight"));
    if (args.isSet(QStringLiteral("min-occupancy")))
        options.context.minOccupancy = args.integer(QStringLiteral("min-occupancy"), 1);
    if (args.isSet(QStringLiteral("mdl-weight")))
        options.context.mdlWeight = args.positiveNumber(QStringLiteral("mdl-weight"));
    options.slds.fullA = args.isSet(QStringLiteral("full-a"));
    options.slds.boundA = args.isSet(QStringLiteral("bound-a")) || args.isSet(QStringLiteral("bound-a-max"));
    options.slds.aMax = args.positiveNumber(QStringLiteral("bound-a-max"));
    options.dpds.paperMode = args.isSet(QStringLiteral("paper-mode"));
    const QString optimizer = args.value(QStringLiteral("optimizer"));
    if (optimizer == QLatin1String("gradient"))
        options.dpds.optimizer = DpdsOptions::Optimizer::GradientAscent;
    else if (optimizer != QLatin1String("lm"))
        throw UsageError(QStringLiteral("--optimizer must be lm or gradient"));
    readLimits(args, options);
    return options;
}

CommandOption modelAamOption(const QString &description)
{
    return {QStringLiteral("aam"), QStringLiteral("AAM|ID"), description};
}

std::string modelAamIdentifier(const CommandLine &args)
{
    const QString aam = args.value(QStringLiteral("aam"));
    if (QFileInfo(aam).isFile())
        return AamModel::load(aam.toStdString()).identifier;
    return aam.toStdString();
}

} // namespace lipsync::cli
