#include "context/StudioActions.h"

#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include <QAction>
#include <QStyle>
#include <QUndoStack>
#include <QWidget>

namespace lipsync::studio {

namespace {

int shownFrames(const StudioContext &c)
{
    return c.media() ? c.media()->frameCount() : 0;
}

} // namespace

StudioActions::StudioActions(QWidget *owner, StudioContext *context)
    : registry(context->commands())
{
    registry->setShortcutWidget(owner);
    undo = context->undoStack()->createUndoAction(owner, tr("&Undo"));
    undo->setShortcuts({QKeySequence::Undo});
    undo->setIcon(owner->style()->standardIcon(QStyle::SP_ArrowBack));
    redo = context->undoStack()->createRedoAction(owner, tr("&Redo"));
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redo->setIcon(owner->style()->standardIcon(QStyle::SP_ArrowForward));
    owner->addAction(undo);
    owner->addAction(redo);

    previousFrame = registry->add({QStringLiteral("frame/previous"), tr("Previous Frame"), {Qt::Key_Left},
                                   QStyle::SP_MediaSeekBackward,
                                   [](const StudioContext &c) { return shownFrames(c) > 0 && c.currentFrame() > 0; },
                                   [](StudioContext &c) { c.setCurrentFrame(c.currentFrame() - 1); }, true});
    nextFrame = registry->add({QStringLiteral("frame/next"), tr("Next Frame"), {Qt::Key_Right},
                               QStyle::SP_MediaSeekForward,
                               [](const StudioContext &c) { return c.currentFrame() + 1 < shownFrames(c); },
                               [](StudioContext &c) { c.setCurrentFrame(c.currentFrame() + 1); }, true});
    firstFrame = registry->add({QStringLiteral("frame/first"), tr("First Frame"), {Qt::Key_Home},
                                QStyle::SP_MediaSkipBackward, [](const StudioContext &c) { return shownFrames(c) > 0; },
                                [](StudioContext &c) { c.setCurrentFrame(0); }});
    lastFrame = registry->add({QStringLiteral("frame/last"), tr("Last Frame"), {Qt::Key_End},
                               QStyle::SP_MediaSkipForward, [](const StudioContext &c) { return shownFrames(c) > 0; },
                               [](StudioContext &c) { c.setCurrentFrame(shownFrames(c) - 1); }});
    playPause = registry->add({QStringLiteral("playback/toggle"), tr("Play/Pause"), {Qt::Key_Space},
                               QStyle::SP_MediaPlay, [](const StudioContext &c) { return c.media() != nullptr; },
                               [](StudioContext &c) { c.togglePlayback(); }});
    // From the sequence asked for last, so that repeated presses step on while one still loads.
    previousSequence = registry->add({QStringLiteral("sequence/previous"), tr("Previous Sequence"), {Qt::Key_PageUp},
                                      QStyle::SP_ArrowUp,
                                      [](const StudioContext &c) { return c.requestedSequence() > 0; },
                                      [](StudioContext &c) { c.selectSequence(c.requestedSequence() - 1); }});
    nextSequence = registry->add({QStringLiteral("sequence/next"), tr("Next Sequence"), {Qt::Key_PageDown},
                                  QStyle::SP_ArrowDown,
                                  [](const StudioContext &c) {
                                      return c.requestedSequence() + 1 < c.document()->sequenceCount();
                                  },
                                  [](StudioContext &c) { c.selectSequence(c.requestedSequence() + 1); }});
}

} // namespace lipsync::studio
