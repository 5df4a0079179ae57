#include "align/ProjectAligner.h"

#include "align/LongAlignment.h"
#include "project/Project.h"

namespace lipsync {

std::string projectAlignerModel(const Project &project)
{
    const ModelReference *own = project.model("aligner");
    return own ? project.resolve(own->file) : std::string();
}

std::optional<AlignerChoice> projectAlignerChoice(const Project &project)
{
    AlignerChoice choice;
    if (std::string own = projectAlignerModel(project); !own.empty()) {
        choice.model = std::move(own); // the speaker's own model wins over what the project says
        return choice;
    }
    if (project.aligner == Project::kGenericAligner) {
        choice.model = "sphinx";
        choice.adapt = true;
        return choice;
    }
    if (project.aligner == Project::kBuiltinAligner)
        return choice;
    return std::nullopt;
}

bool fallBackForLongRecording(AlignerChoice &choice, double seconds)
{
    if (!choice.isSphinx() || seconds <= kLongRecordingSeconds)
        return false;
    choice.model.clear(); // the shipped model, unadapted: adaptation needs a short recording too
    choice.adapt = false;
    return true;
}

} // namespace lipsync
