#pragma once
// Forced alignment as a background task (TaskRunner): the chosen Aligner (align/Aligner.h: the
// shipped GRID model or $LIPSYNC_ALIGNER_MODEL, or CMU Sphinx's generic model), the project's
// pronunciations, the CMU dictionary, and espeak-ng for other words (reported back so the user
// can check them). The worker only computes; the tiers reach the document in the commit, through
// ProjectDocument::requestTiersChange, so cancel leaves the project untouched.
#include "align/Aligner.h"
#include "document/TierEdits.h"
#include "project/Sequence.h"

#include <QString>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lipsync {
class Feedback;
class Task;
class TaskRunner;
} // namespace lipsync

namespace lipsync::studio {

struct AlignJob
{
    int row = -1;
    QString sequenceId;
    QString mediaPath;
    std::string transcript;
    // Re-align only these stretches [start, end) of `current` (seconds, on word boundaries),
    // everything else stays; empty: align the whole sequence.
    std::vector<std::pair<double, double>> stretches;
    TierPair current;
    // The project's pronunciation overrides (Project::pronunciations).
    std::map<std::string, std::string> pronunciations;
    // Which aligner, and whether it adapts to the recording's speaker first.
    AlignerChoice aligner;
};

struct AlignOutcome
{
    int row = -1;
    QString sequenceId;
    QString mediaPath;
    bool ok = false;
    TierPair tiers;
    QString error;     // why it failed (for unknown words: names them)
    QString errorFile; // the file concerned
    // Words only espeak-ng could pronounce, with its guess ("N AW Z IY"), for the user to check.
    std::vector<std::pair<std::string, std::string>> guessed;
};

// One job, on the calling thread, with `aligner` (the job's choice): the work startAlignment's
// task does for each job. Throws lipsync::Error naming the media file.
AlignOutcome alignSequence(const AlignJob &job, const Aligner &aligner, Feedback &feedback);

// Aligns the jobs one after the other (progress per job, cancel between them), with the aligners
// of `aligners` (loaded there on first use). Failures of single sequences are reported in their
// outcome and the others go on; the task itself fails only when every job failed (its error
// lists them). `apply` runs on the GUI thread.
Task *startAlignment(TaskRunner &runner, const QString &title, std::vector<AlignJob> jobs,
                     std::shared_ptr<AlignerCache> aligners, std::function<void(std::vector<AlignOutcome>)> apply);

// The job that aligns `sequence` (at `row`, media at `mediaPath`) again, keeping what the user
// edited: when its tiers hold user-edited intervals and its word tier still spells the
// transcript, only the free stretches are aligned (Realignment, as Re-align Selection does over
// the whole clip); otherwise the whole sequence. `discardsEdits` (may be null) is set when the
// job would replace user-edited intervals — the transcript changed since they were made — so
// the caller can ask first. A job whose every word is edited has no stretch and no transcript
// left to align (`nothingToAlign`).
struct SequenceAlignment
{
    AlignJob job;
    bool discardsEdits = false;
    bool nothingToAlign = false;
};
SequenceAlignment alignmentFor(int row, const Sequence &sequence, const QString &mediaPath,
                               const std::map<std::string, std::string> &pronunciations);

// The stretches of `tiers` to re-align for the selection [a, b): runs of consecutive words
// overlapping it whose word and phones the user has not edited (userEdited words stay fixed).
std::vector<std::pair<double, double>> realignStretches(const TierPair &tiers, double a, double b);

} // namespace lipsync::studio
