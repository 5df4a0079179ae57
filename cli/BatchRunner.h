#pragma once
// The folder and project forms of `align`, `track` and `landmarks detect`: one job per recording
// (or image), all in one process so that models load once.
//  - Inputs (batchRecordings): a project folder (its sequences' media and transcripts) or a
//    folder of media files (io/MediaFolder, transcripts of the same stem beside them or in
//    another folder).
//  - -j N worker threads (default: one per core), each job on one of them.
//  - --shard I/N: only every N-th recording from the I-th (1-based), for N machines or the
//    tasks of a cluster job array sharing one folder (scripts/cluster).
//  - Resumable: a job whose output exists and is newer than every one of its inputs is skipped
//    (--force redoes it); outputs are written atomically, so a killed run leaves no half files.
//  - Progress on stderr: a bar with the ETA on a terminal, one line per finished job otherwise.
//  - At the end, a summary naming every failed file and why; exit code 1 if any failed.
#include "Command.h"

#include <QDir>
#include <QJsonArray>
#include <QJsonObject>
#include <QString>
#include <QStringList>

#include <functional>
#include <string>
#include <vector>

namespace lipsync {
class Feedback;
}

namespace lipsync::cli {

class CommandLine;

// A recording of a project or a media folder.
struct BatchRecording
{
    QString id;
    QString media;
    QString transcriptFile;  // a folder's transcript file, empty if none
    std::string transcript;  // a project sequence's transcript text (when transcriptFile is empty)
    QString project;         // the project's manifest, for a project's sequences
};

// Whether `path` is a folder: the positional argument of a batch form.
bool isBatchInput(const QString &path);
// The recordings of a project folder (one with a project.json) or of a media folder, with the
// transcripts of `transcriptFolder` when not empty. Throws lipsync::Error naming the folder when
// it holds none.
std::vector<BatchRecording> batchRecordings(const QString &folder, const QString &transcriptFolder = {});

struct BatchJob
{
    QString name;       // for progress and failures
    QString file;       // the input named in a failure
    QStringList inputs; // the files the output is made from
    QString output;     // the file the job writes
};

// clip.mpg and clip.wav (or clip.jpg) side by side: the second job's output and name get the
// extension, clip_wav.TextGrid, as project create names its sequence, so no output is written twice.
void makeOutputsUnique(std::vector<BatchJob> &jobs);

// The folder --out names, created if need be; lipsync::Error naming it if it cannot be.
QDir batchOutputFolder(const CommandLine &args);

// --shard I/N: this process's share of the recordings, every N-th from the I-th.
struct Shard
{
    int index = 0; // 0-based
    int count = 1;
};
CommandOption shardOption();
// UsageError for a malformed value; {0, 1} without the option.
Shard shardOf(const CommandLine &args);

// -j/--jobs N, --force and --shard I/N, for a command's CommandSpec.
std::vector<CommandOption> batchOptions();

class BatchRunner
{
public:
    using Work = std::function<QJsonObject(const BatchJob &job, Feedback &feedback)>;

    // Reads -j, --force and --json from `args`.
    explicit BatchRunner(const CommandLine &args);

    // Runs `work` for every job of this shard that is not up to date, `threads()` at a time. `work` throws
    // lipsync::Error (or any std::exception) for a failed job; the others go on. Returns
    // {jobs, done, skipped, failed, seconds, failures: [{name, file, reason}], results: [...]}.
    QJsonObject run(const std::vector<BatchJob> &jobs, const Work &work) const;
    int threads() const { return m_threads; }

    // Prints the summary (JSON with --json) and returns the exit code: 1 if any job failed.
    int finish(const QJsonObject &summary, const QString &verb) const;

private:
    int m_threads = 1;
    bool m_force = false;
    Shard m_shard;
    bool m_json = false;
};

} // namespace lipsync::cli
