// `lipsync render`: new speech -> aligned phones -> generated face parameters -> the face rendered
// into the clip's frames (or a neutral frame for audio only) -> MP4 with the recording's sound.
// All of it is core/render/SpeechToFace (renderSpeechVideo), which the studio uses too.
#include "AlignerSupport.h"
#include "Command.h"

#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"

#include <QElapsedTimer>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

const char *kRenderUsage =
    "usage: lipsync render --model MODEL --aam AAM --media CLIP --transcript FILE\n"
    "                      (--out OUT.mp4 | --png-dir DIR)\n"
    "                      [--side-by-side] [--labels LEFT,RIGHT] [--aligner MODEL] [--fps F]\n"
    "                      [--full-face] [--no-colour-match] [--crf 20] [--json]\n"
    "  CLIP: any audio or video file with speech (audio only renders onto a neutral frame).\n"
    "  FILE: the words spoken (.align, .lab, .txt or a TextGrid words tier).\n"
    "  --side-by-side: the real clip left, the generated face right.\n"
    "  --full-face: synthesise the whole modelled face, eyes included (default: the lower face,\n"
    "               the recording's eyes and upper face kept).\n"
    "  --no-colour-match: keep the model's mean colour instead of matching the frame's lighting.";

int runRender(const QStringList &argv)
{
    const Arguments args(argv);
    const QStringList unknown = args.unknown({"model", "aam", "media", "transcript", "out", "side-by-side",
                                              "labels", "aligner", "fps", "crf", "png-dir", "full-face",
                                              "no-colour-match", "json"});
    if (!unknown.isEmpty() || !args.positional().isEmpty())
        return fail(QStringLiteral("render: unknown argument %1\n").arg((unknown + args.positional()).first())
                        + QString::fromLatin1(kRenderUsage),
                    2);
    SpeechToFaceRequest request;
    request.modelPath = args.value("model").toStdString();
    request.aamPath = args.value("aam").toStdString();
    request.mediaPath = args.value("media").toStdString();
    request.transcriptPath = args.value("transcript").toStdString();
    const QString out = args.value("out");
    const QString pngDir = args.value("png-dir");
    if (request.modelPath.empty() || request.aamPath.empty() || request.mediaPath.empty()
        || request.transcriptPath.empty() || out.isEmpty() == pngDir.isEmpty())
        return fail(QString::fromLatin1(kRenderUsage), 2);
    request.alignerModelPath =
        (args.has("aligner") ? args.value("aligner") : defaultAlignerModel()).toStdString();
    if (request.alignerModelPath.empty())
        return fail(QStringLiteral("render: no --aligner given and the shipped model "
                                   "resources/aligner/grid-s1.aligner was not found "
                                   "(set LIPSYNC_ALIGNER_MODEL)"));
    bool ok = true;
    if (args.has("fps")) {
        request.frameRate = args.value("fps").toDouble(&ok);
        if (!ok || !(request.frameRate > 0))
            return fail(QStringLiteral("render: --fps must be a positive number"), 2);
    }
    RenderOptions options;
    options.sideBySide = args.flag("side-by-side");
    options.composite.region = args.flag("full-face") ? FaceRegion::Full : FaceRegion::Lower;
    options.composite.matchColour = !args.flag("no-colour-match");
    options.video.crf = args.value("crf", "20").toInt(&ok);
    if (!ok || options.video.crf < 0 || options.video.crf > 51)
        return fail(QStringLiteral("render: --crf takes an integer in 0..51"), 2);
    if (args.has("labels")) {
        const QStringList labels = args.value("labels").split(QLatin1Char(','));
        if (labels.size() != (options.sideBySide ? 2 : 1))
            return fail(QStringLiteral("render: --labels takes one label per panel"), 2);
        options.leftLabel = labels.front().trimmed().toStdString();
        options.rightLabel = labels.back().trimmed().toStdString();
    }

    Feedback feedback;
    SpeechVideoReport report;
    if (!pngDir.isEmpty()) {
        // The same steps as renderSpeechVideo, frames to PNGs instead of an MP4.
        report.generated = generateFromSpeech(request, feedback);
        QElapsedTimer timer;
        timer.start();
        const auto renderer = makeRenderer(report.generated, request.mediaPath, feedback);
        report.framesWritten = int(
            exportRenderedImages(report.generated, *renderer, pngDir.toStdString(), feedback, options).size());
        report.renderSeconds = timer.elapsed() / 1000.0;
    } else {
        report = renderSpeechVideo(request, out.toStdString(), feedback, options);
    }
    const SpeechToFaceResult &g = report.generated;
    if (args.flag("json")) {
        printJson(QJsonObject{
            {"out", out.isEmpty() ? pngDir : out},
            {"media", args.value("media")},
            {"model", QString::fromStdString(g.modelKind)},
            {"aligner", QString::fromStdString(g.alignerModelPath)},
            {"frameRate", g.frameRate},
            {"frames", report.framesWritten},
            {"generatedFrames", g.frameCount()},
            {"dimension", int(g.features.cols())},
            {"audioDuration", g.audio.duration()},
            {"video", g.hasVideo},
            {"sideBySide", options.sideBySide},
            {"region", options.composite.region == FaceRegion::Full ? "full" : "lower"},
            {"colourMatch", options.composite.matchColour},
            {"phones", int(g.phones.intervals.size())},
            {"generateSeconds", g.seconds},
            {"renderSeconds", report.renderSeconds},
        });
    } else {
        std::printf("%s: %d frames (%s model, %s) in %.2f s + %.2f s\n", qPrintable(out.isEmpty() ? pngDir : out), report.framesWritten,
                    g.modelKind.c_str(), g.hasVideo ? "into the clip" : "neutral frame", g.seconds,
                    report.renderSeconds);
    }
    return 0;
}

const CommandRegistration registration{
    QStringLiteral("render"),
    QStringLiteral("align new speech, generate the face and render it as MP4 with the sound"), &runRender};

} // namespace
