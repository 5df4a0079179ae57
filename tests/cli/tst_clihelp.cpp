// Every command of `lipsync` as listed by `lipsync --help` (so a new command is covered without
// touching this test): `COMMAND --help` exits 0 with its usage and options, every option the help
// lists is accepted, an unknown option is one line naming it (exit 2); the commands that align
// share one set of aligner options, and renamed options keep their old spelling.
#include "CliRun.h"

#include <QRegularExpression>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <memory>
#include <vector>

using lipsync::testing::Run;
using lipsync::testing::runLipsync;

namespace {

// The command names of `lipsync --help`: the lines after "commands:", "  NAME  summary".
QStringList listedCommands()
{
    const Run r = runLipsync({"--help"});
    QStringList names;
    bool inList = false;
    static const QRegularExpression row(QStringLiteral("^  (\\S.*?)\\s{2,}\\S"));
    for (const QString &line : QString::fromUtf8(r.out).split(QLatin1Char('\n'))) {
        if (line == QLatin1String("commands:")) {
            inList = true;
            continue;
        }
        const QRegularExpressionMatch m = row.match(line);
        if (inList && m.hasMatch())
            names << m.captured(1);
    }
    return names;
}

struct HelpOption
{
    QString name;      // "--aligner"
    bool takesValue = false;
    QString row;       // the help's whole row, continuation lines included
};

// The options a command's help lists: the rows of its "options:" section.
QList<HelpOption> helpOptions(const QString &help)
{
    QList<HelpOption> options;
    static const QRegularExpression start(QStringLiteral("^  (?:-[a-z], )?(--[a-z0-9-]+)( \\S+)?"));
    bool inOptions = false;
    for (const QString &line : help.split(QLatin1Char('\n'))) {
        if (line == QLatin1String("options:")) {
            inOptions = true;
            continue;
        }
        if (!inOptions)
            continue;
        const QRegularExpressionMatch m = start.match(line);
        if (m.hasMatch())
            options.append({m.captured(1), m.capturedLength(2) > 0, line});
        else if (!options.isEmpty() && line.startsWith(QLatin1String("   ")))
            options.last().row += QLatin1Char('\n') + line;
    }
    return options;
}

QStringList words(const QString &command)
{
    return command.split(QLatin1Char(' '));
}

// runLipsync() of every argument list, a few processes at a time: the runs are short, and there
// are hundreds of them.
QList<Run> runAll(const QList<QStringList> &argLists)
{
    constexpr int kAtOnce = 6;
    QList<Run> runs;
    for (qsizetype first = 0; first < argLists.size(); first += kAtOnce) {
        std::vector<std::unique_ptr<QProcess>> batch;
        for (qsizetype i = first; i < std::min(first + kAtOnce, argLists.size()); ++i) {
            batch.push_back(std::make_unique<QProcess>());
            batch.back()->start(QStringLiteral(LIPSYNC_CLI), argLists[i]);
        }
        for (const auto &process : batch) {
            Run run;
            if (process->waitForFinished(120000) && process->exitStatus() == QProcess::NormalExit)
                run.exitCode = process->exitCode();
            else
                process->kill();
            run.out = process->readAllStandardOutput();
            run.err = process->readAllStandardError();
            runs.append(run);
        }
    }
    return runs;
}

} // namespace

class TestCliHelp : public QObject
{
    Q_OBJECT

    QStringList m_commands;
    QList<Run> m_help; // `COMMAND --help` of each command

private slots:
    void initTestCase()
    {
        m_commands = listedCommands();
        // The registry holds these at least; the list is the real binary's.
        for (const char *name : {"info", "align", "render", "train", "aam build", "track", "landmarks detect"})
            QVERIFY2(m_commands.contains(QLatin1String(name)), qPrintable(m_commands.join(", ")));
        QList<QStringList> argLists;
        for (const QString &command : std::as_const(m_commands))
            argLists << (words(command) << QStringLiteral("--help"));
        m_help = runAll(argLists);
    }

