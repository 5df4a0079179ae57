#include "app/DemoProject.h"

#include "util/ResourceLocator.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

namespace lipsync::studio {

namespace {

bool isDemoFolder(const QString &folder)
{
    const QDir dir(folder);
    return !folder.isEmpty()
           && (dir.exists(QString::fromLatin1(Project::kManifestName)) || dir.exists(QStringLiteral("media")));
}

} // namespace

QString DemoProject::locate()
{
    for (const std::string &folder : ResourceLocator::folders()) {
        const QString demo = QDir(QString::fromStdString(folder)).filePath(QStringLiteral("demo"));
        if (isDemoFolder(demo))
            return QDir::cleanPath(QFileInfo(demo).absoluteFilePath());
    }
    return {};
}

Project DemoProject::load(const QString &folder)
{
    const QDir dir(folder);
    if (dir.exists(QString::fromLatin1(Project::kManifestName)))
        return Project::load(folder.toStdString());
    Project project = Project::fromMediaFolder(dir.filePath(QStringLiteral("media")).toStdString(),
                                               folder.toStdString());
    if (project.name.empty())
        project.name = "demo";
    return project;
}

QString DemoProject::defaultSaveFolder()
{
    return QDir::home().filePath(QStringLiteral("lipsync-projects/demo"));
}

} // namespace lipsync::studio
