#pragma once
// File ▸ Import Long Recording…: a long recording of one speaker and its transcript into the open
// project as utterance sequences (render/LongRecordingImport, as `lipsync project import-long`).
// The work runs through the TaskRunner, with progress and cancel, with the aligner the Speech menu
// chose and the project's pronunciations (as the timeline's alignment), on a copy of what it needs
// (the project's folder and its sequence ids). The GUI thread then adds the sequences as one undo
// step (ProjectDocument::requestAddSequences). A cancel or a failure adds nothing and leaves no
// clip behind; opening another project cancels the import.
#include "project/UtteranceSplit.h"
#include "tasks/Task.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

class QAction;
class QWidget;

namespace lipsync::studio {

class ImportLongRecordingDialog;
class StudioContext;

class LongRecordingImporter : public QObject
{
    Q_OBJECT
public:
    // `saveProject` saves the document (Save As for the read-only demo; true once saved): the clips
    // are written into a project folder of the user's. `window` parents the dialog and messages.
    LongRecordingImporter(StudioContext *context, std::function<bool()> saveProject, QWidget *window);

    QAction *action() const { return m_action; }
    bool isImporting() const;
    // Starts importing `recordingPath` with the words of `transcriptPath` into the open project,
    // cut into utterances as `split` says (its frameRate is the recording's own); returns the
    // task, or null (the reason reported) when none started: no writable project, or an import
    // still running.
    Task *start(const QString &recordingPath, const QString &transcriptPath, const UtteranceSplitOptions &split = {});

public slots:
    // The action: a read-only project is saved first (asked), then the dialog, then start().
    void importWithDialog();

signals:
    // The dialog is open, before it runs (tests fill it in).
    void dialogOpened(lipsync::studio::ImportLongRecordingDialog *dialog);
    // An import started (tests wait for it).
    void importStarted(lipsync::Task *task);
    // An import's sequences were added to the document as rows [first, first + count).
    void imported(int first, int count);

private:
    void updateAction();

    StudioContext *m_context;
    std::function<bool()> m_saveProject;
    QWidget *m_window;
    QAction *m_action;
    QPointer<Task> m_task; // the latest import
};

} // namespace lipsync::studio
