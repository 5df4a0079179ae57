#include "app/CommandLine.h"

#include <QCommandLineParser>

#include <cstdio>
#include <cstdlib>
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
    const QCommandLineOption sizeOption(QStringLiteral("size"), tr("Window size, e.g. 1920x1080."),
                                        QStringLiteral("WxH"));
    parser.addOptions({projectOption, langOption, screenshotOption, sizeOption});
    parser.addPositionalArgument(QStringLiteral("project"), tr("Project folder (or its project.json)."),
                                 QStringLiteral("[PROJECT]"));
    parser.process(app);

    CommandLine result;
    result.project = parser.value(projectOption);
    if (result.project.isEmpty() && !parser.positionalArguments().isEmpty())
        result.project = parser.positionalArguments().constFirst();
    result.language = parser.value(langOption);
    result.screenshot = parser.value(screenshotOption);
    if (parser.isSet(sizeOption)) {
        const QStringList wh = parser.value(sizeOption).split(QLatin1Char('x'));
        const int w = wh.value(0).toInt(), h = wh.size() == 2 ? wh.value(1).toInt() : 0;
        if (w < 320 || h < 240) {
            std::fprintf(stderr, "%s\n", qPrintable(tr("--size takes WIDTHxHEIGHT, at least 320x240, e.g. 1920x1080")));
            std::exit(2);
        }
        result.windowSize = QSize(w, h);
    }
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