    void everyCommandHasHelp()
    {
        for (qsizetype i = 0; i < m_help.size(); ++i) {
            const QString &command = m_commands[i];
            const Run &r = m_help[i];
            QVERIFY2(r.exitCode == 0, qPrintable(command + ": " + r.err));
            const QString help = QString::fromUtf8(r.out);
            QVERIFY2(help.startsWith(QStringLiteral("usage: lipsync ") + command), qPrintable(help));
            const QList<HelpOption> options = helpOptions(help);
            QStringList names;
            for (const HelpOption &o : options)
                names << o.name;
            QVERIFY2(names.contains("--json") && names.contains("--help"), qPrintable(command + ": " + help));
            for (const HelpOption &o : options)
                QVERIFY2(o.row.simplified().size() > o.name.size() + 8,
                         qPrintable(command + ": " + o.name + " has no description"));
        }
        const Run h = runLipsync({"project", "check", "-h"});
        QCOMPARE(h.exitCode, 0);
        QCOMPARE(h.out, m_help[m_commands.indexOf("project check")].out);
    }

    // Every group of commands answers --help with its own commands (exit 0); the group alone
    // lists them as a usage error; an unknown command of the group is named.
    void everyGroupHasHelp()
    {
        QStringList groups;
        for (const QString &command : std::as_const(m_commands))
            if (command.contains(QLatin1Char(' ')) && !groups.contains(command.section(QLatin1Char(' '), 0, 0)))
                groups << command.section(QLatin1Char(' '), 0, 0);
        QVERIFY(groups.contains("project") && groups.contains("aligner") && groups.contains("aam"));
        for (const QString &group : std::as_const(groups)) {
            const Run help = runLipsync({group, "--help"});
            QVERIFY2(help.exitCode == 0, qPrintable(group + ": " + help.err));
            QVERIFY(help.err.isEmpty());
            const QString text = QString::fromUtf8(help.out);
            QVERIFY2(text.startsWith(QStringLiteral("usage: lipsync ") + group + " COMMAND"), qPrintable(text));
            for (const QString &command : std::as_const(m_commands))
                if (command.startsWith(group + ' '))
                    QVERIFY2(text.contains("  " + command + "  "), qPrintable(group + ": " + command));
            QVERIFY(!text.contains(QStringLiteral("  info  ")));
            QCOMPARE(runLipsync({group}).exitCode, 2);
        }
        const Run unknown = runLipsync({"project", "frobnicate"});
        QCOMPARE(unknown.exitCode, 2);
        QVERIFY2(unknown.err.contains("unknown command 'project frobnicate'"), unknown.err.constData());
    }

    // Each option the help lists is one the command's parser takes (with a value if the help
    // names one): given all together, the reply may be any error but an unknown option or a
    // missing value, which the parser reports before anything else. The values name no file, so
    // nothing is read or written.
    void everyListedOptionIsAccepted()
    {
        QTemporaryDir dir;
        const QString value = dir.filePath(QStringLiteral("no-such-file"));
        QList<QStringList> argLists;
        for (qsizetype c = 0; c < m_commands.size(); ++c) {
            argLists << words(m_commands[c]);
            for (const HelpOption &o : helpOptions(QString::fromUtf8(m_help[c].out))) {
                if (o.name == QLatin1String("--help"))
                    continue;
                argLists.last() << o.name;
                if (o.takesValue)
                    argLists.last() << value;
            }
            QVERIFY2(argLists.last().contains("--json"), qPrintable(argLists.last().join(' ')));
        }
        const QList<Run> runs = runAll(argLists);
        for (qsizetype i = 0; i < runs.size(); ++i) {
            QVERIFY2(runs[i].exitCode != -1, qPrintable(argLists[i].join(' ')));
            QVERIFY2(!runs[i].err.contains("unknown option") && !runs[i].err.contains("issing value"),
                     qPrintable(argLists[i].join(' ') + ": " + runs[i].err));
        }
    }

