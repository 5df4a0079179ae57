#pragma once
// The application's own commands, registered beside the context's (StudioActions): the project
// files (New, Open, Open Demo, Save, Save As, Quit), fitting the frame to the annotator's view and
// About. They act through ProjectFiles and the window; like every command, each validates itself.
#include <QCoreApplication>

class QMainWindow;

namespace lipsync::studio {

class CommandRegistry;
class FrameView;
class ProjectFiles;

struct AppCommands
{
    Q_DECLARE_TR_FUNCTIONS(AppCommands)

public:
    static void add(CommandRegistry &registry, ProjectFiles *files, FrameView *frameView, QMainWindow *window);
};

} // namespace lipsync::studio
