#pragma once
// Where `lipsync render` and `lipsync export video` write, from their shared options: --out OUT.mp4
// or --png-dir DIR, --captions LEFT[,RIGHT] and --crf.
#include "Command.h"

#include <string>
#include <vector>

namespace lipsync::cli {

class CommandLine;

struct VideoOutput
{
    QString out;                       // the MP4, or empty
    QString pngDir;                    // the PNG folder, or empty
    std::vector<std::string> captions; // one per panel, or none
    int crf = 20;

    static std::vector<CommandOption> options();
    // Throws UsageError unless exactly one of --out and --png-dir is given, for a bad --crf, and
    // unless there are no captions or one for each of `panels`.
    static VideoOutput from(const CommandLine &args, int panels);

    QString path() const { return out.isEmpty() ? pngDir : out; }
};

} // namespace lipsync::cli
