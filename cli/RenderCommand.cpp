// `lipsync render`: new speech -> aligned phones -> generated face parameters -> the face rendered
// into the clip's frames (or a neutral frame for audio only) -> MP4 with the recording's sound.
// The alignment is SpeechAligner's (the options and results of `lipsync align`); generation and
// rendering are core/render/SpeechToFace, which the studio uses too.
#include "CommandLine.h"
#include "Compositing.h"
#include "SpeechAligner.h"
#include "VideoOutput.h"

#include "dynamics/ModelFile.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "util/Error.h"
#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"

#include <QElapsedTimer>
#include <QFileInfo>

#include <algorithm>

#include <cstdio>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// --background VIDEO, or PROJECT: the project's longest recording with video (the most of the
// person's head motion and blinks to re-time).
std::string backgroundVideo(const QString &given)
{
    if (!QFileInfo(given).isDir())
        return given.toStdString();
    const Project project = Project::load(given.toStdString());
    const Sequence *longest = nullptr;
    for (const Sequence &s : project.sequences)
        if ((!longest || s.frameCount > longest->frameCount) && MediaInfo::probe(project.mediaPath(s)).hasVideo)
            longest = &s;
    if (!longest)
        throw Error("the project has no recording with video to render into", project.manifestPath());
    return project.mediaPath(*longest);
}

int runRender(const CommandLine &args)
{
    SpeechToFaceRequest request;
    request.modelPath = args.value("model").toStdString();
    request.aamPath = args.value("aam").toStdString();
    request.mediaPath = args.value("media").toStdString();
    request.transcriptPath = args.value("transcript").toStdString();
    if (args.isSet("background"))
        request.backgroundPath = backgroundVideo(args.value("background"));
    if (args.isSet("fps"))
        request.frameRate = args.positiveNumber("fps");
    RenderOptions options;
    options.sideBySide = args.isSet("side-by-side");
    options.composite = Compositing::from(args);
    request.closeBilabials = Compositing::closesLips(args);
    request.keepPosture = Compositing::keepsPosture(args);
    const VideoOutput output = VideoOutput::from(args, options.sideBySide ? 2 : 1);
    const QString &out = output.out;
    const QString &pngDir = output.pngDir;
    options.video.crf = output.crf;
    if (!output.captions.empty()) {
        options.leftLabel = output.captions.front();
        options.rightLabel = output.captions.back();
    }

    // The shared aligner (the same choices as `lipsync align`), then generation from its phones.
    QElapsedTimer timer;
    timer.start();
    // The speaker's aligner: --aligner, else --project's or the --background project's, else the
    // one the model was trained with.
    const QString project = args.isSet("project") || !QFileInfo(args.value("background")).isDir()
                                ? args.value("project")
                                : args.value("background");
    const SpeechAligner aligner(args, project, true, 0, modelTrainingAligner(request.modelPath));
    const Transcript transcript = readTranscript(request.transcriptPath);
    // The sound decoded once, at its own rate, for the video; the aligner resamples it.
    const RecordingSound sound(request.mediaPath);
    sound.own();
    // In any voice (another than the aligner's speaker's is aligned again by the generic model);
    // words that are not the sound's give lips that do not match it: said, the render still made.
    QString alignerName;
    const AlignerOutput aligned = aligner.alignAnyVoice(sound, transcript.words, args.value("transcript"), &alignerName);
    Feedback feedback;
    SpeechVideoReport report;
    report.generated = generateFromAlignment(request, aligned, sound, feedback);
    report.generated.alignerModelPath = alignerName.toStdString();
    report.generated.seconds = timer.elapsed() / 1000.0;
    timer.restart();
    const auto renderer = makeRenderer(report.generated, request.mediaPath, feedback);
    if (!pngDir.isEmpty())
        report.framesWritten = int(
            exportRenderedImages(report.generated, *renderer, pngDir.toStdString(), feedback, options).size());
    else
        report.framesWritten = exportRenderedVideo(report.generated, *renderer, out.toStdString(), feedback, options);
    report.renderSeconds = timer.elapsed() / 1000.0;
    const SpeechToFaceResult &g = report.generated;
    if (args.isSet("json")) {
        printJson(QJsonObject{
            {"out", output.path()},
            {"media", args.value("media")},
            {"model", QString::fromStdString(g.modelKind)},
            {"aligner", QString::fromStdString(g.alignerModelPath)},
            {"frameRate", g.frameRate},
            {"frames", report.framesWritten},
            {"generatedFrames", g.frameCount()},
            {"dimension", int(g.features.cols())},
            {"audioDuration", g.frames.duration()}, // the sound as written: fitted to the frames
            {"video", g.hasVideo},
            {"background", QString::fromStdString(g.backgroundPath)},
            {"backgroundCuts", int(renderer->retiming().cuts.size())},
            {"backgroundReversals", renderer->retiming().reversals},
            {"backgroundLargestStep", renderer->retiming().largestStep},
            {"backgroundLargestCut", renderer->retiming().cutSteps.empty()
                                         ? 0.0
                                         : *std::max_element(renderer->retiming().cutSteps.begin(),
                                                             renderer->retiming().cutSteps.end())},
            {"backgroundNaturalStep99", renderer->retiming().naturalStep99},
            {"sideBySide", options.sideBySide},
            {"region", options.composite.region == FaceRegion::Full ? "full" : "lower"},
            {"colourMatch", options.composite.matchColour},
            {"detail", options.composite.detail},
            {"phones", int(g.phones.intervals.size())},
            {"generateSeconds", g.seconds},
            {"renderSeconds", report.renderSeconds},
        });
    } else {
        std::printf("%s: %d frames (%s model, %s) in %.2f s + %.2f s\n", qPrintable(output.path()), report.framesWritten,
                    g.modelKind.c_str(),
                    !g.backgroundPath.empty() ? "into the background video" : g.hasVideo ? "into the clip" : "neutral frame",
                    g.seconds,
                    report.renderSeconds);
    }
    return 0;
}

