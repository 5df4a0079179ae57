#pragma once
// Subcommand registry of the `lipsync` CLI. A command file declares its options once and registers
// itself:
//   static const CommandRegistration registration{
//       {"aam build", "summary", "description", {{"images", "DIR", "...", {}, CommandOption::Required}}, {}},
//       &runAamBuild};
// The shared parser (CommandLine) reads the arguments after the command's name from that
// declaration: --help/-h print the command's usage, unknown options and missing values are usage
// errors, --json and --help are added to every command. The command gets the parsed arguments and
// returns the process exit code.
// Conventions: --json prints one JSON object on stdout; errors print one line on stderr and
// return 1 (bad input) or 2 (bad usage: UsageError, thrown anywhere in a command).
#include <QJsonObject>
#include <QStringList>

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace lipsync::cli {

class CommandLine;

// One option of a command: --name VALUE, or a flag when valueName is empty.
struct CommandOption
{
    enum Presence { Optional, Required };

    CommandOption(QString name, QString valueName, QString description, QString defaultValue = {},
                  Presence presence = Optional, QStringList aliases = {})
        : name(std::move(name)), valueName(std::move(valueName)), description(std::move(description)),
          defaultValue(std::move(defaultValue)), presence(presence), aliases(std::move(aliases))
    {
    }

    QString name;          // without dashes: "aligner"
    QString valueName;     // "MODEL"; empty: a flag without a value
    QString description;   // one sentence or more, wrapped by the help
    QString defaultValue;  // what value() returns when the option is not given ("" = none)
    Presence presence = Optional;
    QStringList aliases;   // other spellings accepted, not shown in the help
};

// One positional argument, in order.
struct CommandArgument
{
    CommandArgument(QString name, QString description, bool optional = false)
        : name(std::move(name)), description(std::move(description)), optional(optional)
    {
    }

    QString name;        // "MEDIA"
    QString description;
    bool optional = false;
};

struct CommandSpec
{
    QString name;        // one or more words: "info", "aam build"
    QString summary;     // one line for `lipsync --help`
    QString description; // paragraphs for `lipsync NAME --help`
    std::vector<CommandOption> options;
    std::vector<CommandArgument> arguments;

    // Appends options shared with other commands (SpeechAligner::options(), ...).
    CommandSpec &add(const std::vector<CommandOption> &shared)
    {
        options.insert(options.end(), shared.begin(), shared.end());
        return *this;
    }
};

using CommandFunction = std::function<int(const CommandLine &args)>;

struct CommandInfo
{
    CommandSpec spec;
    CommandFunction run;
};

std::map<QString, CommandInfo> &commandRegistry();

struct CommandRegistration
{
    CommandRegistration(CommandSpec spec, CommandFunction run);
};

// Parses `args` (the words after the command's name) by the command's spec and runs it: --help
// prints its usage (exit 0), a usage error one line (exit 2), lipsync::Error one line (exit 1).
int runCommand(const CommandInfo &command, const QStringList &args);

// Prints a JSON object (indented) on stdout.
void printJson(const QJsonObject &object);
// Prints "lipsync: <message>" on stderr and returns the exit code.
int fail(const QString &message, int exitCode = 1);

} // namespace lipsync::cli
