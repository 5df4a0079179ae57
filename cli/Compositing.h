#pragma once
// How `lipsync render` and `lipsync evaluate --realism` draw the synthesised face into the frames,
// from their shared options: --full-face, --no-colour-match and --no-detail (AamSynthesizer's
// CompositeOptions).
#include "Command.h"

#include "aam/AamSynthesizer.h"

#include <vector>

namespace lipsync::cli {

class CommandLine;

struct Compositing
{
    static std::vector<CommandOption> options();
    static CompositeOptions from(const CommandLine &args);
};

} // namespace lipsync::cli
