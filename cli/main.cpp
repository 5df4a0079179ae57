// lipsync: the headless tool. Every long job of the studio runs here without a display.
#include "Command.h"

#include <QCoreApplication>

#include <cstdio>

using namespace lipsync::cli;

static void printUsage()
{
    std::printf("usage: lipsync COMMAND [ARGS...] [--json]\n"
                "       lipsync COMMAND --help   (the command's arguments and options)\n\ncommands:\n");
    // Two spaces at least between a command's name and its summary (tests read the list).
    for (const auto &[name, info] : commandRegistry())
        std::printf("  %-18s  %s\n", name.toLocal8Bit().constData(),
                    info.spec.summary.toLocal8Bit().constData());
}

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("lipsync"));
    QCoreApplication::setApplicationVersion(QStringLiteral(LIPSYNC_VERSION));
    const QStringList args = app.arguments().mid(1);
    if (args.isEmpty() || args[0] == QLatin1String("--help") || args[0] == QLatin1String("-h")) {
        printUsage();
        return args.isEmpty() ? 2 : 0;
    }
    if (args[0] == QLatin1String("--version")) {
        std::printf("lipsync %s\n", LIPSYNC_VERSION);
        return 0;
    }
    // Longest matching command name: "aam build" before "aam".
    const CommandInfo *best = nullptr;
    int bestWords = 0;
    for (const auto &[name, info] : commandRegistry()) {
        const QStringList words = name.split(QLatin1Char(' '));
        if (words.size() <= args.size() && args.mid(0, words.size()) == words
            && words.size() > bestWords) {
            best = &info;
            bestWords = int(words.size());
        }
    }
    if (!best) {
        printUsage();
        return fail(QStringLiteral("unknown command '%1'").arg(args[0]), 2);
    }
    try {
        return runCommand(*best, args.mid(bestWords));
    } catch (const std::exception &e) {
        return fail(QString::fromUtf8(e.what()));
    }
}
