// `lipsync project import-long PROJECT MEDIA --transcript FILE`: a long recording into a project
// as utterance sequences (render/LongRecordingImport): aligned in bounded memory, cut at its
// pauses, one clip per utterance with its words and alignment.
#include "CommandLine.h"
#include "SpeechAligner.h"

#include "align/LongAlignment.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "render/LongRecordingImport.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>

#include <cstdio>
#include <unistd.h>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// Progress on stderr: a percentage rewritten in place on a terminal, a line per tenth otherwise.
void showProgress(Feedback &feedback)
{
    const bool terminal = isatty(fileno(stderr)) != 0;
    feedback.onProgress = [terminal, shown = -1](double fraction) mutable {
        const int percent = int(fraction * 100.0);
        if (terminal ? percent == shown : percent / 10 == shown / 10)
            return;
        shown = percent;
        if (terminal)
            std::fprintf(stderr, "\r\033[Kimporting: %3d %%", percent);
        else
            std::fprintf(stderr, "importing: %d %%\n", percent);
        std::fflush(stderr);
    };
}

double positiveNumber(const CommandLine &a, const char *name)
{
    const double v = a.number(QString::fromLatin1(name));
    if (!(v > 0))
        throw UsageError(QStringLiteral("--%1 must be a number > 0").arg(QString::fromLatin1(name)));
    return v;
}

// The project in `folder`; a folder that does not exist yet, or is empty, gets a new empty project
// (named after the folder) for the recording to go into. A folder holding other files but no
// project is refused: those files are not ours to mix with.
Project loadOrCreate(const QString &folder)
{
    const QDir dir(folder);
    if (dir.exists(QString::fromLatin1(Project::kManifestName)))
        return Project::load(folder.toStdString());
    if (dir.exists() && !dir.isEmpty(QDir::AllEntries | QDir::NoDotAndDotDot))
        throw Error("the folder holds files but no project (" + std::string(Project::kManifestName)
                        + "): import into an empty or new folder, or make a project here with lipsync project create",
                    folder.toStdString());
    if (!QDir().mkpath(folder))
        throw Error("cannot create the project folder", folder.toStdString());
    Project project;
    project.name = QFileInfo(QDir::cleanPath(dir.absolutePath())).fileName().toStdString();
    project.aligner = Project::kGenericAligner; // a new person: the model that fits anyone
    project.saveAs(QDir(folder).absolutePath().toStdString());
    return project;
}

int runImportLong(const CommandLine &a)
{
    const QString projectFolder = a.positional(0);
    const QString media = a.positional(1);
    LongRecordingImportOptions options;
    options.split.minimumPause = positiveNumber(a, "min-pause");
    options.split.shortest = positiveNumber(a, "shortest");
    options.split.longest = positiveNumber(a, "longest");
    if (options.split.longest < options.split.shortest)
        throw UsageError(QStringLiteral("--longest must be at least --shortest"));
    try {
        Project project = loadOrCreate(projectFolder);
        // A recording longer than CMU Sphinx aligns is cut with the shipped model, window by
        // window; its utterances can be aligned again with the generic model once cut.
        const SpeechAligner aligner(a, projectFolder, true, MediaInfo::probe(media.toStdString()).audioDuration);
        if (aligner.usesShippedForLong())
            std::fprintf(stderr,
                         "lipsync: %s is longer than CMU Sphinx aligns (%d min): cut with the shipped model of GRID's "
                         "speaker; align the utterances again with the project's generic model: lipsync align %s "
                         "--out DIR, then lipsync project import %s --alignments DIR\n",
                         qPrintable(media), int(kLongRecordingSeconds / 60), qPrintable(projectFolder),
                         qPrintable(projectFolder));
        const Transcript transcript = readTranscript(a.value("transcript").toStdString());
        Feedback feedback;
        if (!a.isSet("json"))
            showProgress(feedback);
        QElapsedTimer timer;
        timer.start();
        LongRecordingImportResult r =
            importLongRecording(project, media.toStdString(), transcript.words, a.value("transcript").toStdString(),
                                aligner.aligner(), aligner.lexicon(), options, feedback);
        const size_t imported = r.sequences.size();
        if (transcriptMisfit(r.transcriptFit))
            std::fprintf(stderr, "lipsync: warning: %s: %s: check the words before training on its utterances\n",
                         qPrintable(a.value("transcript")), r.transcriptFit->reason().c_str());
        QJsonArray ids;
        for (Sequence &s : r.sequences) {
            ids.append(QString::fromStdString(s.id));
            project.sequences.push_back(std::move(s));
        }
        project.save();
        const double seconds = timer.elapsed() / 1000.0;
        if (a.isSet("json")) {
            printJson(QJsonObject{{QStringLiteral("project"), projectFolder},
                                  {QStringLiteral("media"), media},
                                  {QStringLiteral("aligner"), aligner.modelName()},
                                  {QStringLiteral("duration"), r.duration},
                                  {QStringLiteral("utteranceSeconds"), r.spokenSeconds},
                                  {QStringLiteral("words"), r.words},
                                  {QStringLiteral("transcriptFit"), r.transcriptFit ? QJsonValue(r.transcriptFit->value) : QJsonValue()},
                                  {QStringLiteral("transcriptFitThreshold"),
                                   r.transcriptFit ? QJsonValue(r.transcriptFit->threshold) : QJsonValue()},
                                  {QStringLiteral("sequences"), ids},
                                  {QStringLiteral("seconds"), seconds}});
        } else {
            std::fprintf(stderr, "\r\033[K");
            std::printf("imported %zu utterances (%d words, %.1f of %.1f s) of %s into %s in %.1f s\n",
                        imported, r.words, r.spokenSeconds, r.duration, qPrintable(media),
                        qPrintable(projectFolder), seconds);
        }
    } catch (const Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
    return 0;
}

const CommandRegistration registration{
    CommandSpec{
        QStringLiteral("project import-long"),
        QStringLiteral("a long recording into a project as utterance sequences, aligned and cut at its pauses"),
        QStringLiteral("Aligns a long recording (up to 3 hours: a broadcast, a lecture) to its transcript in bounded "
                       "memory, a window at a time (subtitle cue times, if the transcript is .srt or .vtt, choose "
                       "the words of each window), cuts it at its pauses into utterances and adds each to the "
                       "project as a sequence of its own: a clip in PROJECT/clips (MP4 from a video, WAV from "
                       "sound alone; the sound mono at 16 kHz) with its words and alignment. The project is saved; a "
                       "new or empty folder becomes a new project."),
        {{QStringLiteral("transcript"), QStringLiteral("FILE"),
          QStringLiteral("the words spoken (.txt, .srt, .vtt, .lab, .align or a TextGrid words tier)"), {},
          CommandOption::Required},
         {QStringLiteral("min-pause"), QStringLiteral("S"),
          QStringLiteral("a silence this long (seconds) ends an utterance once it lasts --shortest"),
          QStringLiteral("0.3")},
         {QStringLiteral("shortest"), QStringLiteral("S"), QStringLiteral("seconds an utterance lasts before a pause ends it"),
          QStringLiteral("2")},
         {QStringLiteral("longest"), QStringLiteral("S"),
          QStringLiteral("seconds after which the longest silence so far (or a word boundary) ends it"),
          QStringLiteral("12")}},
        {{QStringLiteral("PROJECT"), QStringLiteral("the project folder (new or empty: a project is made there)")},
         {QStringLiteral("MEDIA"), QStringLiteral("the recording (any audio or video file)")}}}
        .add(SpeechAligner::options({}, false)),
    &runImportLong};

} // namespace
