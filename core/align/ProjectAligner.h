#pragma once
// Which forced aligner aligns a project's speech: one rule for the CLI (cli/SpeechAligner) and the
// studio's Speech menu (TimelinePanel), and one rule for recordings longer than CMU Sphinx aligns
// (`project import-long`, the studio's Import Long Recording).
#include "align/Aligner.h"

#include <optional>

namespace lipsync {

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

} // namespace lipsync
