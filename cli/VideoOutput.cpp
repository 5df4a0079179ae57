#include "VideoOutput.h"

#include "CommandLine.h"

namespace lipsync::cli {

std::vector<CommandOption> VideoOutput::options()
{
    return {{QStringLiteral("out"), QStringLiteral("OUT.mp4"), QStringLiteral("the MP4 to write (or --png-dir)")},
            {QStringLiteral("png-dir"), QStringLiteral("DIR"), QStringLiteral("write every frame as a PNG in DIR instead")},
            {QStringLiteral("captions"), QStringLiteral("LEFT[,RIGHT]"),
             QStringLiteral("a caption in the corner of each panel (ASCII)"), {}, CommandOption::Optional,
             {QStringLiteral("labels")}},
            {QStringLiteral("crf"), QStringLiteral("0..51"), QStringLiteral("H.264 quality (lower is better)"),
             QStringLiteral("20")}};
}

VideoOutput VideoOutput::from(const CommandLine &args, int panels)
{
    VideoOutput output;
    output.out = args.value(QStringLiteral("out"));
    output.pngDir = args.value(QStringLiteral("png-dir"));
    if (output.out.isEmpty() == output.pngDir.isEmpty())
        throw UsageError(QStringLiteral("give either --out OUT.mp4 or --png-dir DIR"));
    output.crf = args.integer(QStringLiteral("crf"), 0, 51);
    for (const QString &caption : args.list(QStringLiteral("captions")))
        output.captions.push_back(caption.toStdString());
    if (!output.captions.empty() && int(output.captions.size()) != panels)
        throw UsageError(QStringLiteral("--captions takes one caption per panel (%1)").arg(panels));
    return output;
}

} // namespace lipsync::cli
