#include "project/Project.h"

#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "project/ProjectManifest.h"
#include "util/Error.h"

#include <QDir>
#include <QFileInfo>

#include <cmath>

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

    // Validate everything before touching the disk: the manifest by reading back what would be
    // written (the same checks as load), the features here since load reads them from the CSV.
    const QJsonObject json = ProjectManifest::toJson(*this, folder);
    ProjectManifest::fromJson(json, manifest, folder, /*readFeatures=*/false);
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

    if (!QDir().mkpath(q(folder)))
        throw Error("cannot create the project folder", folder);
    // Features first and the manifest last: if anything fails on the way, the old manifest is
    // still the one on disk (each file is replaced atomically; features of a sequence that no
    // longer has any stay on disk, unreferenced, rather than deleting user data).
    for (const Sequence &s : sequences)
        if (s.features.size() > 0)
            writeFeatureCsv(QDir(q(folder)).filePath(q(ProjectManifest::featureFileName(s.id)))
                                .toStdString(),
                            s.features);
    if (study)
        study->save(QDir(q(folder)).filePath(q(kStudyFileName)).toStdString());
    if (QFileInfo(q(manifest)).isFile())
        writeFileAtomically(manifest + ".bak", readWholeFile(manifest));
    const QByteArray text = ProjectManifest::serialize(json);
    writeFileAtomically(manifest, std::string(text.constData(), size_t(text.size())));
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

bool Project::operator==(const Project &other) const
{
    return name == other.name && sequences == other.sequences && models == other.models
           && study == other.study && pronunciations == other.pronunciations;
}

} // namespace lipsync