const CommandRegistration registration{
    CommandSpec{
        QStringLiteral("render"),
        QStringLiteral("align new speech, generate the face and render it as MP4 with the sound"),
        QStringLiteral("Aligns new speech to its transcript, generates the face's parameters with a trained dynamic "
                       "model and renders the face into the clip's frames, into another video of the person "
                       "(--background, re-timed to the speech's length), or onto a neutral frame for audio only: an "
                       "MP4 with the recording's sound and duration (--out) or PNGs (--png-dir)."),
        {{QStringLiteral("model"), QStringLiteral("MODEL"), QStringLiteral("a trained dynamic model (lipsync train)"),
          {}, CommandOption::Required},
         {QStringLiteral("aam"), QStringLiteral("AAM"), QStringLiteral("the AAM the model's features are parameters of"),
          {}, CommandOption::Required},
         {QStringLiteral("media"), QStringLiteral("CLIP"),
          QStringLiteral("any audio or video file with speech (audio only renders onto a neutral frame)"), {},
          CommandOption::Required},
         {QStringLiteral("transcript"), QStringLiteral("FILE"),
          QStringLiteral("the words spoken (.align, .lab, .txt, a TextGrid words tier, or .srt/.vtt subtitles)"), {}, CommandOption::Required},
         {QStringLiteral("background"), QStringLiteral("VIDEO|PROJECT"),
          QStringLiteral("a video of the person to render the new speech into (or a project: its longest "
                         "recording, and its aligner and pronunciations unless --project), played in runs with cuts where the head's motion allows for as long as the "
                         "speech lasts (default: the media's own frames)")},
         {QStringLiteral("side-by-side"), {}, QStringLiteral("the real clip left, the generated face right")},
         {QStringLiteral("fps"), QStringLiteral("RATE"),
          QStringLiteral("frames per second of the generated face (default: the video's rate; for audio only the "
                         "model's, else 25)")}},
                {}}
        .add(Compositing::options())
        .add(VideoOutput::options())
        .add(SpeechAligner::options()),
    &runRender};

} // namespace
