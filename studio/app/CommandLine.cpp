#include "app/CommandLine.h"

#include <QCommandLineParser>

#include <cstring>

namespace lipsync::studio {

CommandLine CommandLine::parse(const QCoreApplication &app)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(tr("LipSync Studio: realistic lip movement from speech."));
    parser.addHelpOption();
    parser.addVersionOption();
    const QCommandLineOption projectOption(QStringLiteral("project"), tr("Open the project in DIR."),
                                           QStringLiteral("DIR"));
    const QCommandLineOption langOption(QStringLiteral("lang"),
                                        tr("User interface language (en, de); default: the system's."),
                                        QStringLiteral("LANG"));
    const QCommandLineOption screenshotOption(
        QStringLiteral("screenshot"), tr("Render the main window into FILE (PNG) once the project has loaded, then exit."),
        QStringLiteral("FILE"));
    parser.addOptions({projectOption, langOption, screenshotOption});
    parser.addPositionalArgument(QStringLiteral("project"), tr("Project folder (or its project.json)."),
                                 QStringLiteral("[PROJECT]"));
    parser.process(app);

    CommandLine result;
    result.project = parser.value(projectOption);
    if (result.project.isEmpty() && !parser.positionalArguments().isEmpty())
        result.project = parser.positionalArguments().constFirst();
    result.language = parser.value(langOption);
    result.screenshot = parser.value(screenshotOption);
    return result;
}

bool CommandLine::asksForInformation(int argc, char *argv[])
{
    for (int i = 1; i < argc; ++i)
        for (const char *option : {"-h", "-?", "--help", "--help-all", "-v", "--version"})
            if (std::strcmp(argv[i], option) == 0)
                return true;
    return false;
}

} // namespace lipsync::studio
