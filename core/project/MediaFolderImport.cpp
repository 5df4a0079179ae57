// Project::fromMediaFolder: a new project from a folder of recordings.
#include "project/Project.h"

#include "io/AtomicFile.h"
#include "io/GridAlign.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>
#include <set>

namespace lipsync {

namespace {

const QStringList kMediaSuffixes{"mpg", "mp4", "mov", "avi", "mkv", "wav"};

// Reads <stem>.align (words with timings), else <stem>.lab / <stem>.txt (plain words), else the
// spoken words of <stem>.srt / <stem>.vtt (subtitles).
void readSequenceTranscript(const QDir &dir, const QString &stem, Sequence &sequence)
{
    const QString align = dir.filePath(stem + QLatin1String(".align"));
    if (QFileInfo(align).isFile()) {
        sequence.words = readGridAlign(align.toStdString());
        sequence.words.name = "words";
        sequence.transcript = transcriptFromTier(sequence.words);
        return;
    }
    for (const QString suffix : {QStringLiteral(".lab"), QStringLiteral(".txt"), QStringLiteral(".srt"),
                                 QStringLiteral(".vtt")}) {
        const QString path = dir.filePath(stem + suffix);
        if (!QFileInfo(path).isFile())
            continue;
        if (suffix == QLatin1String(".srt") || suffix == QLatin1String(".vtt")) {
            sequence.transcript = readTranscript(path.toStdString()).text(); // the cues' spoken words
        } else {
            const std::string text = readWholeFile(path.toStdString());
            sequence.transcript = QString::fromUtf8(text.data(), qsizetype(text.size())).simplified().toStdString();
        }
        return;
    }
}

} // namespace

Project Project::fromMediaFolder(const std::string &mediaFolder, const std::string &projectFolder)
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
    const QFileInfoList files = dir.entryInfoList(QDir::Files, QDir::Name);
    for (const QFileInfo &file : files) {
        // Hidden files would give ids starting with '.', which the manifest rejects.
        if (!kMediaSuffixes.contains(file.suffix().toLower()) || file.fileName().startsWith('.'))
            continue;
        const std::string path = file.absoluteFilePath().toStdString();
        const MediaInfo info = MediaInfo::probe(path);

        Sequence s;
        s.id = file.completeBaseName().toStdString();
        // clip.mpg and clip.wav side by side: the second becomes "clip_wav".
        if (!ids.insert(s.id).second) {
            s.id += '_';
            s.id += file.suffix().toLower().toStdString();
            if (!ids.insert(s.id).second)
                throw Error("two media files give the sequence id '" + s.id + "'", path);
        }
        s.mediaFile = QDir(projectDir).relativeFilePath(file.absoluteFilePath()).toStdString();
        if (info.hasVideo) {
            s.frameRate = info.frameRate;
            s.frameCount = info.frameCount;
        } else {
            s.frameRate = kAudioOnlyFrameRate;
            s.frameCount = int(std::lround(info.audioDuration * kAudioOnlyFrameRate));
        }
        if (!(s.frameRate > 0) || !std::isfinite(s.frameRate))
            throw Error("no usable frame rate", path);
        readSequenceTranscript(dir, file.completeBaseName(), s);
        project.sequences.push_back(std::move(s));
    }
    if (project.sequences.empty())
        throw Error("no media files (*.mpg, *.mp4, *.mov, *.avi, *.mkv, *.wav)", mediaFolder);
    return project;
}

} // namespace lipsync
