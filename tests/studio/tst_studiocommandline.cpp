// lipsync-studio's command line as a user runs it: --help and --version answer without a
// display (no X server, no platform plugin), in the system's language.
#include <QProcess>
#include <QProcessEnvironment>
#include <QTest>

class TestStudioCommandLine : public QObject
{
    Q_OBJECT

    static QProcess *runWithoutDisplay(const QStringList &arguments)
    {
        auto *process = new QProcess;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.remove(QStringLiteral("DISPLAY"));
        env.remove(QStringLiteral("WAYLAND_DISPLAY"));
        env.insert(QStringLiteral("QT_QPA_PLATFORM"), QStringLiteral("xcb")); // would abort without a display
        env.insert(QStringLiteral("LANG"), QStringLiteral("C"));
        env.remove(QStringLiteral("LANGUAGE"));
        env.remove(QStringLiteral("LC_ALL"));
        process->setProcessEnvironment(env);
        process->start(QStringLiteral(LIPSYNC_STUDIO), arguments);
        return process;
    }

private slots:
    void helpNeedsNoDisplay()
    {
        QScopedPointer<QProcess> studio(runWithoutDisplay({QStringLiteral("--help")}));
        QVERIFY(studio->waitForFinished(30000));
        QCOMPARE(studio->exitStatus(), QProcess::NormalExit);
        QCOMPARE(studio->exitCode(), 0);
        const QString out = QString::fromUtf8(studio->readAllStandardOutput());
        QVERIFY2(out.contains(QStringLiteral("--project <DIR>")) && out.contains(QStringLiteral("--screenshot")),
                 qPrintable(out));
    }

    void versionNeedsNoDisplay()
    {
        QScopedPointer<QProcess> studio(runWithoutDisplay({QStringLiteral("--version")}));
        QVERIFY(studio->waitForFinished(30000));
        QCOMPARE(studio->exitCode(), 0);
        QVERIFY(QString::fromUtf8(studio->readAllStandardOutput()).startsWith(QStringLiteral("LipSync Studio ")));
    }
};

QTEST_GUILESS_MAIN(TestStudioCommandLine)
#include "tst_studiocommandline.moc"
