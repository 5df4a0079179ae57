// `lipsync export cues` and `lipsync export controls`: a person's mouth as animation data, from a
// project's tracked sequence or from new speech generated with a trained model. The mapping from
// this person's mouth to cues and controls is learned from the project's tracked, aligned
// sequences (animation/MouthMapping), with the user's own shapes (Project::mouthShapes).
#include "CommandLine.h"
#include "SpeechAligner.h"

#include "aam/AamModel.h"
#include "animation/AnimationControls.h"
#include "animation/MouthCues.h"
#include "animation/MouthMapping.h"
#include "animation/MouthTrack.h"
#include "dynamics/ModelFile.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QJsonArray>
#include <QJsonObject>

#include <cstdio>
#include <tuple>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// What both commands read: the project's AAM and mapping, and the one track to export.
struct AnimationSource
{
    Project project;
    std::shared_ptr<const AamModel> aam;
    MouthMapping mapping;
    MouthTrack track;
};

AnimationSource readSource(const CommandLine &args)
{
    if (!args.isSet("project"))
        throw UsageError(QStringLiteral("--project DIR is required: its AAM and its tracked sequences define the mouth"));
    if (args.isSet("sequence") == args.isSet("media"))
        throw UsageError(QStringLiteral("give either --sequence ID (a tracked sequence) or --media with --transcript "
                                        "and --model (new speech)"));
    AnimationSource source;
    source.project = Project::load(args.value("project").toStdString());
    const std::string aamPath = source.project.aamPath();
    source.aam = std::make_shared<const AamModel>(AamModel::load(aamPath));
    const MouthMeasurer measurer(*source.aam);
    if (args.isSet("sequence")) {
        const Sequence *s = source.project.sequence(args.value("sequence").toStdString());
        if (!s)
            throw Error("no sequence '" + args.value("sequence").toStdString() + "' in the project",
                        source.project.manifestPath());
        std::tie(source.mapping, source.track) = projectMouthMappingAndTrack(measurer, source.project, *s);
        return source;
    }
    source.mapping = projectMouthMapping(measurer, source.project);
    if (!args.isSet("transcript") || !args.isSet("model"))
        throw UsageError(QStringLiteral("--media needs --transcript and --model"));
    SpeechToFaceRequest request;
    request.mediaPath = args.value("media").toStdString();
    request.transcriptPath = args.value("transcript").toStdString();
    request.modelPath = args.value("model").toStdString();
    request.aamPath = aamPath;
    request.aam = source.aam;
    request.pronunciations = source.project.pronunciations;
    const SpeechAligner aligner(args, args.value("project"), true, 0, modelTrainingAligner(request.modelPath));
    const Transcript transcript = readTranscript(request.transcriptPath);
    const RecordingSound sound(request.mediaPath); // decoded once for the aligner and the result
    sound.own();
    const AlignerOutput aligned = aligner.alignAnyVoice(sound, transcript.words, args.value("transcript")); // as render
    Feedback feedback;
    source.track = mouthTrackOfGenerated(measurer, generateFromAlignment(request, aligned, sound, feedback));
    return source;
}

std::vector<CommandOption> sourceOptions()
{
    std::vector<CommandOption> options{
        {QStringLiteral("out"), QStringLiteral("FILE"), QStringLiteral("the file to write (its extension says the format)"),
         {}, CommandOption::Required},
        {QStringLiteral("sequence"), QStringLiteral("ID"), QStringLiteral("a tracked, aligned sequence of the project")},
        {QStringLiteral("media"), QStringLiteral("CLIP"), QStringLiteral("new speech (any audio or video file)")},
        {QStringLiteral("transcript"), QStringLiteral("FILE"), QStringLiteral("the words of --media")},
        {QStringLiteral("model"), QStringLiteral("MODEL"),
         QStringLiteral("a dynamic model trained on the project (lipsync train) to generate --media's face with")},
    };
    for (CommandOption &o : SpeechAligner::options())
        options.push_back(std::move(o));
    return options;
}

