#include "align/ProjectAligner.h"

#include "align/AlignerUtterance.h"
#include "align/LongAlignment.h"
#include "align/SphinxAligner.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

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
        choice.useGenericAdapted();
        return choice;
    }
    if (project.aligner == Project::kBuiltinAligner)
        return choice;
    return std::nullopt;
}

VoiceAlignment alignAnyVoice(const Aligner &chosen, const AlignerChoice &choice, bool named,
                             const RecordingSound &sound, const std::vector<std::string> &words,
                             const Lexicon &lexicon, Feedback &feedback, const std::string &transcriptPath,
                             AlignerCache *cache)
{
    // The share of the progress the first alignment reports over [choice: most alignments are the
    // first alone; a second, only where the words misfit, reports over the rest].
    constexpr double kFirstShare = 0.75;
    const bool mayRetry = !named && !choice.isSphinx() && SphinxAligner::available();
    VoiceAlignment result;
    Feedback first(feedback, 0.0, mayRetry ? kFirstShare : 1.0);
    result.output = chosen.align(sound, words, lexicon, first, transcriptPath);
    result.aligner = chosen.name();
    if (mayRetry && transcriptMisfit(result.output.transcriptFit)) {
        AlignerChoice generic;
        generic.useGenericAdapted();
        generic.transcriptFit = true;
        try {
            const std::shared_ptr<const Aligner> aligner =
                cache ? cache->get(generic) : std::shared_ptr<const Aligner>(createAligner(generic));
            feedback.setStatus("The words misfit this voice: aligning them again with CMU Sphinx's generic model");
            Feedback second(feedback, kFirstShare, 1.0);
            AlignerOutput again = aligner->align(sound, words, lexicon, second, transcriptPath);
            result.chosenFit = result.output.transcriptFit;
            if (again.transcriptFit && !again.transcriptFit->misfit()) {
                result.output = std::move(again);
                result.aligner = aligner->name();
                result.generic = true;
            }
        } catch (const Error &) {
            // beyond what it aligns (a recording too long for it): the first stands
        }
    }
    feedback.setProgress(1.0);
    return result;
}

bool fallBackForLongRecording(AlignerChoice &choice, double seconds)
{
    if (!choice.isSphinx() || seconds <= kLongRecordingSeconds)
        return false;
    choice.model.clear(); // the shipped model, unadapted: adaptation needs a short recording too
    choice.adapt = false;
    return true;
}

std::vector<TrainingUtterance> projectUtterances(const Project &project, const AcousticModel &model,
                                                 const Lexicon &lexicon, Feedback &feedback,
                                                 std::vector<std::string> *skipped)
{
    std::vector<TrainingUtterance> utterances;
    const size_t n = project.sequences.size();
    for (size_t k = 0; k < n; ++k) {
        feedback.throwIfCanceled();
        feedback.setProgress(double(k) / double(std::max<size_t>(1, n)));
        const Sequence &s = project.sequences[k];
        const std::vector<std::string> words = Sequence::transcriptWords(s.transcript);
        if (words.empty()) {
            if (skipped)
                skipped->push_back(s.id + ": no transcript");
            continue;
        }
        try {
            PreparedUtterance p = prepareUtterance(s.id, project.mediaPath(s), words, model, lexicon);
            utterances.push_back({p.id, std::move(p.features), std::move(p.pronunciations), {}});
        } catch (const Error &e) {
            if (skipped)
                skipped->push_back(s.id + ": " + e.what());
        }
    }
    feedback.setProgress(1.0);
    return utterances;
}

} // namespace lipsync

