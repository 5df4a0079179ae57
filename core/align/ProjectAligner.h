#pragma once
// Which forced aligner aligns a project's speech: one rule for the CLI (cli/SpeechAligner) and the
// studio's Speech menu (TimelinePanel), and one rule for recordings longer than CMU Sphinx aligns
// (`project import-long`, the studio's Import Long Recording).
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

// The project's sequences with a transcript, as utterances to adapt or train an aligner of the
// speaker's own on (SpeakerAdaptation, AlignerTrainer): decoded, their features as `model`
// computes them and their words pronounced by `lexicon`. Those that cannot be used (no sound,
// silence, words that do not fit) are left out and named in `skipped` ("id: reason"). Progress
// and cancel through `feedback`.
std::vector<TrainingUtterance> projectUtterances(const Project &project, const AcousticModel &model,
                                                 const Lexicon &lexicon, Feedback &feedback,
                                                 std::vector<std::string> *skipped = nullptr);

} // namespace lipsync
