#pragma once
// Which forced aligner aligns a project's speech: one rule for the CLI (cli/SpeechAligner) and the
// studio's Speech menu (TimelinePanel), one rule for recordings longer than CMU Sphinx aligns
// (`project import-long`, the studio's Import Long Recording), and one for new speech in another
// voice than the aligner's speaker's (render, export animation, Generate from Speech).
#include "align/Aligner.h"
#include "align/AlignerTrainer.h"

#include <optional>
#include <string>
#include <vector>

namespace lipsync {

class AcousticModel;
class Feedback;
class Lexicon;
class Project;

// The project's choice (Project::aligner): its own aligner model when it names one (a model
// reference of kind "aligner", resolved to a path), else CMU Sphinx adapted to each recording's
// speaker for kGenericAligner, else the shipped model (an empty model) for kBuiltinAligner.
// nullopt: the project does not say (no own model, no `aligner`), so the caller's default holds.
std::optional<AlignerChoice> projectAlignerChoice(const Project &project);

// The path of the project's own aligner model, empty when it has none.
std::string projectAlignerModel(const Project &project);

// CMU Sphinx aligns at most kLongRecordingSeconds (SphinxAligner): for a recording of `seconds`
// beyond that, a Sphinx choice gives way to the shipped model, which aligns window by window
// (alignLongRecording). True when `choice` was changed.
bool fallBackForLongRecording(AlignerChoice &choice, double seconds);

// New speech in any voice (render, export animation, the studio's Generate from Speech): aligned by
// `chosen`, made from `choice` with its transcript fit measured. A model of one speaker's voice (ours;
// the shipped one is GRID s1's) misfits another voice as it misfits other words: when the words
// misfit it and the user did not name it (`named`), CMU Sphinx's generic model adapted to the
// recording aligns them again, and that alignment is kept when they fit it. The generic aligner
// comes from `cache` when given (loaded once a session, as the studio's other aligners). Where a
// second alignment may follow, the first reports over the first three quarters of `feedback`'s
// range and the second over the rest, so the progress never goes back.
struct VoiceAlignment
{
    AlignerOutput output;
    std::string aligner;                      // Aligner::name of the aligner kept
    bool generic = false;                     // the generic model's alignment replaced the first
    std::optional<TranscriptFit> chosenFit;   // the first alignment's fit, when the generic model was tried
    bool genericTried() const { return chosenFit.has_value(); }
};
VoiceAlignment alignAnyVoice(const Aligner &chosen, const AlignerChoice &choice, bool named,
                             const RecordingSound &sound, const std::vector<std::string> &words,
                             const Lexicon &lexicon, Feedback &feedback, const std::string &transcriptPath = {},
                             AlignerCache *cache = nullptr);

// The project's sequences with a transcript, as utterances to adapt or train an aligner of the
// speaker's own on (SpeakerAdaptation, AlignerTrainer): decoded, their features as `model`
// computes them and their words pronounced by `lexicon`. Those that cannot be used (no sound,
// silence, words that do not fit) are left out and named in `skipped` ("id: reason"). Progress
// and cancel through `feedback`.
std::vector<TrainingUtterance> projectUtterances(const Project &project, const AcousticModel &model,
                                                 const Lexicon &lexicon, Feedback &feedback,
                                                 std::vector<std::string> *skipped = nullptr);

} // namespace lipsync
