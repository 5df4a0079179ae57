#pragma once
// Open / save / save as / recent projects for the main window: the dialogs, the read-only demo
// rule and the error messages. A failed open or save changes nothing.
#include <QObject>
#include <QString>

class QMenu;
class QWidget;

namespace lipsync::studio {

class ProjectDocument;
class RecentProjects;

class ProjectFiles : public QObject
{
    Q_OBJECT
public:
    ProjectFiles(ProjectDocument *document, QWidget *window, QMenu *recentMenu);

    // Loads the project in `folder` (or the folder of a project.json). Returns false, having
    // reported why, if it cannot be loaded; the open document is then untouched.
    bool open(const QString &path);
    bool openDemo();
    // Save: to the project's folder; for the read-only demo it behaves as Save As.
    bool save();
    bool saveAs();
    // Before closing or replacing a modified document: save, discard or cancel. True = go on.
    bool maybeSave();

public slots:
    void openWithDialog();

private:
    bool saveTo(const QString &folder);

    ProjectDocument *m_document;
    QWidget *m_window;
    RecentProjects *m_recent;
};

} // namespace lipsync::studio
