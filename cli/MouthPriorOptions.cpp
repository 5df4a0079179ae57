#include "MouthPriorOptions.h"

#include "animation/MouthShapePrior.h"
#include "util/Error.h"
#include "util/ResourceLocator.h"

namespace lipsync::cli {

std::vector<CommandOption> mouthPriorOptions(const QString &prefix)
{
    return {{QStringLiteral("prior"), {},
             prefix + QStringLiteral("the phone means of HMM-mean or Brand start from mouths learnt on other speakers (GRID s1), "
                                     "combined with the person's own frames: for a person with little footage")},
            {QStringLiteral("prior-file"), QStringLiteral("FILE"),
             prefix + QStringLiteral("--prior from this mouth prior (lipsync export prior)")},
            {QStringLiteral("prior-weight"), QStringLiteral("FRAMES|cv"),
             prefix + QStringLiteral("how many of the person's frames of a phone weigh as much as the prior; cv: "
                                     "the weight (0, 5, 20, 80 or 320) that best predicts the person's own frames of "
                                     "clips left out (default: cv)")}};
}

std::shared_ptr<const MouthShapePrior> mouthPriorFrom(const CommandLine &args, double *weight)
{
    *weight = MouthShapePrior::kCrossValidated;
    if (!args.isSet(QStringLiteral("prior")) && !args.isSet(QStringLiteral("prior-file"))) {
        if (args.isSet(QStringLiteral("prior-weight")))
            throw UsageError(QStringLiteral("--prior-weight goes with --prior or --prior-file"));
        return nullptr;
    }
    if (args.value(QStringLiteral("prior-weight")) == QLatin1String("cv")) {
        *weight = MouthShapePrior::kCrossValidated;
    } else if (args.isSet(QStringLiteral("prior-weight"))) {
        *weight = args.number(QStringLiteral("prior-weight"));
        if (!(*weight >= 0))
            throw UsageError(QStringLiteral("--prior-weight must be a number of frames >= 0, or cv"));
    }
    std::string path = args.value(QStringLiteral("prior-file")).toStdString();
    if (path.empty()) {
        path = ResourceLocator::find("prior/grid-s1.mouthprior");
        if (path.empty())
            throw Error("the shipped mouth prior (prior/grid-s1.mouthprior) was not found");
    }
    return std::make_shared<const MouthShapePrior>(MouthShapePrior::load(path));
}

} // namespace lipsync::cli
