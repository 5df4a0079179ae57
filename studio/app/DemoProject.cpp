#include "app/DemoProject.h"

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
    QStringList candidates;
    candidates << qEnvironmentVariable("LIPSYNC_DEMO_DIR");
    candidates << QDir(QCoreApplication::applicationDirPath()).filePath(QStringLiteral("../share/lipsync/demo"));
#ifdef LIPSYNC_SOURCE_DIR
    candidates << QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
#endif
    for (const QString &c : std::as_const(candidates))
        if (isDemoFolder(c))
            return QDir::cleanPath(QFileInfo(c).absoluteFilePath());
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
