#pragma once
// --prior, --prior-file and --prior-weight, as `train` and `evaluate --realism` take them: HMM-mean's
// phone means started from mouths learnt on other speakers (animation/MouthShapePrior).
#include "CommandLine.h"

#include <memory>
#include <vector>

namespace lipsync {
class MouthShapePrior;
}

namespace lipsync::cli {

// The three options; `prefix` starts their help ("--realism: ", or empty).
std::vector<CommandOption> mouthPriorOptions(const QString &prefix = {});
// The prior the options ask for (the shipped GRID s1 prior for --prior, else --prior-file's), null
// for neither; `weight` receives --prior-weight (cv, the default: MouthShapePrior::kCrossValidated).
// Errors name the file; a negative weight is bad usage.
std::shared_ptr<const MouthShapePrior> mouthPriorFrom(const CommandLine &args, double *weight);

} // namespace lipsync::cli
