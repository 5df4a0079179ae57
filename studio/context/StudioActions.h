#pragma once
// The commands of the studio that act on the context alone — moving through frames and
// sequences, playing — registered in the context's CommandRegistry (which the application, the
// export menu and the panels add their own to), with the undo stack's Undo and Redo. Their keys
// are shortcuts of `owner`, the window. Menus, toolbars and the transport show these actions;
// each is enabled when its command validates.
#include "context/CommandRegistry.h"

#include <QCoreApplication>

class QAction;
class QWidget;

namespace lipsync::studio {

class StudioContext;

struct StudioActions
{
    Q_DECLARE_TR_FUNCTIONS(StudioActions)

public:
    StudioActions(QWidget *owner, StudioContext *context);

    CommandRegistry *registry; // the context's
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
};

} // namespace lipsync::studio
