#include "project/Project.h"

#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "project/ProjectManifest.h"
#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>

#include <cmath>
#include <map>

namespace lipsync {

namespace {

QString q(const std::string &s)
{
    return QString::fromStdString(s);
}

std::string absolutePath(const std::string &path)
{
    return QDir::cleanPath(QFileInfo(q(path)).absoluteFilePath()).toStdString();
}

// Where a save puts changed feature files until the manifest names them (see save).
constexpr const char *kStagingFolder = "features/.saving";

// Sequence id -> the features file the manifest on disk names (empty if it cannot be read).
std::map<std::string, std::string> featureFilesOf(const std::string &manifest)
{
    std::map<std::string, std::string> files;
    QFile file(q(manifest));
    if (!file.open(QIODevice::ReadOnly))
        return files;
    const QJsonArray sequences = QJsonDocument::fromJson(file.readAll()).object().value("sequences").toArray();
    for (const QJsonValue &value : sequences) {
        const QJsonObject o = value.toObject();
        if (o.value("features").isString())
            files[o.value("id").toString().toStdString()] = o.value("features").toString().toStdString();
    }
    return files;
}

void setFeatureFile(QJsonObject &manifest, size_t sequence, const std::string &relative)
{
    QJsonArray sequences = manifest.value("sequences").toArray();
    QJsonObject o = sequences[qsizetype(sequence)].toObject();
    o.insert("features", q(relative));
    sequences[qsizetype(sequence)] = o;
    manifest.insert("sequences", sequences);
}

void writeManifest(const std::string &path, const QJsonObject &json)
{
    const QByteArray text = ProjectManifest::serialize(json);
    writeFileAtomically(path, std::string(text.constData(), size_t(text.size())));
}

} // namespace

std::string Project::manifestPath(const std::string &folder)
{
    return QDir::cleanPath(QDir(q(folder)).absoluteFilePath(q(kManifestName))).toStdString();
}

Project Project::load(const std::string &folderOrManifest)
{
    std::string folder = folderOrManifest;
    const QFileInfo given(q(folderOrManifest));
    if (given.isFile() && given.fileName() == QLatin1String(kManifestName))
        folder = given.absolutePath().toStdString();
    folder = absolutePath(folder);
    if (!QFileInfo(q(folder)).isDir())
        throw Error("no such project folder", folder);
    const std::string manifest = manifestPath(folder);
    if (!QFileInfo(q(manifest)).isFile())
        throw Error(std::string("not a project folder (no ") + kManifestName + ")", manifest);
    const std::string text = readWholeFile(manifest);
    Project project = ProjectManifest::parse(QByteArray(text.data(), qsizetype(text.size())),
                                             manifest, folder);
    project.m_folder = folder;
    return project;
}

void Project::save(const std::string &folderArgument) const
{
    if (folderArgument.empty())
        throw Error("the project has no folder yet; save it into a folder first");
    const std::string folder = absolutePath(folderArgument);
    const std::string manifest = manifestPath(folder);

    validate(folder);
    const QJsonObject json = ProjectManifest::toJson(*this, folder);

    if (!QDir().mkpath(q(folder)))
        throw Error("cannot create the project folder", folder);
    // The manifest is the commit point: every feature file it names is complete before it is
    // replaced, so a crash at any moment leaves a manifest that loads with the features it was
    // saved with (the old version or the new one, never a mix). Changed features of a project
    // already on disk are therefore first written beside the ones the current manifest uses
    // (features/.saving/), the manifest switched to them, then moved into place and the manifest
    // switched back. Anything failing before the manifest is replaced leaves the old one (and
    // its .bak) as they were. Features of a sequence that no longer has any stay on disk,
    // unreferenced, rather than deleting user data.
    const QDir dir(q(folder));
    const bool replacing = QFileInfo(q(manifest)).isFile();
    const std::map<std::string, std::string> current = replacing ? featureFilesOf(manifest)
                                                                 : std::map<std::string, std::string>{};
    QJsonObject staged = json;
    std::vector<std::pair<std::string, std::string>> moves; // (staged path, final path)
    for (size_t i = 0; i < sequences.size(); ++i) {
        const Sequence &s = sequences[i];
        if (s.features.size() == 0)
            continue;
        const std::string relative = ProjectManifest::featureFileName(s.id);
        const std::string path = dir.filePath(q(relative)).toStdString();
        const std::string text = formatFeatureCsv(s.features, {}, 0.0, path);
        const auto used = current.find(s.id);
        if (used == current.end() || used->second != relative || !QFileInfo(q(path)).isFile()) {
            // The manifest on disk does not read this file (or it is gone): no version to keep.
            writeFileAtomically(path, text);
            continue;
        }
        if (text == readWholeFile(path))
            continue; // unchanged: nothing written
        const std::string stagedRelative = std::string(kStagingFolder) + "/" + s.id + ".csv";
        const std::string stagedPath = dir.filePath(q(stagedRelative)).toStdString();
        writeFileAtomically(stagedPath, text);
        setFeatureFile(staged, i, stagedRelative);
        moves.emplace_back(stagedPath, path);
    }
    // The study is written whole before the manifest that names it (saveStudy rewrites it alone
    // after every answer of a participant, so it stands apart from the manifest's versions).
    if (study)
        study->save(dir.filePath(q(kStudyFileName)).toStdString());
    if (replacing)
        writeFileAtomically(manifest + ".bak", readWholeFile(manifest));
    writeManifest(manifest, staged);
    if (moves.empty()) {
        QDir(dir).rmdir(QString::fromLatin1(kStagingFolder)); // only if empty
        return;
    }
    for (const auto &[from, to] : moves)
        writeFileAtomically(to, readWholeFile(from));
    writeManifest(manifest, json);
    QDir(dir.filePath(QString::fromLatin1(kStagingFolder))).removeRecursively();
}

void Project::validate(const std::string &folderArgument) const
{
    const std::string folder = absolutePath(folderArgument);
    const std::string manifest = manifestPath(folder);
    // The manifest by reading back what would be written (the same checks as load), the
    // features here since load reads them from the CSV.
    ProjectManifest::fromJson(ProjectManifest::toJson(*this, folder), manifest, folder, /*readFeatures=*/false);
    for (size_t i = 0; i < sequences.size(); ++i) {
        const Sequence &s = sequences[i];
        if (s.features.size() == 0)
            continue;
        const std::string field = "sequences[" + std::to_string(i) + "].features";
        if (!s.features.allFinite())
            throw Error("sequence '" + s.id + "': features contain NaN or infinite values",
                        manifest, field);
        if (s.features.rows() != s.frameCount)
            throw Error("sequence '" + s.id + "': " + std::to_string(s.features.rows())
                            + " feature rows, expected frameCount " + std::to_string(s.frameCount),
                        manifest, field);
    }
}

void Project::saveAs(const std::string &folderArgument)
{
    save(folderArgument);
    const std::string folder = absolutePath(folderArgument);
    const std::string from = m_folder.empty() ? folder : m_folder;
    for (Sequence &s : sequences)
        s.mediaFile = rebaseRelativePath(s.mediaFile, from, folder);
    for (ModelReference &m : models)
        m.file = rebaseRelativePath(m.file, from, folder);
    m_folder = folder;
}

void Project::saveStudy() const
{
    if (m_folder.empty())
        throw Error("the project has no folder yet; save it into a folder first");
    if (!study)
        throw Error("the project has no study", manifestPath());
    study->save(studyPath());
}

std::string Project::resolve(const std::string &relative) const
{
    if (QDir::isAbsolutePath(q(relative)))
        return QDir::cleanPath(q(relative)).toStdString();
    return QDir::cleanPath(QDir(q(m_folder.empty() ? std::string(".") : m_folder))
                               .absoluteFilePath(q(relative)))
        .toStdString();
}

Sequence *Project::sequence(const std::string &id)
{
    for (Sequence &s : sequences)
        if (s.id == id)
            return &s;
    return nullptr;
}

const Sequence *Project::sequence(const std::string &id) const
{
    return const_cast<Project *>(this)->sequence(id);
}

const ModelReference *Project::model(const std::string &kind) const
{
    for (auto it = models.rbegin(); it != models.rend(); ++it)
        if (it->kind == kind)
            return &*it;
    return nullptr;
}

std::string Project::aamPath() const
{
    const ModelReference *reference = aam();
    if (!reference)
        throw Error("the project has no AAM: build one first (lipsync aam build, or Faces ▸ Build AAM)", manifestPath());
    return resolve(reference->file);
}

bool Project::operator==(const Project &other) const
{
    return name == other.name && sequences == other.sequences && models == other.models
           && study == other.study && pronunciations == other.pronunciations && aligner == other.aligner
           && mouthShapes == other.mouthShapes;
}

} // namespace lipsync
