#include "CommandLine.h"

#include <algorithm>
#include <cmath>

namespace lipsync::cli {

namespace {

constexpr int kHelpWidth = 100;  // columns the help is wrapped to
constexpr int kSyntaxColumn = 30; // an option's description starts here (or on the next line)

// --json and --help: every command has them.
const CommandOption &jsonOption()
{
    static const CommandOption option{QStringLiteral("json"), {},
                                      QStringLiteral("print the result as one JSON object on stdout"), {}};
    return option;
}

const CommandOption &helpOption()
{
    static const CommandOption option{QStringLiteral("help"), {}, QStringLiteral("print this help and exit"),
                                      {}, CommandOption::Optional, {QStringLiteral("h")}};
    return option;
}

std::vector<CommandOption> allOptions(const CommandSpec &spec)
{
    std::vector<CommandOption> options = spec.options;
    options.push_back(jsonOption());
    options.push_back(helpOption());
    return options;
}

QString dashed(const QString &name)
{
    return (name.size() == 1 ? QStringLiteral("-") : QStringLiteral("--")) + name;
}

QString optionSyntax(const CommandOption &option)
{
    // A one-letter alias goes first: "-h, --help", "-j, --jobs N".
    QString syntax = dashed(option.name);
    for (const QString &alias : option.aliases)
        if (alias.size() == 1)
            syntax = dashed(alias) + QStringLiteral(", ") + syntax;
    if (!option.valueName.isEmpty())
        syntax += QLatin1Char(' ') + option.valueName;
    return syntax;
}

// `text` wrapped to kHelpWidth, every line after the first indented by `indent` columns; the
// text's own line breaks are kept.
QString wrapped(const QString &text, int firstColumn, int indent)
{
    QString out;
    int column = firstColumn;
    const QStringList lines = text.split(QLatin1Char('\n'));
    for (int l = 0; l < lines.size(); ++l) {
        if (l > 0) {
            out += QLatin1Char('\n') + QString(indent, QLatin1Char(' '));
            column = indent;
        }
        bool lineStart = true;
        for (const QString &word : lines[l].split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
            if (!lineStart && column + 1 + word.size() > kHelpWidth) {
                out += QLatin1Char('\n') + QString(indent, QLatin1Char(' '));
                column = indent;
                lineStart = true;
            }
            if (!lineStart) {
                out += QLatin1Char(' ');
                ++column;
            }
            out += word;
            column += int(word.size());
            lineStart = false;
        }
    }
    return out;
}

// "  SYNTAX   description", the description wrapped beside the syntax or below a long one.
QString helpRow(const QString &syntax, const QString &description)
{
    QString row = QStringLiteral("  ") + syntax;
    if (row.size() + 2 > kSyntaxColumn)
        row += QLatin1Char('\n') + QString(kSyntaxColumn, QLatin1Char(' '));
    else
        row += QString(kSyntaxColumn - int(row.size()), QLatin1Char(' '));
    return row + wrapped(description, kSyntaxColumn, kSyntaxColumn) + QLatin1Char('\n');
}

} // namespace

CommandLine::CommandLine(const CommandSpec &spec, const QStringList &args) : m_spec(spec)
{
    m_parser.setOptionsAfterPositionalArgumentsMode(QCommandLineParser::ParseAsOptions);
    for (const CommandOption &option : allOptions(spec)) {
        QCommandLineOption parserOption(QStringList{option.name} + option.aliases, option.description,
                                        option.valueName);
        if (!option.valueName.isEmpty() && !option.defaultValue.isEmpty())
            parserOption.setDefaultValue(option.defaultValue);
        m_parser.addOption(parserOption);
    }
    // The first word is taken for the program's name.
    const bool parsed = m_parser.parse(QStringList{QStringLiteral("lipsync")} + args);
    m_help = m_parser.isSet(QStringLiteral("help"));
    if (m_help)
        return;
    if (!parsed) {
        const QStringList unknown = m_parser.unknownOptionNames();
        if (!unknown.isEmpty())
            throw UsageError(QStringLiteral("unknown option %1").arg(dashed(unknown.front())));
        // "Missing value after '--out'." and the like.
        QString error = m_parser.errorText();
        if (error.endsWith(QLatin1Char('.')))
            error.chop(1);
        if (!error.isEmpty())
            error[0] = error[0].toLower();
        throw UsageError(error);
    }
    for (const CommandOption &option : spec.options)
        if (option.presence == CommandOption::Required && !m_parser.isSet(option.name))
            throw UsageError(QStringLiteral("missing %1").arg(optionSyntax(option)));
    m_positional = m_parser.positionalArguments();
    int required = 0;
    for (const CommandArgument &argument : spec.arguments)
        if (!argument.optional)
            ++required;
    if (m_positional.size() < required)
        throw UsageError(QStringLiteral("missing %1").arg(spec.arguments[size_t(m_positional.size())].name));
    // A last argument named "NAME..." takes any number of values.
    const bool variadic = !spec.arguments.empty() && spec.arguments.back().name.endsWith(QLatin1String("..."));
    if (!variadic && m_positional.size() > qsizetype(spec.arguments.size()))
        throw UsageError(QStringLiteral("unexpected argument '%1'").arg(m_positional[qsizetype(spec.arguments.size())]));
}

QString CommandLine::helpText(const CommandSpec &spec)
{
    QString usage = QStringLiteral("usage: lipsync ") + spec.name;
    for (const CommandArgument &argument : spec.arguments)
        usage += QLatin1Char(' ') + (argument.optional ? QLatin1Char('[') + argument.name + QLatin1Char(']') : argument.name);
    for (const CommandOption &option : spec.options)
        if (option.presence == CommandOption::Required)
            usage += QLatin1Char(' ') + optionSyntax(option);
    usage += QStringLiteral(" [options]");
    QString text = wrapped(usage, 0, 8) + QStringLiteral("\n\n");
    text += wrapped(spec.description.isEmpty() ? spec.summary : spec.description, 0, 0) + QStringLiteral("\n");
    if (!spec.arguments.empty()) {
        text += QStringLiteral("\narguments:\n");
        for (const CommandArgument &argument : spec.arguments)
            text += helpRow(argument.name, argument.description);
    }
    text += QStringLiteral("\noptions:\n");
    for (const CommandOption &option : allOptions(spec)) {
        QString description = option.description;
        if (!option.defaultValue.isEmpty())
            description += QStringLiteral(" (default: %1)").arg(option.defaultValue);
        text += helpRow(optionSyntax(option), description);
    }
    return text;
}

void CommandLine::check(const QString &name) const
{
    Q_ASSERT_X(name == QLatin1String("json") || name == QLatin1String("help")
                   || std::any_of(m_spec.options.begin(), m_spec.options.end(),
                                  [&](const CommandOption &o) { return o.name == name; }),
               "CommandLine", qPrintable(QStringLiteral("--%1 is not declared by %2").arg(name, m_spec.name)));
    Q_UNUSED(name);
}

bool CommandLine::isSet(const QString &name) const
{
    check(name);
    return m_parser.isSet(name);
}

QString CommandLine::value(const QString &name) const
{
    check(name);
    return m_parser.value(name);
}

int CommandLine::integer(const QString &name, int min, int max) const
{
    bool ok = false;
    const int n = value(name).toInt(&ok);
    if (ok && n >= min && n <= max)
        return n;
    if (max == std::numeric_limits<int>::max())
        throw UsageError(QStringLiteral("--%1 must be an integer >= %2").arg(name).arg(min));
    throw UsageError(QStringLiteral("--%1 must be an integer in %2..%3").arg(name).arg(min).arg(max));
}

quint64 CommandLine::unsignedInteger(const QString &name) const
{
    bool ok = false;
    const quint64 n = value(name).toULongLong(&ok);
    if (!ok)
        throw UsageError(QStringLiteral("--%1 must be a non-negative integer").arg(name));
    return n;
}

double CommandLine::number(const QString &name) const
{
    bool ok = false;
    const double x = value(name).toDouble(&ok);
    if (!ok || !std::isfinite(x))
        throw UsageError(QStringLiteral("--%1 must be a number").arg(name));
    return x;
}

double CommandLine::positiveNumber(const QString &name) const
{
    const double x = value(name).toDouble();
    if (!(x > 0) || !std::isfinite(x))
        throw UsageError(QStringLiteral("--%1 must be a positive number").arg(name));
    return x;
}

QStringList CommandLine::list(const QString &name) const
{
    QStringList items;
    for (const QString &item : value(name).split(QLatin1Char(','), Qt::SkipEmptyParts))
        if (!item.trimmed().isEmpty())
            items << item.trimmed();
    return items;
}

} // namespace lipsync::cli
