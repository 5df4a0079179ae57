#include "context/StudioActions.h"

#include <QAction>
#include <QStyle>
#include <QUndoStack>
#include <QWidget>

namespace lipsync::studio {

namespace {

QAction *make(QWidget *owner, const QString &text, const QList<QKeySequence> &keys,
              QStyle::StandardPixmap icon = QStyle::SP_CustomBase)
{
    auto *a = new QAction(text, owner);
    a->setShortcuts(keys);
    // Window-wide, so the keys work whichever dock has focus.
    a->setShortcutContext(Qt::WindowShortcut);
    if (icon != QStyle::SP_CustomBase)
        a->setIcon(owner->style()->standardIcon(icon));
    if (!keys.isEmpty())
        a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')).remove(QStringLiteral("…")),
                                                    keys.first().toString(QKeySequence::NativeText)));
    owner->addAction(a);
    return a;
}

} // namespace

StudioActions::StudioActions(QWidget *owner, QUndoStack *undoStack)
{
    newProject = make(owner, tr("&New Project…"), {QKeySequence::New}, QStyle::SP_FileDialogNewFolder);
    open = make(owner, tr("&Open Project…"), {QKeySequence::Open}, QStyle::SP_DialogOpenButton);
    openDemo = make(owner, tr("Open &Demo Project"), {});
    save = make(owner, tr("&Save"), {QKeySequence::Save}, QStyle::SP_DialogSaveButton);
    saveAs = make(owner, tr("Save &As…"), {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)});
    quit = make(owner, tr("&Quit"), {QKeySequence::Quit});

    undo = undoStack->createUndoAction(owner, tr("&Undo"));
    undo->setShortcuts({QKeySequence::Undo});
    undo->setIcon(owner->style()->standardIcon(QStyle::SP_ArrowBack));
    redo = undoStack->createRedoAction(owner, tr("&Redo"));
    redo->setShortcuts({QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    redo->setIcon(owner->style()->standardIcon(QStyle::SP_ArrowForward));
    owner->addAction(undo);
    owner->addAction(redo);

    previousFrame = make(owner, tr("Previous Frame"), {Qt::Key_Left}, QStyle::SP_MediaSeekBackward);
    nextFrame = make(owner, tr("Next Frame"), {Qt::Key_Right}, QStyle::SP_MediaSeekForward);
    firstFrame = make(owner, tr("First Frame"), {Qt::Key_Home}, QStyle::SP_MediaSkipBackward);
    lastFrame = make(owner, tr("Last Frame"), {Qt::Key_End}, QStyle::SP_MediaSkipForward);
    playPause = make(owner, tr("Play/Pause"), {Qt::Key_Space}, QStyle::SP_MediaPlay);
    previousSequence = make(owner, tr("Previous Sequence"), {Qt::Key_PageUp}, QStyle::SP_ArrowUp);
    nextSequence = make(owner, tr("Next Sequence"), {Qt::Key_PageDown}, QStyle::SP_ArrowDown);
    fitFrame = make(owner, tr("Fit Frame to View"), {QKeySequence(Qt::CTRL | Qt::Key_0)});
    about = make(owner, tr("&About LipSync Studio"), {});
}

} // namespace lipsync::studio
