#pragma once
// The File → Open Recent list, kept in QSettings ("recentProjects", newest first).
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
    void add(const QString &folder);
    void clear();

signals:
    void openRequested(const QString &folder);

private:
    void rebuildMenu();

    QMenu *m_menu;
};

} // namespace lipsync::studio
