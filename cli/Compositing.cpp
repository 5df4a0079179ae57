#include "Compositing.h"

#include "CommandLine.h"

namespace lipsync::cli {

std::vector<CommandOption> Compositing::options()
{
    return {{QStringLiteral("full-face"), {},
             QStringLiteral("synthesise the whole modelled face, eyes included (default: the recording's own face, "
                            "its lips moved to the generated opening and width)")},
            {QStringLiteral("synthesize-skin"), {},
             QStringLiteral("paste the AAM's synthesis of the lower face (skin included) instead of moving the "
                            "recording's own")},
            {QStringLiteral("no-colour-match"), {},
             QStringLiteral("keep the model's mean colour instead of matching the frame's lighting")},
            {QStringLiteral("no-detail"), {},
             QStringLiteral("draw the model's smooth texture only, without the detail (teeth, lip highlights) "
                            "of the AAM's nearest training images")},
            {QStringLiteral("drawn-closures"), {},
             QStringLiteral("draw lips closed where the recording's are open with the AAM's synthesis, instead of "
                            "the person's own closed lips from another moment of the video")},
            {QStringLiteral("drawn-insides"), {},
             QStringLiteral("draw the inside of a mouth opened wider than recorded with the AAM's synthesis, instead "
                            "of the person's own open mouth from another moment of the video")},
            {QStringLiteral("no-lip-closure"), {},
             QStringLiteral("draw the model's trajectory as generated, without closing the lips on /p b m/")},
            {QStringLiteral("model-posture"), {},
             QStringLiteral("draw the model's average posture outside the speech (head set, jaw, expression) instead "
                            "of keeping the posture of the frames drawn into")}};
}

CompositeOptions Compositing::from(const CommandLine &args)
{
    CompositeOptions options;
    options.region = args.isSet(QStringLiteral("full-face")) ? FaceRegion::Full : FaceRegion::Lower;
    options.synthesizeSkin = args.isSet(QStringLiteral("synthesize-skin"));
    options.matchColour = !args.isSet(QStringLiteral("no-colour-match"));
    options.detail = !args.isSet(QStringLiteral("no-detail"));
    options.recordedClosures = !args.isSet(QStringLiteral("drawn-closures"));
    options.recordedInsides = !args.isSet(QStringLiteral("drawn-insides"));
    return options;
}

bool Compositing::closesLips(const CommandLine &args)
{
    return !args.isSet(QStringLiteral("no-lip-closure"));
}

bool Compositing::keepsPosture(const CommandLine &args)
{
    return !args.isSet(QStringLiteral("model-posture"));
}

} // namespace lipsync::cli
