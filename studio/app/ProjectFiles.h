#pragma once
// New / open / save / save as / recent projects for the main window: the dialogs, the read-only
// demo rule and the error messages. A failed new, open or save changes nothing.
#include "project/Project.h"

#include <QObject>
#include <QString>

class QMenu;
class QWidget;

namespace lipsync {
class Task;
class TaskRunner;
} // namespace lipsync

namespace lipsync::studio {

class Autosave;
class ProjectDocument;
class RecentProjects;

class ProjectFiles : public QObject
{
    Q_OBJECT
public:
    ProjectFiles(ProjectDocument *document, QWidget *window, QMenu *recentMenu, TaskRunner *runner);

    // A new project from a folder of clips with their transcripts beside them (as `lipsync
    // project create`: Project::fromMediaFolder), written into `projectFolder` (the clips stay
    // where they are) and opened. The clips are probed in a background task, returned (null if
    // `projectFolder` already holds a project, which is reported); a failure is reported naming
    // the file and leaves the open document as it was.
    Task *createFromMediaFolder(const QString &mediaFolder, const QString &projectFolder);

    // Loads the project in `folder` (or the folder of a project.json). Returns false, having
    // reported why, if it cannot be loaded; the open document is then untouched. If a crash left
    // an autosave newer than the project, offers to recover it (see Autosave): recovered
    // changes open as unsaved changes; Cancel opens nothing and returns false.
    bool open(const QString &path);
    bool openDemo();
    // Save: to the project's folder; for the read-only demo it behaves as Save As.
    bool save();
    bool saveAs();
    // Save As without the dialog: writes the document into `folder`. A failure is reported and
    // leaves no new file in `folder`, the document and its autosave as they were.
    bool saveTo(const QString &folder);
    // Before closing or replacing a modified document: save, discard or cancel. True = go on.
    bool maybeSave();

    Autosave *autosave() const { return m_autosave; }

public slots:
    void openWithDialog();
    // Asks for the folder of clips; the project is written into that folder.
    void newProjectWithDialog();

private:
    bool openLoaded(Project project, const QString &folder, bool readOnly);

    ProjectDocument *m_document;
    QWidget *m_window;
    RecentProjects *m_recent;
    Autosave *m_autosave;
    TaskRunner *m_runner;
};

} // namespace lipsync::studio
