#include "app/RecentProjects.h"

#include "project/Project.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace lipsync::studio {

namespace {
const QString kKey = QStringLiteral("recentProjects");
const QString kLastKey = QStringLiteral("session/lastProject");
}

RecentProjects::RecentProjects(QMenu *menu, QObject *parent) : QObject(parent), m_menu(menu)
{
    rebuildMenu();
}

QStringList RecentProjects::folders() const
{
    return QSettings().value(kKey).toStringList();
}

void RecentProjects::add(const QString &folder)
{
    const QString clean = QDir::cleanPath(QFileInfo(folder).absoluteFilePath());
    QStringList list = folders();
    list.removeAll(clean);
    list.prepend(clean);
    while (list.size() > kMaxEntries)
        list.removeLast();
    QSettings().setValue(kKey, list);
    QSettings().setValue(kLastKey, clean);
    rebuildMenu();
}

void RecentProjects::openedDemo()
{
    QSettings().remove(kLastKey);
}

QString RecentProjects::lastSession()
{
    const QString folder = QSettings().value(kLastKey).toString();
    if (folder.isEmpty() || !QFileInfo::exists(QDir(folder).filePath(QString::fromLatin1(Project::kManifestName))))
        return {};
    return folder;
}

void RecentProjects::clear()
{
    QSettings().remove(kKey);
    rebuildMenu();
}

void RecentProjects::rebuildMenu()
{
    m_menu->clear();
    const QStringList list = folders();
    int n = 0;
    for (const QString &folder : list) {
        const QString label = QStringLiteral("&%1 %2").arg(++n).arg(QDir::toNativeSeparators(folder));
        QAction *a = m_menu->addAction(label);
        a->setEnabled(QFileInfo(folder).isDir());
        connect(a, &QAction::triggered, this, [this, folder] { emit openRequested(folder); });
    }
    if (list.isEmpty()) {
        m_menu->addAction(tr("No recent projects"))->setEnabled(false);
        return;
    }
    m_menu->addSeparator();
    connect(m_menu->addAction(tr("Clear List")), &QAction::triggered, this, &RecentProjects::clear);
}

} // namespace lipsync::studio
