#include "TrainingData.h"

#include "dynamics/LabelledFolder.h"
#include "project/Project.h"

#include <cmath>

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

QString loadTrainingData(const Arguments &args, std::vector<LabelledSequence> &sequences,
                         std::string *projectAam)
{
    const bool project = args.has(QStringLiteral("project"));
    const bool folders = args.has(QStringLiteral("features")) || args.has(QStringLiteral("labels"));
    if (project == folders)
        return QStringLiteral("give either --project DIR or --features DIR --labels DIR");
    if (project) {
        sequences = projectSequences(args.value(QStringLiteral("project")).toStdString(), projectAam);
        return {};
    }
    if (!args.has(QStringLiteral("features")) || !args.has(QStringLiteral("labels")))
        return QStringLiteral("--features and --labels go together");
    // The frame rate the feature files record; --fps only for files that record none.
    double fps = 0.0;
    if (args.has(QStringLiteral("fps"))) {
        bool ok = false;
        fps = args.value(QStringLiteral("fps")).toDouble(&ok);
        if (!ok || !(fps > 0) || !std::isfinite(fps))
            return QStringLiteral("--fps must be a positive number");
    }
    sequences = loadLabelledFolder(args.value(QStringLiteral("features")).toStdString(),
                                   args.value(QStringLiteral("labels")).toStdString(), fps);
    return {};
}

} // namespace lipsync::cli
