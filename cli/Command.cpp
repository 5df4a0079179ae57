#include "Command.h"

#include "CommandLine.h"

#include <QJsonDocument>

#include <cstdio>

namespace lipsync::cli {

std::map<QString, CommandInfo> &commandRegistry()
{
    static std::map<QString, CommandInfo> registry;
    return registry;
}

CommandRegistration::CommandRegistration(CommandSpec spec, CommandFunction run)
{
    const QString name = spec.name;
    commandRegistry()[name] = CommandInfo{std::move(spec), std::move(run)};
}

int runCommand(const CommandInfo &command, const QStringList &args)
{
    try {
        const CommandLine line(command.spec, args);
        if (line.helpRequested()) {
            const QByteArray text = CommandLine::helpText(command.spec).toLocal8Bit();
            std::fwrite(text.constData(), 1, size_t(text.size()), stdout);
            return 0;
        }
        return command.run(line);
    } catch (const UsageError &e) {
        return fail(QStringLiteral("%1: %2 (usage: lipsync %1 --help)").arg(command.spec.name, e.message()), 2);
    }
}

void printJson(const QJsonObject &object)
{
    const QByteArray text = QJsonDocument(object).toJson(QJsonDocument::Indented);
    std::fwrite(text.constData(), 1, size_t(text.size()), stdout);
    std::fflush(stdout);
}

int fail(const QString &message, int exitCode)
{
    // One line: a newline inside the message would break scripts that read the first line.
    QString line = message;
    line.replace(QLatin1Char('\n'), QLatin1String("; "));
    std::fprintf(stderr, "lipsync: %s\n", line.toLocal8Bit().constData());
    return exitCode;
}

} // namespace lipsync::cli
