#include "TrainingData.h"

#include "CommandLine.h"

#include "dynamics/LabelledFolder.h"
#include "project/Project.h"

namespace lipsync::cli {

namespace {

// The project's sequences with features and phones (core/dynamics/LabelledFolder).
std::vector<LabelledSequence> projectSequences(const std::string &folder, std::string *projectAam)
{
    const Project project = Project::load(folder);
    if (projectAam) {
        const ModelReference *aam = project.model("aam");
        *projectAam = aam ? project.resolve(aam->file) : std::string();
    }
    return loadProjectSequences(project);
}

} // namespace

std::vector<CommandOption> trainingDataOptions()
{
    return {{QStringLiteral("project"), QStringLiteral("DIR"),
             QStringLiteral("a project: its sequences with both face features and a phone alignment")},
            {QStringLiteral("features"), QStringLiteral("DIR"),
             QStringLiteral("instead of --project: a folder of feature files NAME.csv (lipsync track)")},
            {QStringLiteral("labels"), QStringLiteral("DIR"),
             QStringLiteral("with --features: their phone labels NAME.TextGrid or NAME.lab")},
            {QStringLiteral("fps"), QStringLiteral("RATE"),
             QStringLiteral("with --features: the video frame rate of feature files that record none (\"# fps=RATE\")")}};
}

std::vector<LabelledSequence> loadTrainingData(const CommandLine &args, std::string *projectAam)
{
    const bool project = args.isSet(QStringLiteral("project"));
    const bool folders = args.isSet(QStringLiteral("features")) || args.isSet(QStringLiteral("labels"));
    if (project == folders)
        throw UsageError(QStringLiteral("give either --project DIR or --features DIR --labels DIR"));
    if (project)
        return projectSequences(args.value(QStringLiteral("project")).toStdString(), projectAam);
    if (!args.isSet(QStringLiteral("features")) || !args.isSet(QStringLiteral("labels")))
        throw UsageError(QStringLiteral("--features and --labels go together"));
    // The frame rate the feature files record; --fps only for files that record none.
    const double fps = args.isSet(QStringLiteral("fps")) ? args.positiveNumber(QStringLiteral("fps")) : 0.0;
    return loadLabelledFolder(args.value(QStringLiteral("features")).toStdString(),
                              args.value(QStringLiteral("labels")).toStdString(), fps);
}

} // namespace lipsync::cli
