// lipsync: the headless tool. Every long job of the studio runs here without a display.
#include "Command.h"

#include <QCoreApplication>

#include <cstdio>

using namespace lipsync::cli;

// The commands of group `group` ("project": "project create", "project check", ...), or none.
static QStringList groupCommands(const QString &group)
{
    QStringList names;
    for (const auto &[name, info] : commandRegistry())
        if (name.startsWith(group + QLatin1Char(' ')))
            names << name;
    return names;
}

static void printGroupUsage(const QString &group)
{
    std::printf("usage: lipsync %s COMMAND [ARGS...] [--json]\n"
                "       lipsync %s COMMAND --help\n\ncommands:\n",
                group.toLocal8Bit().constData(), group.toLocal8Bit().constData());
    for (const auto &[name, info] : commandRegistry())
        if (name.startsWith(group + QLatin1Char(' ')))
            std::printf("  %-18s  %s\n", name.toLocal8Bit().constData(), info.spec.summary.toLocal8Bit().constData());
}

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
        // A group of commands ("lipsync project", "lipsync aligner --help"): its commands.
        if (!groupCommands(args[0]).isEmpty()) {
            const bool help = args.size() >= 2 && (args[1] == QLatin1String("--help") || args[1] == QLatin1String("-h"));
            printGroupUsage(args[0]);
            if (help)
                return 0;
            return args.size() == 1 ? 2
                                    : fail(QStringLiteral("unknown command '%1 %2'").arg(args[0], args[1]), 2);
        }
        printUsage();
        return fail(QStringLiteral("unknown command '%1'").arg(args[0]), 2);
    }
    try {
        return runCommand(*best, args.mid(bestWords));
    } catch (const std::exception &e) {
        return fail(QString::fromUtf8(e.what()));
    }
}
