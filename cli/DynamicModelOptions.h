#pragma once
// The options of the dynamic models (docs/models.md §2-4) that `lipsync train` and
// `lipsync evaluate` share, and the ModelOptions they give.
#include "Command.h"

#include "dynamics/ModelFile.h"

namespace lipsync::cli {

class CommandLine;

std::vector<CommandOption> dynamicModelOptions();
// Throws UsageError for a bad value.
ModelOptions dynamicModelOptionsFrom(const CommandLine &args);

} // namespace lipsync::cli
