// Project::fromMediaFolder: a new project from a folder of recordings.
#include "project/Project.h"

#include "io/AtomicFile.h"
#include "io/GridAlign.h"
#include "io/MediaFolder.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <set>

namespace lipsync {

namespace {

// The transcript of a sequence: an .align file's words with their timings; an .lab or .txt file's
// text as it is; the spoken words of subtitles or a TextGrid's word tier.
void readSequenceTranscript(const std::string &path, Sequence &sequence)
{
    const QString suffix = QFileInfo(QString::fromStdString(path)).suffix().toLower();
    if (suffix == QLatin1String("align")) {
        sequence.words = readGridAlign(path);
        sequence.words.name = "words";
        sequence.transcript = transcriptFromTier(sequence.words);
    } else if (suffix == QLatin1String("lab") || suffix == QLatin1String("txt")) {
        const std::string text = readWholeFile(path);
        sequence.transcript = QString::fromUtf8(text.data(), qsizetype(text.size())).simplified().toStdString();
    } else {
        sequence.transcript = readTranscript(path).text();
    }
}

// Adds the sequence of one media file (and its transcript) to `project`; throws lipsync::Error
// naming the file when it cannot be read.
void addMediaFile(Project &project, const MediaFile &file, const QString &projectDir, std::set<std::string> &ids)
{
    const std::string &path = file.path;
    const MediaInfo info = MediaInfo::probe(path);
    const QFileInfo fileInfo(QString::fromStdString(path));

    Sequence s;
    s.id = file.id;
    // clip.mpg and clip.wav side by side: the second becomes "clip_wav".
    if (!ids.insert(s.id).second) {
        s.id += '_';
        s.id += fileInfo.suffix().toLower().toStdString();
        if (!ids.insert(s.id).second)
            throw Error("two media files give the sequence id '" + s.id + "'", path);
    }
    s.mediaFile = QDir(projectDir).relativeFilePath(fileInfo.absoluteFilePath()).toStdString();
    if (info.hasVideo) {
        s.setClock(info.frames);
    } else {
        s.frameRate = Project::kAudioOnlyFrameRate;
        s.frameCount = int(std::lround(info.audioEndTime * Project::kAudioOnlyFrameRate));
    }
    if (!(s.frameRate > 0) || !std::isfinite(s.frameRate))
        throw Error("no usable frame rate", path);
    if (!file.transcript.empty())
        readSequenceTranscript(file.transcript, s);
    project.sequences.push_back(std::move(s));
}

} // namespace

Project Project::fromMediaFolder(const std::string &mediaFolder, const std::string &projectFolder,
                                 std::vector<std::string> *skipped)
{
    const QDir dir(QString::fromStdString(mediaFolder));
    if (!dir.exists())
        throw Error("no such media folder", mediaFolder);
    const QString projectDir =
        QDir::cleanPath(QFileInfo(QString::fromStdString(projectFolder)).absoluteFilePath());

    Project project;
    project.setFolder(projectDir.toStdString());
    project.name = QFileInfo(projectDir).fileName().toStdString();

    std::set<std::string> ids;
    for (const MediaFile &file : listMediaFolder(mediaFolder)) {
        try {
            addMediaFile(project, file, projectDir, ids);
        } catch (const Error &e) {
            if (!skipped)
                throw;
            skipped->push_back(e.what());
        }
    }
    if (project.sequences.empty())
        throw Error(skipped && !skipped->empty() ? "no readable media file (" + skipped->front() + ")"
                                                 : "no media files (" + mediaExtensionList() + ")",
                    mediaFolder);
    return project;
}


} // namespace lipsync
