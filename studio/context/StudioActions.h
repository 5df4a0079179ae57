#pragma once
// Every menu/toolbar/shortcut action of the main window in one place, so the keyboard map can
// be read (and translated) at a glance. MainWindow connects them.
#include <QCoreApplication>

class QAction;
class QUndoStack;
class QWidget;

namespace lipsync::studio {

struct StudioActions
{
    Q_DECLARE_TR_FUNCTIONS(StudioActions)

public:
    StudioActions(QWidget *owner, QUndoStack *undoStack);

    // File
    QAction *newProject;
    QAction *open;
    QAction *openDemo;
    QAction *save;
    QAction *saveAs;
    QAction *quit;
    // Edit
    QAction *undo;
    QAction *redo;
    // Navigation and playback
    QAction *previousFrame;
    QAction *nextFrame;
    QAction *firstFrame;
    QAction *lastFrame;
    QAction *playPause;
    QAction *previousSequence;
    QAction *nextSequence;
    QAction *fitFrame;
    // Help
    QAction *about;
};

} // namespace lipsync::studio
