#pragma once
// How `lipsync render`, `lipsync live` and `lipsync evaluate --realism` draw the synthesised face
// into the frames, from their shared options: --full-face, --no-colour-match and --no-detail
// (AamSynthesizer's CompositeOptions), --no-lip-closure (render/BilabialClosure) and
// --model-posture (render/PostureTransfer).
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
    // Whether generated faces keep the posture of the frames drawn into (not --model-posture).
    static bool keepsPosture(const CommandLine &args);

};

} // namespace lipsync::cli
