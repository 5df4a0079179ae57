// lipsync-studio: the desktop studio.
//   lipsync-studio [PROJECT] [--project DIR] [--lang de] [--screenshot FILE.png]
// Without a project it opens the bundled demo (see DemoProject.h for where it is looked up).
#include "app/AppIcon.h"
#include "app/CommandLine.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "app/RecentProjects.h"
#include "app/ScreenshotRunner.h"
#include "app/SurfaceFormat.h"
#include "app/Translations.h"
#include "context/ErrorReporter.h"

#include <QApplication>
#include <QStyleFactory>

using namespace lipsync::studio;

namespace {

void nameApplication()
{
    QCoreApplication::setOrganizationName(QStringLiteral("lipsync"));
    QCoreApplication::setApplicationName(QStringLiteral("LipSync Studio"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LIPSYNC_VERSION));
}

} // namespace

int main(int argc, char *argv[])
{
    if (CommandLine::asksForInformation(argc, argv)) {
        // --help and --version need no display: answered (and exited) by the parser.
        QCoreApplication core(argc, argv);
        nameApplication();
        Translations::install();
        CommandLine::parse(core);
        return 0;
    }
    setDefaultSurfaceFormat(); // VTK needs it before QApplication exists
    QApplication app(argc, argv);
    nameApplication();
    QApplication::setStyle(QStyleFactory::create(QStringLiteral("Fusion")));
    QApplication::setWindowIcon(appIcon());

    // The system's language first, so --help is translated too; --lang replaces it.
    Translations::install();
    const CommandLine options = CommandLine::parse(app);
    if (!options.language.isEmpty())
        Translations::install(options.language);

    const bool batch = !options.screenshot.isEmpty();
    ErrorReporter::setBatchMode(batch);
    MainWindow window;
    if (options.windowSize.isValid() || batch) {
        window.resize(options.windowSize.isValid() ? options.windowSize : QSize(1280, 800)); // not the saved geometry
        window.show();
    } else {
        window.showAsLastTime();
    }

    // The project named, else the one the last session had open, else the bundled demo.
    const QString project = !options.project.isEmpty() ? options.project
                            : batch                    ? QString()
                                                       : RecentProjects::lastSession();
    // A last project that no longer opens (moved, damaged) is reported, and the demo opens instead.
    if (project.isEmpty() || (!window.files()->open(project) && options.project.isEmpty()))
        window.files()->openDemo();
    if (batch)
        (new ScreenshotRunner(&window, options.screenshot))->start();
    return app.exec();
}
