#pragma once
// Subcommand registry of the `lipsync` CLI. A command file registers itself with
//   static const CommandRegistration registration{"aam build", "summary", &runAamBuild};
// A command gets the arguments after its name and returns the process exit code.
// Conventions: --json prints one JSON object on stdout; errors print one line on stderr and
// return 1 (bad input) or 2 (bad usage).
#include <QJsonObject>
#include <QStringList>

#include <functional>
#include <map>
#include <string>

namespace lipsync::cli {

using CommandFunction = std::function<int(const QStringList &args)>;

struct CommandInfo
{
    QString name; // one or more words: "info", "aam build"
    QString summary;
    CommandFunction run;
};

std::map<QString, CommandInfo> &commandRegistry();

struct CommandRegistration
{
    CommandRegistration(const QString &name, const QString &summary, CommandFunction run);
};

// Prints a JSON object (indented) on stdout.
void printJson(const QJsonObject &object);
// Prints "lipsync: <message>" on stderr and returns the exit code.
int fail(const QString &message, int exitCode = 1);

// Minimal option parsing shared by commands: --name value, --name=value, --flag, positionals.
// Options named in `booleanFlags` never take a value, so "--json DIR" keeps DIR positional.
class Arguments
{
public:
    static QStringList defaultBooleanFlags();
    explicit Arguments(const QStringList &args,
                       const QStringList &booleanFlags = defaultBooleanFlags());
    bool flag(const QString &name) const;                // --name present
    QString value(const QString &name, const QString &fallback = {}) const; // --name VALUE
    bool has(const QString &name) const;
    QStringList positional() const { return m_positional; }
    // Names of options given that are not in `known` (to reject typos).
    QStringList unknown(const QStringList &known) const;

private:
    QStringList m_positional;
    std::map<QString, QString> m_options; // flags map to ""
};

} // namespace lipsync::cli
