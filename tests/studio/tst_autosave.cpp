// Crash safety in the studio (studio/app/Autosave): a modified project is autosaved to a side
// folder (never over project.json), on a timer from QSettings and after a task changed it; a
// save or a clean close removes the autosave; opening a project whose autosave is newer (a crash
// left it) offers Recover / Discard / Cancel — answered here through the injectable prompt.
#include "../DamagedFiles.h"
#include "app/Autosave.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "context/ErrorReporter.h"
#include "DemoWindow.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/TaskRunner.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::testing::readAll;

namespace {

const QString kClip = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");

// A one-sequence project in `folder` with the demo clip in media/ (a relative path, so the
// autosave's rebasing is exercised) and the given transcript.
Project makeProject(const QString &folder, const std::string &transcript)
{
    QDir().mkpath(folder + QStringLiteral("/media"));
    QFile::copy(kClip, folder + QStringLiteral("/media/bbaf2n.mpg"));
    Project p;
    p.name = "autosave test";
    Sequence s;
    s.id = "bbaf2n";
    s.mediaFile = "media/bbaf2n.mpg";
    s.frameCount = 75;
    s.transcript = transcript;
    p.sequences.push_back(s);
    p.save(folder.toStdString());
    return Project::load(folder.toStdString());
}

QString autosaveManifest(const QString &folder)
{
    return Autosave::folderFor(folder, false) + QStringLiteral("/project.json");
}

} // namespace

class TestAutosave : public QObject
{
    Q_OBJECT
public:
    static void initMain() { studio::testing::initStudioTest(); }

private:
    MainWindow *m_window = nullptr;
    QTemporaryDir m_dir;

    void newWindow()
    {
        delete m_window;
        m_window = new MainWindow;
        m_window->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_window));
    }
    void idle() { QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->taskRunner()->runningCount(), 0, 30000); }
    ProjectDocument *doc() const { return m_window->context()->document(); }
    Autosave *autosave() const { return m_window->files()->autosave(); }

