#pragma once
// Training data for `lipsync train` and `lipsync evaluate`: either a project (--project DIR: every
// sequence with both features and a phone tier) or a features folder + labels folder.
#include "Command.h"

#include "dynamics/LabelledSequence.h"

#include <vector>

namespace lipsync::cli {

// Returns "" and fills `sequences`, or returns a usage error (exit 2). Bad files throw
// lipsync::Error naming the file. With --project, `projectAam` (if given) receives the path of the
// project's AAM, empty if it has none.
QString loadTrainingData(const Arguments &args, std::vector<LabelledSequence> &sequences,
                         std::string *projectAam = nullptr);

} // namespace lipsync::cli
