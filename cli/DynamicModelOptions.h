#pragma once
// What the commands on dynamic models share: the models' options (docs/models.md §2-4) of
// `lipsync train` and `lipsync evaluate`, and the AAM a model is for (train, generate).
#include "Command.h"

#include "dynamics/ModelFile.h"

namespace lipsync::cli {

class CommandLine;

std::vector<CommandOption> dynamicModelOptions();
// Throws UsageError for a bad value.
ModelOptions dynamicModelOptionsFrom(const CommandLine &args);

// --aam AAM|ID: the AAM a model's features are parameters of, as its file or its identifier.
CommandOption modelAamOption(const QString &description);
// The identifier of --aam's AAM: the file's (lipsync::Error naming a broken file), else the text.
std::string modelAamIdentifier(const CommandLine &args);

} // namespace lipsync::cli