    void unknownOptionIsOneLineNamingIt()
    {
        QList<QStringList> argLists;
        for (const QString &command : std::as_const(m_commands))
            argLists << (words(command) << QStringLiteral("--no-such-option"));
        const QList<Run> runs = runAll(argLists);
        for (qsizetype i = 0; i < runs.size(); ++i) {
            const QString &command = m_commands[i];
            const Run &r = runs[i];
            QVERIFY2(r.exitCode == 2, qPrintable(command + ": " + r.err));
            QVERIFY2(r.err.count('\n') == 1 && r.err.contains("unknown option --no-such-option")
                         && r.err.contains(command.toUtf8()),
                     qPrintable(command + ": " + r.err));
            QVERIFY2(r.out.isEmpty(), qPrintable(command + ": " + r.out));
        }
        // A value where a flag stands, and an option without its value.
        Run r = runLipsync({"info", "--json=yes", "x"});
        QCOMPARE(r.exitCode, 2);
        QCOMPARE(r.err.count('\n'), 1);
        r = runLipsync({"align", "clip.mpg", "--transcript"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.count('\n') == 1 && r.err.contains("--transcript"), r.err.constData());
        // A missing required option or argument names it.
        r = runLipsync({"align", "clip.mpg", "--transcript", "t.txt"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("missing --out"), r.err.constData());
        r = runLipsync({"info"});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("missing PATH"), r.err.constData());
    }

    // Every command that aligns offers the same aligner choices, described the same way (live's
    // --aligner chooses a recogniser, not a forced aligner, and says so in its own words).
    void alignersAreTheSameEverywhere()
    {
        QMap<QString, QString> alignerRows; // command -> its aligner options' rows
        for (qsizetype c = 0; c < m_commands.size(); ++c) {
            if (m_commands[c] == QLatin1String("live"))
                continue;
            QString rows;
            bool aligns = false;
            for (const HelpOption &o : helpOptions(QString::fromUtf8(m_help[c].out))) {
                if (o.name == QLatin1String("--aligner") && o.row.contains(QLatin1String("sphinx")))
                    aligns = true;
                if (QStringList{"--aligner", "--adapt", "--pronunciations"}.contains(o.name))
                    rows += o.row + QLatin1Char('\n');
            }
            if (aligns)
                alignerRows[m_commands[c]] = rows;
        }
        QVERIFY2(alignerRows.contains("align") && alignerRows.contains("render"),
                 qPrintable(alignerRows.keys().join(", ")));
        for (auto it = alignerRows.cbegin(); it != alignerRows.cend(); ++it)
            QCOMPARE(it.value(), alignerRows.value("align"));
    }

    // Old spellings of renamed options are still accepted (not listed in the help).
    void renamedOptionsKeepTheirOldSpelling()
    {
        const struct
        {
            QStringList args; // the command and the old option
            QString now;      // the option it stands for
        } renamed[] = {
            {{"align", "--model"}, "--aligner"},
            {{"aligner", "adapt", "--model"}, "--aligner"},
            {{"track", "--model"}, "--aam"},
            {{"aam", "eval", "--model"}, "--aam"},
            {{"landmarks", "detect", "--model"}, "--aam"},
            {{"aam", "build", "--features"}, "--fit-features"},
            {{"render", "--labels"}, "--captions"},
            {{"export", "video", "--labels"}, "--captions"},
        };
        for (const auto &r : renamed) {
            const Run run = runLipsync(QStringList(r.args) << QStringLiteral("value"));
            QVERIFY2(!run.err.contains("unknown option"), qPrintable(r.args.join(' ') + ": " + run.err));
            const Run help = runLipsync(r.args.mid(0, r.args.size() - 1) << QStringLiteral("--help"));
            QVERIFY2(help.out.contains(r.now.toUtf8() + ' '), help.out.constData());
            QVERIFY2(!help.out.contains(r.args.last().toUtf8() + ' '), help.out.constData());
        }
    }
};

QTEST_GUILESS_MAIN(TestCliHelp)
#include "tst_clihelp.moc"
