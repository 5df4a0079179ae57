#include "TrainingData.h"

#include "CommandLine.h"

#include "dynamics/LabelledFolder.h"
#include "project/Project.h"

#include <algorithm>

namespace lipsync::cli {

namespace {

// The project's sequences with features and phones (core/dynamics/LabelledFolder).
std::vector<LabelledSequence> projectSequences(const std::string &folder, std::string *projectAam)
{
    const Project project = Project::load(folder);
    if (projectAam) {
        const ModelReference *aam = project.aam();
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
             QStringLiteral("with --features: the video frame rate of feature files that record none (\"# fps=RATE\")")},
            {QStringLiteral("exclude"), QStringLiteral("ID,ID,..."),
             QStringLiteral("leave these sequences (or feature files, by name) out: held out for testing the model")}};
}

std::vector<LabelledSequence> loadTrainingData(const CommandLine &args, std::string *projectAam)
{
    const bool project = args.isSet(QStringLiteral("project"));
    const bool folders = args.isSet(QStringLiteral("features")) || args.isSet(QStringLiteral("labels"));
    if (project == folders)
        throw UsageError(QStringLiteral("give either --project DIR or --features DIR --labels DIR"));
    std::vector<LabelledSequence> sequences;
    if (project) {
        sequences = projectSequences(args.value(QStringLiteral("project")).toStdString(), projectAam);
    } else {
        if (!args.isSet(QStringLiteral("features")) || !args.isSet(QStringLiteral("labels")))
            throw UsageError(QStringLiteral("--features and --labels go together"));
        // The frame rate the feature files record; --fps only for files that record none.
        const double fps = args.isSet(QStringLiteral("fps")) ? args.positiveNumber(QStringLiteral("fps")) : 0.0;
        sequences = loadLabelledFolder(args.value(QStringLiteral("features")).toStdString(),
                                       args.value(QStringLiteral("labels")).toStdString(), fps);
    }
    // --exclude: every id named must be one of the data's (a typo would silently train on it).
    for (const QString &id : args.list(QStringLiteral("exclude"))) {
        const auto it = std::find_if(sequences.begin(), sequences.end(),
                                     [&](const LabelledSequence &s) { return s.name == id.toStdString(); });
        if (it == sequences.end())
            throw UsageError(QStringLiteral("--exclude: no sequence '%1' with features and phones to leave out").arg(id));
        sequences.erase(it);
    }
    if (sequences.empty())
        throw UsageError(QStringLiteral("--exclude leaves no sequence to train on"));
    return sequences;
}

} // namespace lipsync::cli
