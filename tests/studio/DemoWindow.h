#pragma once
// Shared set-up of the GUI tests: the process (OpenGL surface format for VTK, test-mode settings
// so the user's own are untouched), the studio's main window on the bundled demo project, shown,
// active (window shortcuts only fire in the active window) and with its loading tasks finished.
#include "app/DemoProject.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "app/SurfaceFormat.h"
#include "context/ErrorReporter.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "timeline/TimelinePanel.h"

#include <QCoreApplication>
#include <QDir>
#include <QDirIterator>
#include <QFile>
#include <QFileInfo>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTest>
#include <QVBoxLayout>

namespace lipsync::studio::testing {

// For the test class's static initMain(), before the application exists.
inline void initStudioTest()
{
    setDefaultSurfaceFormat();
    QStandardPaths::setTestModeEnabled(true);
}

// The bundled demo opened read-only on `context`, for tests of panels without a window.
inline void openDemo(StudioContext &context)
{
    const QString demo = DemoProject::locate();
    QVERIFY(!demo.isEmpty());
    context.document()->reset(DemoProject::load(demo), demo, true);
}

// Sequence `row` of the context's document made the current one, its media as the window's
// loader hands it over (only its frames count here).
inline void makeCurrent(StudioContext &context, int row)
{
    auto media = std::make_shared<SequenceMedia>();
    media->sequenceId = QString::fromStdString(context.document()->sequence(row).id);
    media->frames.resize(context.document()->sequence(row).frameCount);
    context.setCurrentSequence(row, media);
    context.announceSequenceLoaded();
}

// Copies every file under `from` into `to`, subfolders included, each writable by the owner (a
// writable copy of the demo, wherever it is installed).
inline bool copyFolder(const QString &from, const QString &to)
{
    QDirIterator it(from, QDir::Files, QDirIterator::Subdirectories);
    while (it.hasNext()) {
        const QString file = it.next();
        const QString target = QDir(to).filePath(QDir(from).relativeFilePath(file));
        if (!QDir().mkpath(QFileInfo(target).absolutePath()) || !QFile::copy(file, target))
            return false;
        QFile::setPermissions(target, QFile::permissions(target) | QFileDevice::WriteOwner);
    }
    return true;
}

// Waits for `task` (null: none started) to end; true if it finished, not failed or canceled.
inline bool waitFor(Task *task, int timeoutMs = 120000)
{
    if (!task)
        return false;
    QSignalSpy finished(task, &Task::finished);
    if (task->isRunning() && !finished.wait(timeoutMs))
        return false;
    return task->state() == Task::State::Finished;
}

// Waits until the window's background tasks (training, tracking, export) have finished.
inline void waitForTasks(MainWindow *window, int timeoutMs = 120000)
{
    QTRY_COMPARE_WITH_TIMEOUT(window->context()->taskRunner()->runningCount(), 0, timeoutMs);
}

// Creates `window`. A failed check fails the calling test: callers return when
// QTest::currentTestFailed().
inline void openDemoWindow(MainWindow *&window)
{
    QCoreApplication::setOrganizationName(QStringLiteral("lipsync-tests"));
    ErrorReporter::setBatchMode(true);
    window = new MainWindow;
    window->resize(1280, 800);
    window->show();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    window->activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(window));
    QVERIFY(window->files()->openDemo());
    QTRY_VERIFY_WITH_TIMEOUT(window->context()->media() != nullptr, 60000);
    waitForTasks(window, 60000);
}

// Opens the project in `folder` (a writable copy, see copyFolder) in the window and waits until its
// first sequence and its loading tasks are done. Callers return when QTest::currentTestFailed().
inline void openProjectFolder(MainWindow *window, const QString &folder)
{
    QVERIFY(window->files()->open(folder));
    QTRY_VERIFY_WITH_TIMEOUT(window->context()->media() != nullptr, 60000);
    waitForTasks(window);
    QVERIFY(!window->context()->document()->isReadOnly());
}

// The demo window, audio playback off, then the project in `folder` opened in it (openProjectFolder).
// Callers return when QTest::currentTestFailed().
inline void openWindowOnProject(MainWindow *&window, const QString &folder)
{
    openDemoWindow(window);
    if (QTest::currentTestFailed())
        return;
    window->context()->playback()->setAudioEnabled(false);
    openProjectFolder(window, folder);
}

// A Timeline panel made in `host` (shown, active) on `context`, the demo opened and its first
// sequence loaded, audio playback off: the speech tests, without a window. Callers return when
// QTest::currentTestFailed().
inline void openDemoTimeline(StudioContext &context, QWidget &host, TimelinePanel *&panel)
{
    QCoreApplication::setOrganizationName(QStringLiteral("lipsync-tests"));
    ErrorReporter::setBatchMode(true);
    auto *layout = new QVBoxLayout(&host);
    panel = new TimelinePanel(&host);
    layout->addWidget(panel);
    panel->attach(&context);
    context.playback()->setAudioEnabled(false);
    host.resize(1280, 360);
    host.show();
    QVERIFY(QTest::qWaitForWindowExposed(&host));
    host.activateWindow();
    QVERIFY(QTest::qWaitForWindowActive(&host));
    openDemo(context);
    context.selectSequence(0);
    QTRY_VERIFY_WITH_TIMEOUT(context.media() != nullptr, 60000);
}

} // namespace lipsync::studio::testing
