#include "Command.h"

#include <QJsonDocument>

#include <cstdio>

namespace lipsync::cli {

std::map<QString, CommandInfo> &commandRegistry()
{
    static std::map<QString, CommandInfo> registry;
    return registry;
}

CommandRegistration::CommandRegistration(const QString &name, const QString &summary,
                                         CommandFunction run)
{
    commandRegistry()[name] = CommandInfo{name, summary, std::move(run)};
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

QStringList Arguments::defaultBooleanFlags()
{
    return {QStringLiteral("json"), QStringLiteral("force"), QStringLiteral("help"),
            QStringLiteral("side-by-side"), QStringLiteral("verbose"), QStringLiteral("quiet")};
}

Arguments::Arguments(const QStringList &args, const QStringList &booleanFlags)
{
    for (int i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        if (a.startsWith(QLatin1String("--")) && a.size() > 2) {
            const int eq = a.indexOf(QLatin1Char('='));
            if (eq > 0) {
                m_options[a.mid(2, eq - 2)] = a.mid(eq + 1);
            } else if (!booleanFlags.contains(a.mid(2)) && i + 1 < args.size()
                       && !args[i + 1].startsWith(QLatin1String("--"))) {
                m_options[a.mid(2)] = args[i + 1];
                ++i;
            } else {
                m_options[a.mid(2)] = QString();
            }
        } else {
            m_positional << a;
        }
    }
}

bool Arguments::flag(const QString &name) const
{
    return m_options.count(name) > 0;
}

bool Arguments::has(const QString &name) const
{
    return m_options.count(name) > 0;
}

QString Arguments::value(const QString &name, const QString &fallback) const
{
    auto it = m_options.find(name);
    return it == m_options.end() || it->second.isEmpty() ? fallback : it->second;
}

QStringList Arguments::unknown(const QStringList &known) const
{
    QStringList out;
    for (const auto &[name, value] : m_options)
        if (!known.contains(name))
            out << QStringLiteral("--") + name;
    return out;
}

} // namespace lipsync::cli