int runExportCues(const CommandLine &args)
{
    DatOptions dat;
    if (args.isSet("dat-fps"))
        dat.frameRate = args.positiveNumber("dat-fps");
    dat.prestonBlair = !args.isSet("dat-letters");
    try {
        const AnimationSource source = readSource(args);
        const MouthCueTrack cues = mouthCues(source.track, source.mapping);
        writeMouthCues(cues, args.value("out").toStdString(), dat);
        if (args.isSet("json")) {
            QJsonObject shapes;
            for (const MouthCue &c : cues.cues) {
                const QString letter(QLatin1Char(mouthShapeLetter(c.shape)));
                shapes[letter] = shapes[letter].toInt() + 1;
            }
            printJson(QJsonObject{{"out", args.value("out")},
                                  {"soundFile", QString::fromStdString(cues.soundFile)},
                                  {"duration", cues.duration},
                                  {"cues", int(cues.cues.size())},
                                  {"shapes", shapes}});
        } else {
            std::printf("%s: %zu mouth cues over %.2f s\n", qPrintable(args.value("out")), cues.cues.size(),
                        cues.duration);
        }
    } catch (const Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
    return 0;
}

int runExportControls(const CommandLine &args)
{
    try {
        const AnimationSource source = readSource(args);
        const AnimationControls controls = animationControls(source.track, source.mapping);
        writeAnimationControls(controls, args.value("out").toStdString());
        if (args.isSet("json")) {
            QJsonArray names;
            for (const std::string &n : controls.names)
                names.append(QString::fromStdString(n));
            printJson(QJsonObject{{"out", args.value("out")},
                                  {"soundFile", QString::fromStdString(controls.soundFile)},
                                  {"frameRate", controls.frameRate},
                                  {"frames", controls.frameCount()},
                                  {"controls", names}});
        } else {
            std::printf("%s: %zu controls and 23 points on %d frames\n", qPrintable(args.value("out")),
                        controls.names.size(), controls.frameCount());
        }
    } catch (const Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
    return 0;
}

const CommandRegistration cuesRegistration{
    CommandSpec{QStringLiteral("export cues"),
                QStringLiteral("mouth cues A-H and X as Rhubarb Lip Sync writes them: TSV, JSON, XML or Moho .dat"),
                QStringLiteral("Writes a tracked sequence's or new speech's mouth as Rhubarb Lip Sync's mouth cues (the "
                               "nine shapes A-H and X) so that the plug-ins reading Rhubarb's output read it unchanged. "
                               "The format follows --out's extension: .tsv, .json, .xml or .dat (Moho switch data). "
                               "The shapes are learned from the project's tracked, aligned frames; X is rest in "
                               "silence, A every /p b m/."),
                [] {
                    std::vector<CommandOption> options = sourceOptions();
                    options.push_back({QStringLiteral("dat-fps"), QStringLiteral("RATE"),
                                       QStringLiteral(".dat: frames per second, 24 to 100 (default 24)")});
                    options.push_back({QStringLiteral("dat-letters"), {},
                                       QStringLiteral(".dat: the letters A-H and X instead of Preston Blair's names")});
                    return options;
                }(),
                {}},
    &runExportCues};

const CommandRegistration controlsRegistration{
    CommandSpec{QStringLiteral("export controls"),
                QStringLiteral("continuous 0-1 mouth controls named after ARKit's blend shapes, and the 23 points, "
                               "as JSON or CSV"),
                QStringLiteral("Writes a tracked sequence's or new speech's mouth as continuous controls per frame "
                               "(jawOpen, mouthClose, mouthFunnel, mouthPucker, mouthStretch, mouthUpperUp and "
                               "mouthLowerDown left and right, mouthOpen), 0 to 1 over this person's own range, and "
                               "the 23 points free of head pose, with the frame rate and the sound's file name. "
                               "The format follows --out's extension: .json or .csv."),
                sourceOptions(),
                {}},
    &runExportControls};

} // namespace
