#pragma once
// Runs the `lipsync` executable as a user would, for the CLI tests (LIPSYNC_CLI is its path).
#include <QByteArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QStringList>
#include <QTest>

namespace lipsync::testing {

struct Run
{
    int exitCode = -1; // -1 when the process crashed or timed out
    QByteArray out;
    QByteArray err;
};

inline Run runLipsync(const QStringList &args,
                      const QProcessEnvironment &environment = QProcessEnvironment::systemEnvironment(),
                      int timeoutMs = 120000)
{
    QProcess process;
    process.setProcessEnvironment(environment);
    process.start(QStringLiteral(LIPSYNC_CLI), args);
    Run run;
    if (!process.waitForFinished(timeoutMs)) {
        process.kill();
        process.waitForFinished();
        return run;
    }
    run.exitCode = process.exitStatus() == QProcess::NormalExit ? process.exitCode() : -1;
    run.out = process.readAllStandardOutput();
    run.err = process.readAllStandardError();
    return run;
}

// The JSON object printed on stdout, or an empty object if it is not valid JSON.
inline QJsonObject parseJsonObject(const QByteArray &out)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(out, &error);
    return error.error == QJsonParseError::NoError ? document.object() : QJsonObject();
}

// A failed command as users see it: exit code `exitCode`, nothing on stdout, and one line on
// stderr, "lipsync: ...", that says `needle`.
inline void verifyOneLineError(const Run &r, int exitCode, const QString &needle)
{
    QCOMPARE(r.exitCode, exitCode);
    QVERIFY2(r.out.isEmpty(), r.out.constData());
    QCOMPARE(r.err.count('\n'), 1);
    QVERIFY2(r.err.startsWith("lipsync: "), r.err.constData());
    QVERIFY2(QString::fromUtf8(r.err).contains(needle), r.err.constData());
}

} // namespace lipsync::testing
