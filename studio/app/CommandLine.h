#pragma once
// lipsync-studio's command line:
//   lipsync-studio [PROJECT] [--project DIR] [--lang LANG] [--screenshot FILE.png] [--size WxH]
#include <QCoreApplication>
#include <QSize>
#include <QString>

namespace lipsync::studio {

struct CommandLine
{
    Q_DECLARE_TR_FUNCTIONS(CommandLine)

public:
    QString project;    // empty: the bundled demo
    QString language;   // empty: the system's
    QString screenshot; // empty: interactive
    QSize windowSize;   // --size WxH; invalid: the saved geometry (1280 x 800 for a screenshot)

    // Parses the application's arguments; exits for --help, --version and errors.
    static CommandLine parse(const QCoreApplication &app);
    // The arguments ask only for --help or --version: main answers them with a QCoreApplication,
    // before any display is needed.
    static bool asksForInformation(int argc, char *argv[]);
};

} // namespace lipsync::studio
