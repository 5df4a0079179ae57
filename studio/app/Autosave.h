#pragma once
// Crash safety of the open project: every few minutes (QSettings "autosave/intervalMinutes",
// default 3, 0 = off) and after each background task that changed the document (tracking,
// alignment, training), a modified document is written — off the GUI thread, atomically — to a
// side folder, never over the user's project.json (saving stays explicit):
//   <project>/.autosave/            for a project the user owns
//   <app data>/autosave/<hash>/     for the read-only bundled demo
// A save, undoing back to the saved state, discarding changes or closing cleanly removes it.
// So an autosave that is still there and newer than project.json when the project is opened was
// left behind by a crash: recoveryFor offers it (Recover / Discard / Cancel).
#include "project/Project.h"

#include <QDateTime>
#include <QFutureWatcher>
#include <QObject>
#include <QString>
#include <QTimer>

#include <functional>
#include <optional>

class QWidget;

namespace lipsync {
class TaskRunner;
}

namespace lipsync::studio {

class ProjectDocument;

class Autosave : public QObject
{
    Q_OBJECT
public:
    static constexpr int kDefaultIntervalMinutes = 3;

    enum class Choice { Recover, Discard, Cancel };
    // Asks the user what to do with a left-behind autosave (the default shows a message box;
    // tests install their own answer). Batch mode without a prompt neither asks nor deletes.
    using Prompt = std::function<Choice(QWidget *parent, const QString &projectFolder, const QDateTime &autosaved)>;
    static void setPrompt(Prompt prompt);

    Autosave(ProjectDocument *document, QWidget *window);
    ~Autosave() override; // a clean close: waits for a write in flight, removes the autosave

    // Also autosave when a task of `runner` finishes having changed the document.
    void watch(TaskRunner *runner);
    // The timer's period in ms (0: off), read from QSettings at construction.
    int intervalMs() const;
    void setIntervalMinutes(double minutes);

    // Starts writing the document if it changed since the last autosave and is modified.
    // Returns false if there was nothing to write. waitForWrite blocks until it is on disk.
    bool saveNow();
    void waitForWrite();
    // Removes the autosave of the open document (after waiting for a write in flight).
    void discard();

    // Where the autosave of the project in `projectFolder` lives.
    static QString folderFor(const QString &projectFolder, bool readOnly);
    // Writes `project` (living in `projectFolder`) as that project's autosave. Throws lipsync::Error.
    static void write(const Project &project, const QString &projectFolder, bool readOnly);

    // On open: if an autosave newer than the saved project is there, asks what to do. Recover:
    // `recovered` holds the autosaved project (paths relative to projectFolder). Discard: the
    // autosave is removed. Cancel: the caller opens nothing. An unreadable autosave is reported
    // and kept; the saved project opens.
    struct Offer
    {
        Choice choice = Choice::Discard;
        std::optional<Project> recovered;
    };
    static Offer recoveryFor(const QString &projectFolder, bool readOnly, QWidget *parent);

signals:
    // An autosave reached the disk (folder) or failed (message).
    void written(const QString &folder);
    void failed(const QString &message);

private:
    void onDocumentReset();
    void onWriteFinished();

    ProjectDocument *m_document;
    QTimer m_timer;
    QFutureWatcher<QString> m_write; // the error message, empty on success
    QString m_target;                // autosave folder of the open document ("" if none)
    QString m_writing;               // target of the write in flight
    bool m_changed = false;          // edited since the last autosave started
    bool m_pending = false;          // another write was asked for while one was in flight
};

} // namespace lipsync::studio