private slots:
    void initTestCase()
    {
        QCoreApplication::setOrganizationName(QStringLiteral("lipsync-tests"));
        ErrorReporter::setBatchMode(true);
        QSettings().remove(QStringLiteral("autosave"));
        QVERIFY(m_dir.isValid());
    }

    void cleanup()
    {
        Autosave::setPrompt({});
        QSettings().remove(QStringLiteral("autosave"));
        if (m_window)
            idle();
        delete m_window;
        m_window = nullptr;
    }

    void writesASideCopyNotTheProject()
    {
        const QString folder = m_dir.filePath(QStringLiteral("side"));
        makeProject(folder, "original");
        newWindow();
        QCOMPARE(autosave()->intervalMs(), Autosave::kDefaultIntervalMinutes * 60000);
        QVERIFY(m_window->files()->open(folder));
        idle();
        const QByteArray saved = readAll(folder + QStringLiteral("/project.json"));
        QVERIFY(!autosave()->saveNow()); // nothing unsaved
        QVERIFY(!QFileInfo::exists(autosaveManifest(folder)));

        QVERIFY(doc()->requestTranscriptChange(0, QStringLiteral("edited once")));
        QVERIFY(autosave()->saveNow());
        autosave()->waitForWrite();
        const Project side = Project::load(Autosave::folderFor(folder, false).toStdString());
        QCOMPARE(side.sequences.at(0).transcript, std::string("edited once"));
        // Its media path still reaches the clip from the side folder.
        QCOMPARE(QFileInfo(QString::fromStdString(side.mediaPath(side.sequences.at(0)))).canonicalFilePath(),
                 QFileInfo(folder + QStringLiteral("/media/bbaf2n.mpg")).canonicalFilePath());
        QCOMPARE(readAll(folder + QStringLiteral("/project.json")), saved); // the user's file untouched
        QVERIFY(doc()->isModified());
        QVERIFY(!autosave()->saveNow()); // unchanged since

        // Saving makes it stale: removed.
        QVERIFY(m_window->files()->save());
        QVERIFY(!QFileInfo::exists(Autosave::folderFor(folder, false)));
        QVERIFY(readAll(folder + QStringLiteral("/project.json")).contains("edited once"));
    }

    // An autosave that cannot be written (here a file squats on the side folder's name — root ignores
    // permissions) is shown in the status bar; the user's project stays as it was.
    void aFailedAutosaveIsShown()
    {
        const QString folder = m_dir.filePath(QStringLiteral("blocked"));
        makeProject(folder, "original");
        QFile squatter(Autosave::folderFor(folder, false));
        QVERIFY(squatter.open(QIODevice::WriteOnly));
        squatter.close();
        newWindow();
        QVERIFY(m_window->files()->open(folder));
        idle();
        const QByteArray saved = readAll(folder + QStringLiteral("/project.json"));
        QVERIFY(doc()->requestTranscriptChange(0, QStringLiteral("edited")));
        QSignalSpy failed(autosave(), &Autosave::failed);
        QVERIFY(autosave()->saveNow());
        autosave()->waitForWrite();
        QCOMPARE(failed.count(), 1);
        const QString shown = m_window->statusBar()->currentMessage();
        QVERIFY2(shown.startsWith(QStringLiteral("Autosave failed")), qPrintable(shown));
        QVERIFY2(shown.contains(QStringLiteral(".autosave")), qPrintable(shown));
        QCOMPARE(readAll(folder + QStringLiteral("/project.json")), saved);
        QVERIFY(doc()->isModified());
    }

    void autosavesAfterATaskChangedTheDocument()
    {
        const QString folder = m_dir.filePath(QStringLiteral("task"));
        makeProject(folder, "original");
        newWindow();
        QVERIFY(m_window->files()->open(folder));
        idle();
        ProjectDocument *document = doc();
        m_window->context()->taskRunner()->start(QStringLiteral("an edit"), [document](Feedback &) {
            return TaskRunner::Commit([document] { document->requestTranscriptChange(0, QStringLiteral("by a task")); });
        });
        QTRY_VERIFY_WITH_TIMEOUT(QFileInfo::exists(autosaveManifest(folder)), 10000);
        autosave()->waitForWrite();
        QVERIFY(readAll(autosaveManifest(folder)).contains("by a task"));
    }

    void autosavesOnTheTimerFromSettings()
    {
        QSettings().setValue(QStringLiteral("autosave/intervalMinutes"), 0.005); // 300 ms
        const QString folder = m_dir.filePath(QStringLiteral("timer"));
        makeProject(folder, "original");
        newWindow();
        QCOMPARE(autosave()->intervalMs(), 300);
        QVERIFY(m_window->files()->open(folder));
        idle();
        QVERIFY(doc()->requestTranscriptChange(0, QStringLiteral("on the timer")));
        QTRY_VERIFY_WITH_TIMEOUT(readAll(autosaveManifest(folder)).contains("on the timer"), 10000);
        // Undone back to the saved state: nothing to keep, the next tick removes it.
        m_window->context()->undoStack()->undo();
        QTRY_VERIFY_WITH_TIMEOUT(!QFileInfo::exists(Autosave::folderFor(folder, false)), 10000);
    }

    void cleanCloseRemovesTheAutosave()
    {
        const QString folder = m_dir.filePath(QStringLiteral("close"));
        makeProject(folder, "original");
        newWindow();
        QVERIFY(m_window->files()->open(folder));
        idle();
        QVERIFY(doc()->requestTranscriptChange(0, QStringLiteral("unsaved")));
        QVERIFY(autosave()->saveNow());
        autosave()->waitForWrite();
        QVERIFY(QFileInfo::exists(autosaveManifest(folder)));
        QVERIFY(m_window->close()); // batch mode: closing does not ask
        delete m_window;
        m_window = nullptr;
        QVERIFY(!QFileInfo::exists(Autosave::folderFor(folder, false)));
        QVERIFY(readAll(folder + QStringLiteral("/project.json")).contains("original"));
    }

    void demoAutosavesOutsideTheInstallation()
    {
        newWindow();
        QVERIFY(m_window->files()->openDemo());
        idle();
        const QString side = Autosave::folderFor(doc()->folder(), true);
        QVERIFY(!side.startsWith(doc()->folder()));
        QVERIFY(doc()->requestTranscriptChange(1, QStringLiteral("demo edit")));
        QElapsedTimer clock;
        clock.start();
        QVERIFY(autosave()->saveNow());
        const qint64 onGuiThread = clock.elapsed();
        autosave()->waitForWrite();
        qInfo("demo autosave (10 sequences with features): %lld ms on the GUI thread, %lld ms until on disk",
              onGuiThread, clock.elapsed());
        QVERIFY(readAll(side + QStringLiteral("/project.json")).contains("demo edit"));
        QVERIFY(!QFileInfo::exists(doc()->folder() + QStringLiteral("/.autosave")));
        delete m_window;
        m_window = nullptr;
        QVERIFY(!QFileInfo::exists(side));
    }

    // A Save As that fails half-way (the target's manifest name is taken by a folder, so the
    // demo's clips, AAM and features are copied first and the manifest then cannot be written)
    // leaves the target as it was, the document unsaved and its autosave in place.
    void aFailedSaveLeavesNothingAndKeepsTheAutosave()
    {
        newWindow();
        QVERIFY(m_window->files()->openDemo());
        idle();
        QVERIFY(doc()->requestTranscriptChange(1, QStringLiteral("unsaved edit")));
        QVERIFY(autosave()->saveNow());
        autosave()->waitForWrite();
        const QString side = Autosave::folderFor(doc()->folder(), true);
        QVERIFY(QFileInfo::exists(side + QStringLiteral("/project.json")));

        const QString target = m_dir.filePath(QStringLiteral("half-written"));
        QVERIFY(QDir().mkpath(target + QStringLiteral("/project.json")));
        const QStringList before = QDir(target).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden);
        QVERIFY(!m_window->files()->saveTo(target));
        QCOMPARE(QDir(target).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden), before);
        QVERIFY(doc()->isReadOnly());
        QVERIFY(doc()->isModified());
        QVERIFY(readAll(side + QStringLiteral("/project.json")).contains("unsaved edit"));

        // The same folder once nothing is in the way: saved, the autosave removed.
        QVERIFY(QDir(target + QStringLiteral("/project.json")).removeRecursively());
        QVERIFY(m_window->files()->saveTo(target));
        QVERIFY(!doc()->isModified());
        QVERIFY(readAll(target + QStringLiteral("/project.json")).contains("unsaved edit"));
        QVERIFY(!QFileInfo::exists(side));
    }

    void offersRecovery_data()
    {
        QTest::addColumn<int>("answer");
        QTest::newRow("recover") << int(Autosave::Choice::Recover);
        QTest::newRow("discard") << int(Autosave::Choice::Discard);
        QTest::newRow("cancel") << int(Autosave::Choice::Cancel);
    }

    void offersRecovery()
    {
        QFETCH(int, answer);
        const auto choice = Autosave::Choice(answer);
        const QString folder = m_dir.filePath(QStringLiteral("crashed-") + QString::fromLatin1(QTest::currentDataTag()));
        Project project = makeProject(folder, "original");
        // What a crash leaves behind: an autosave with an edit, newer than the project.
        project.sequences.at(0).transcript = "autosaved edit";
        Autosave::write(project, folder, false);
        QFile manifest(folder + QStringLiteral("/project.json"));
        QVERIFY(manifest.open(QIODevice::ReadWrite));
        QVERIFY(manifest.setFileTime(QDateTime::currentDateTime().addSecs(-60), QFileDevice::FileModificationTime));
        manifest.close();

        int asked = 0;
        QString askedFor;
        Autosave::setPrompt([&](QWidget *, const QString &projectFolder, const QDateTime &) {
            ++asked;
            askedFor = projectFolder;
            return choice;
        });
        newWindow();
        const bool opened = m_window->files()->open(folder);
        QCOMPARE(asked, 1);
        QCOMPARE(QFileInfo(askedFor).canonicalFilePath(), QFileInfo(folder).canonicalFilePath());
        switch (choice) {
        case Autosave::Choice::Recover:
            QVERIFY(opened);
            QCOMPARE(doc()->sequence(0).transcript, std::string("autosaved edit"));
            QVERIFY(doc()->isModified());
            QCOMPARE(QFileInfo(doc()->mediaPath(0)).canonicalFilePath(),
                     QFileInfo(folder + QStringLiteral("/media/bbaf2n.mpg")).canonicalFilePath());
            idle();
            QVERIFY(m_window->context()->media()); // the clip loaded from the recovered path
            QVERIFY(m_window->isWindowModified());
            QVERIFY(m_window->files()->save());
            QVERIFY(!doc()->isModified());
            QVERIFY(readAll(folder + QStringLiteral("/project.json")).contains("autosaved edit"));
            QVERIFY(!QFileInfo::exists(Autosave::folderFor(folder, false)));
            break;
        case Autosave::Choice::Discard:
            QVERIFY(opened);
            QCOMPARE(doc()->sequence(0).transcript, std::string("original"));
            QVERIFY(!doc()->isModified());
            QVERIFY(!QFileInfo::exists(Autosave::folderFor(folder, false)));
            break;
        case Autosave::Choice::Cancel:
            QVERIFY(!opened);
            QVERIFY(!doc()->isOpen());
            QVERIFY(QFileInfo::exists(autosaveManifest(folder))); // kept for next time
            break;
        }
    }

    void olderAutosaveIsNotOffered()
    {
        const QString folder = m_dir.filePath(QStringLiteral("older"));
        Project project = makeProject(folder, "original");
        project.sequences.at(0).transcript = "older edit";
        Autosave::write(project, folder, false);
        QFile side(autosaveManifest(folder));
        QVERIFY(side.open(QIODevice::ReadWrite));
        QVERIFY(side.setFileTime(QDateTime::currentDateTime().addSecs(-60), QFileDevice::FileModificationTime));
        side.close();
        int asked = 0;
        Autosave::setPrompt([&](QWidget *, const QString &, const QDateTime &) {
            ++asked;
            return Autosave::Choice::Recover;
        });
        newWindow();
        QVERIFY(m_window->files()->open(folder));
        QCOMPARE(asked, 0);
        QCOMPARE(doc()->sequence(0).transcript, std::string("original"));
        QVERIFY(!QFileInfo::exists(Autosave::folderFor(folder, false)));
    }
};

QTEST_MAIN(TestAutosave)
#include "tst_autosave.moc"
