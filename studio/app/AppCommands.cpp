#include "app/AppCommands.h"

#include "annotate/FrameView.h"
#include "app/AboutBox.h"
#include "app/ProjectFiles.h"
#include "context/CommandRegistry.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include <QMainWindow>

namespace lipsync::studio {

namespace {

bool documentOpen(const StudioContext &c)
{
    return c.document()->isOpen();
}

} // namespace

void AppCommands::add(CommandRegistry &registry, ProjectFiles *files, FrameView *frameView, QMainWindow *window)
{
    registry.add({QStringLiteral("file/new"), tr("&New Project…"), {QKeySequence::New}, QStyle::SP_FileDialogNewFolder,
                  nullptr, [files](StudioContext &) { files->newProjectWithDialog(); }},
                 window);
    registry.add({QStringLiteral("file/open"), tr("&Open Project…"), {QKeySequence::Open}, QStyle::SP_DialogOpenButton,
                  nullptr, [files](StudioContext &) { files->openWithDialog(); }},
                 window);
    registry.add({QStringLiteral("file/open-demo"), tr("Open &Demo Project"), {}, QStyle::SP_CustomBase, nullptr,
                  [files](StudioContext &) {
                      if (files->maybeSave())
                          files->openDemo();
                  }},
                 window);
    registry.add({QStringLiteral("file/save"), tr("&Save"), {QKeySequence::Save}, QStyle::SP_DialogSaveButton,
                  documentOpen, [files](StudioContext &) { files->save(); }},
                 window);
    registry.add({QStringLiteral("file/save-as"), tr("Save &As…"), {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)},
                  QStyle::SP_CustomBase, documentOpen, [files](StudioContext &) { files->saveAs(); }},
                 window);
    registry.add({QStringLiteral("app/quit"), tr("&Quit"), {QKeySequence::Quit}, QStyle::SP_CustomBase, nullptr,
                  [window](StudioContext &) { window->close(); }},
                 window);
    registry.add({QStringLiteral("view/fit-frame"), tr("Fit Frame to View"), {QKeySequence(Qt::CTRL | Qt::Key_0)},
                  QStyle::SP_CustomBase,
                  [](const StudioContext &c) { return c.media() && c.media()->frameCount() > 0; },
                  [frameView](StudioContext &) { frameView->fitToView(); }},
                 window);
    registry.add({QStringLiteral("help/about"), tr("&About LipSync Studio"), {}, QStyle::SP_CustomBase, nullptr,
                  [window](StudioContext &) { AboutBox::show(window); }},
                 window);
}

} // namespace lipsync::studio
