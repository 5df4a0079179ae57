#include "Compositing.h"

#include "CommandLine.h"

namespace lipsync::cli {

std::vector<CommandOption> Compositing::options()
{
    return {{QStringLiteral("full-face"), {},
             QStringLiteral("synthesise the whole modelled face, eyes included (default: the lower face, the "
                            "recording's eyes and upper face kept)")},
            {QStringLiteral("no-colour-match"), {},
             QStringLiteral("keep the model's mean colour instead of matching the frame's lighting")},
            {QStringLiteral("no-detail"), {},
             QStringLiteral("draw the model's smooth texture only, without the detail (teeth, lip highlights) "
                            "of the AAM's nearest training images")},
            {QStringLiteral("no-lip-closure"), {},
             QStringLiteral("draw the model's trajectory as generated, without closing the lips on /p b m/")}};
}

CompositeOptions Compositing::from(const CommandLine &args)
{
    CompositeOptions options;
    options.region = args.isSet(QStringLiteral("full-face")) ? FaceRegion::Full : FaceRegion::Lower;
    options.matchColour = !args.isSet(QStringLiteral("no-colour-match"));
    options.detail = !args.isSet(QStringLiteral("no-detail"));
    return options;
}

bool Compositing::closesLips(const CommandLine &args)
{
    return !args.isSet(QStringLiteral("no-lip-closure"));
}

} // namespace lipsync::cli
