// Crash safety of Project::save: a child process (ProjectSaveLoop) saves a project in a loop and
// is killed with SIGKILL at random moments, 100 times in a row. After every kill the project on
// disk must load and be exactly one version — the one before or a newer one, never a mix of two
// (every field and feature cell of a version says its number) and never broken.
#include "project/Project.h"
#include "util/Error.h"

#include <QDirIterator>
#include <QElapsedTimer>
#include <QProcess>
#include <QRandomGenerator>
#include <QTemporaryDir>
#include <QThread>
#include <QTest>

#include <csignal>
#include <sys/types.h>
#include <sys/wait.h>

using namespace lipsync;

namespace {

// The version a loaded project holds, or a message saying how it is inconsistent.
int versionOf(const Project &project, QString &problem)
{
    bool ok = false;
    const int k = QString::fromStdString(project.name).mid(1).toInt(&ok);
    if (!ok || project.name[0] != 'v') {
        problem = QStringLiteral("name '%1'").arg(QString::fromStdString(project.name));
        return -1;
    }
    if (project.sequences.size() != 3) {
        problem = QStringLiteral("%1 sequences").arg(project.sequences.size());
        return -1;
    }
    for (const Sequence &s : project.sequences) {
        const Eigen::Index columns = k % 2 ? 8 : 12;
        if (s.transcript != project.name || s.features.rows() != s.frameCount || s.features.cols() != columns
            || (s.features.array() != double(k)).any()) {
            problem = QStringLiteral("sequence %1 of version %2 has transcript '%3' and %4x%5 features (first %6)")
                          .arg(QString::fromStdString(s.id)).arg(k).arg(QString::fromStdString(s.transcript))
                          .arg(s.features.rows()).arg(s.features.cols())
                          .arg(s.features.size() ? s.features(0, 0) : 0.0);
            return -1;
        }
    }
    return k;
}

} // namespace

class TestProjectCrash : public QObject
{
    Q_OBJECT
private slots:
    void killedMidSaveLeavesOldOrNewVersion()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString folder = dir.filePath(QStringLiteral("project"));
        QRandomGenerator random(20071207); // reproducible kill moments
        int previous = 0;
        int advanced = 0;
        int midSave = 0; // kills that left a staged or temporary file behind
        int knownFiles = 0;
        QElapsedTimer clock;
        clock.start();
        for (int round = 0; round < 100; ++round) {
            QProcess child;
            child.start(QStringLiteral(LIPSYNC_SAVE_LOOP), {folder});
            QVERIFY2(child.waitForStarted(), qPrintable(child.errorString()));
            // After the child's first save (so every round makes progress, however loaded the
            // machine), anywhere in the next 0–20 ms: before, inside or between later saves.
            QVERIFY2(child.waitForReadyRead(10000), "the child did not save");
            QThread::usleep(random.bounded(20000));
            ::kill(pid_t(child.processId()), SIGKILL);
            QVERIFY(child.waitForFinished(5000));
            QCOMPARE(child.exitStatus(), QProcess::CrashExit);

            // A kill mid-save leaves a staged feature file or a new temporary file behind.
            QStringList files;
            for (QDirIterator it(folder, QDir::Files | QDir::Hidden, QDirIterator::Subdirectories); it.hasNext();)
                files << it.next();
            if (files.size() > knownFiles || files.filter(QStringLiteral("/.saving/")).size() > 0)
                ++midSave;
            knownFiles = int(files.size());
            Project project;
            try {
                project = Project::load(folder.toStdString());
            } catch (const Error &e) {
                QFAIL(qPrintable(QStringLiteral("round %1: the project does not load: %2").arg(round).arg(QString::fromUtf8(e.what()))));
            }
            QString problem;
            const int version = versionOf(project, problem);
            QVERIFY2(version > 0, qPrintable(QStringLiteral("round %1: %2").arg(round).arg(problem)));
            QVERIFY2(version >= previous, qPrintable(QStringLiteral("round %1: version %2 after %3").arg(round).arg(version).arg(previous)));
            advanced += version > previous;
            previous = version;
        }
        qInfo("100 kills in %lld ms; %d advanced the version, %d landed mid-save; last version %d",
              clock.elapsed(), advanced, midSave, previous);
        QCOMPARE(advanced, 100); // every round saved at least once before its kill
        QVERIFY(midSave > 10);   // and many kills interrupted a save
    }
};

QTEST_GUILESS_MAIN(TestProjectCrash)
#include "tst_projectcrash.moc"
