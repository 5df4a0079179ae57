#pragma once
// The arguments of one command, parsed by QCommandLineParser from the command's declaration
// (CommandSpec, Command.h): typed access to its options and positional arguments. Everything a
// command reads here was declared, so a misspelt name is a programming error (Q_ASSERT).
#include "Command.h"

#include <QCommandLineParser>

#include <limits>
#include <stdexcept>

namespace lipsync::cli {

// Bad usage of a command (exit 2): the message names the option or argument at fault.
class UsageError : public std::runtime_error
{
public:
    explicit UsageError(const QString &message) : std::runtime_error(message.toStdString()) {}
    QString message() const { return QString::fromStdString(what()); }
};

class CommandLine
{
public:
    // Parses `args` (after the command's name). Throws UsageError for an unknown option, a missing
    // value, a missing required option or positional argument and a surplus positional argument;
    // not when --help is given (helpRequested()).
    CommandLine(const CommandSpec &spec, const QStringList &args);

    bool helpRequested() const { return m_help; }
    // "usage: lipsync NAME ...", the description, the arguments and every option with its
    // default; wrapped for a terminal.
    static QString helpText(const CommandSpec &spec);

    const CommandSpec &spec() const { return m_spec; }
    // --name (or one of its aliases) was given.
    bool isSet(const QString &name) const;
    // The option's value: the last one given, else its default.
    QString value(const QString &name) const;
    // The value as an integer in [min, max]; UsageError naming the option otherwise.
    int integer(const QString &name, int min = std::numeric_limits<int>::min(),
                int max = std::numeric_limits<int>::max()) const;
    quint64 unsignedInteger(const QString &name) const;
    // The value as a finite number; UsageError naming the option otherwise.
    double number(const QString &name) const;
    // The value as a finite number > 0.
    double positiveNumber(const QString &name) const;
    // A comma-separated list, items trimmed, empty items dropped.
    QStringList list(const QString &name) const;

    QStringList positional() const { return m_positional; }
    QString positional(int index) const { return m_positional.value(index); }

private:
    void check(const QString &name) const;

    CommandSpec m_spec;
    QCommandLineParser m_parser;
    QStringList m_positional;
    bool m_help = false;
};

} // namespace lipsync::cli
