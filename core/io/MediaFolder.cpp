#include "io/MediaFolder.h"

#include "io/Transcript.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>

namespace lipsync {

const std::vector<std::string> &mediaExtensions()
{
    static const std::vector<std::string> list{".mpg", ".mp4", ".mov", ".avi", ".mkv", ".webm",
                                               ".wav", ".flac", ".mp3", ".ogg", ".m4a"};
    return list;
}

std::string mediaExtensionList()
{
    std::string out;
    for (const std::string &ext : mediaExtensions())
        out += (out.empty() ? "*" : ", *") + ext;
    return out;
}

std::vector<MediaFile> listMediaFolder(const std::string &folder, const std::string &transcriptFolder)
{
    const QDir dir(QString::fromStdString(folder));
    if (!dir.exists())
        throw Error("no such folder", folder);
    const QDir transcripts(QString::fromStdString(transcriptFolder.empty() ? folder : transcriptFolder));
    // Every file of the transcript folder by lower-case name, for case-insensitive lookups.
    std::vector<std::pair<QString, QString>> names;
    for (const QString &name : transcripts.entryList(QDir::Files))
        names.emplace_back(name.toLower(), name);
    std::sort(names.begin(), names.end());
    auto transcriptOf = [&](const QString &stem) {
        for (const std::string &ext : transcriptExtensions()) {
            const QString wanted = (stem + QString::fromStdString(ext)).toLower();
            const auto it = std::lower_bound(names.begin(), names.end(), std::make_pair(wanted, QString()));
            if (it != names.end() && it->first == wanted)
                return transcripts.absoluteFilePath(it->second).toStdString();
        }
        return std::string();
    };
    std::vector<MediaFile> out;
    for (const QFileInfo &file : dir.entryInfoList(QDir::Files, QDir::Name)) {
        const std::string ext = (QLatin1Char('.') + file.suffix().toLower()).toStdString();
        const auto &known = mediaExtensions();
        if (file.fileName().startsWith(QLatin1Char('.')) || std::find(known.begin(), known.end(), ext) == known.end())
            continue;
        const QString stem = file.completeBaseName();
        out.push_back({stem.toStdString(), file.absoluteFilePath().toStdString(), transcriptOf(stem)});
    }
    return out;
}

} // namespace lipsync
