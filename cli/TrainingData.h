#pragma once
// Training data for `lipsync train` and `lipsync evaluate`: either a project (--project DIR: every
// sequence with both features and a phone tier) or a features folder + labels folder.
#include "Command.h"

#include "dynamics/LabelledSequence.h"

#include <vector>

namespace lipsync::cli {

class CommandLine;

// --project DIR, --features DIR, --labels DIR and --fps RATE.
std::vector<CommandOption> trainingDataOptions();

// The sequences the options name. Throws UsageError for options that do not go together, and
// lipsync::Error naming the file for bad files. With --project, `projectAam` (if given) receives
// the path of the project's AAM, empty if it has none.
std::vector<LabelledSequence> loadTrainingData(const CommandLine &args, std::string *projectAam = nullptr);

} // namespace lipsync::cli
