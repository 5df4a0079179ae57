#pragma once
// The File → Open Recent list, kept in QSettings ("recentProjects", newest first), and the
// project the last session had open ("session/lastProject"; empty for the bundled demo), which
// the studio reopens when it is launched without one.
#include <QObject>
#include <QStringList>

class QMenu;

namespace lipsync::studio {

class RecentProjects : public QObject
{
    Q_OBJECT
public:
    static constexpr int kMaxEntries = 8;

    RecentProjects(QMenu *menu, QObject *parent = nullptr);

    QStringList folders() const;
    // A project opened or saved: first in the list, and the one the next launch reopens.
    void add(const QString &folder);
    // The bundled demo opened: the next launch opens the demo again.
    void openedDemo();
    void clear();

    // The folder of the project the last session had open, if it still holds one; else empty.
    static QString lastSession();

signals:
    void openRequested(const QString &folder);

private:
    void rebuildMenu();

    QMenu *m_menu;
};

} // namespace lipsync::studio
