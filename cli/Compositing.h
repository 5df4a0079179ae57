#pragma once
// How `lipsync render`, `lipsync live` and `lipsync evaluate --realism` draw the synthesised face
// into the frames, from their shared options: --full-face, --no-colour-match and --no-detail
// (AamSynthesizer's CompositeOptions), and --no-lip-closure (render/BilabialClosure).
#include "Command.h"

#include "aam/AamSynthesizer.h"

#include <vector>

namespace lipsync::cli {

class CommandLine;

struct Compositing
{
    static std::vector<CommandOption> options();
    static CompositeOptions from(const CommandLine &args);
    // Whether the generated lips are closed on /p b m/ (not --no-lip-closure).
    static bool closesLips(const CommandLine &args);
};

} // namespace lipsync::cli
