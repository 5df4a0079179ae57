#pragma once
// File ▸ Export: the current sequence's generated face as MP4 (H.264 + its sound as AAC), real and
// generated side by side, or PNG frames; and its features (CSV), alignment (TextGrid) and landmarks
// (.pts), and the project's AAM and trained dynamic model; its mouth as animation data (Rhubarb
// mouth cues, ARKit-named controls: core/animation), and the Mouth Shapes those cues are made of.
//
// Every entry asks for a path (a QFileDialog, or the prompt a test installs), then runs in the
// background through the TaskRunner with progress and cancel. Every writer is atomic
// (core/io/AtomicFile, VideoExporter, ImageSequenceExporter), so a cancel or an error leaves no
// half-written file under the chosen name.
#include "tasks/TaskRunner.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <functional>

class QAction;
class QMenu;
class QWidget;

namespace lipsync {
struct Sequence;
class Task;
}

namespace lipsync::studio {

class MouthShapesDialog;
class StudioContext;

class ExportMenu : public QObject
{
    Q_OBJECT
public:
    enum class Kind { Video, SideBySide, Images, Features, Alignment, Landmarks, Aam, Model, MouthCues, Controls };
    Q_ENUM(Kind)

    // What the path prompt is asked for: a file (with a name filter) or a folder.
    struct PathRequest
    {
        Kind kind;
        QString title;
        QString suggestedPath;
        QString filter; // empty: a folder
    };
    // Returns the chosen path, or an empty string to cancel.
    using PathPrompt = std::function<QString(const PathRequest &)>;
    // Which trained dynamic model to export or render with, when the project has several:
    // `kinds` ("dpds", ...) with their user-visible `names`; returns a kind, or empty to cancel.
    using ModelPrompt = std::function<QString(const QStringList &kinds, const QStringList &names)>;

    // Adds File ▸ Export to `parentMenu`; its dialogs and messages open over `dialogParent`.
    ExportMenu(StudioContext *context, QMenu *parentMenu, QWidget *dialogParent);

    QMenu *menu() const { return m_menu; }
    QAction *action(Kind kind) const;
    // Whether the context holds what `kind` writes (the command's validate()).
    bool canExport(Kind kind) const;
    // File ▸ Export ▸ Mouth Shapes…: opens the MouthShapesDialog.
    QAction *mouthShapesAction() const { return m_mouthShapesAction; }
    // The dialog, once opened (null before).
    MouthShapesDialog *mouthShapesDialog() const;
    // `path` with the extension of the file dialog's chosen `filter` ("Moho switch data (*.dat)")
    // when the name typed has none: the format follows the extension.
    static QString withFilterSuffix(const QString &path, const QString &filter);
    // Replaces the file dialogs (GUI tests).
    void setPathPrompt(PathPrompt prompt) { m_prompt = std::move(prompt); }
    void setModelPrompt(ModelPrompt prompt) { m_modelPrompt = std::move(prompt); }

    // Asks which model (when it matters and there is a choice) and for a path, then starts the
    // export; returns the task (null if nothing was started). Where it wrote is shown in the
    // status bar when it is done.
    Task *trigger(Kind kind);
    // Starts the export to `path` without asking. `modelKind` is the dynamic model to use
    // (empty: the paper's DPDS when trained, else the first trained). Null (and the reason
    // reported) when the project lacks what the export needs (a sequence, features, an
    // alignment, a model).
    Task *exportTo(Kind kind, const QString &path, const QString &modelKind = {});

signals:
    // A file or folder was written completely.
    void exported(const QString &path);

private:
    // An export's task: its title and work; no work when it was refused (and the reason shown).
    struct Job
    {
        QString title;
        TaskRunner::Work work;
    };
    Job videoJob(Kind kind, const QString &path, const Sequence &sequence, const QString &modelKind);
    Job sequenceDataJob(Kind kind, const QString &path, const Sequence &sequence);
    Job modelJob(Kind kind, const QString &path, const QString &modelKind);
    Job animationJob(Kind kind, const QString &path, const Sequence &sequence);
    void showMouthShapes();
    void updateActions();

    StudioContext *m_context;
    QWidget *m_dialogParent;
    QMenu *m_menu;
    QList<QAction *> m_actions; // in Kind order
    QAction *m_mouthShapesAction = nullptr;
    QPointer<MouthShapesDialog> m_shapesDialog;
    PathPrompt m_prompt;
    ModelPrompt m_modelPrompt;
};

} // namespace lipsync::studio
