// The studio opens the bundled demo: ten sequences, the first frame and the waveform on screen
// once the background load has finished; frame/sequence navigation; undo/redo of a transcript
// edit (every step back and forward again); a canceled load leaves the views as they were.
#include "DemoWindow.h"

#include "align/SphinxAligner.h"
#include "annotate/FrameView.h"
#include "app/AboutBox.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "app/RecentProjects.h"
#include "app/SequenceListModel.h"
#include "app/ShortcutsDialog.h"
#include "app/TransportBar.h"
#include "app/UserGuide.h"
#include "context/ErrorReporter.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioActions.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "export/ExportMenu.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "timeline/TimelinePanel.h"
#include "timeline/WaveformView.h"

#include <QAbstractButton>
#include <QAction>
#include <QAudioDevice>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileInfo>
#include <QMediaDevices>
#include <QMenuBar>
#include <QMenu>
#include <QScreen>
#include <QSet>
#include <QSettings>
#include <QSignalSpy>
#include <QSpinBox>
#include <QStatusBar>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>
#include <QTextBrowser>
#include <QTreeWidget>
#include <QUndoStack>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::studio::testing::openDemoWindow;

class TestMainWindow : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase()
    {
        openDemoWindow(m_window);
    }

    void cleanupTestCase() { delete m_window; }

    void opensDemoProject()
    {
        QCOMPARE(m_window->sequenceView()->model()->rowCount(), 10);
        QVERIFY(m_window->context()->document()->isReadOnly());
        QCOMPARE(m_window->context()->currentSequence(), 0);
        QCOMPARE(m_window->context()->currentFrame(), 0);
        QCOMPARE(m_window->context()->media()->frameCount(), 75);
        QVERIFY(m_window->context()->media()->peaks);
    }

    void frameViewShowsTheFrame()
    {
        const QImage image = m_window->frameView()->grab().toImage();
        QSet<QRgb> colours;
        for (int y = 0; y < image.height(); y += 2)
            for (int x = 0; x < image.width(); x += 2)
                colours.insert(image.pixel(x, y) & 0xffffff);
        QVERIFY2(colours.size() > 1000, qPrintable(QStringLiteral("%1 distinct colours").arg(colours.size())));
    }

    void waveformViewShowsTheWaveform()
    {
        const QImage image = m_window->waveformView()->grab().toImage().convertToFormat(QImage::Format_RGB32);
        const QRgb wave = WaveformView::waveformColor().rgb() & 0xffffff;
        int n = 0;
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                n += (image.pixel(x, y) & 0xffffff) == wave ? 1 : 0;
        QVERIFY2(n > 2000, qPrintable(QStringLiteral("%1 waveform pixels").arg(n)));
    }

    void frameNavigation()
    {
        const StudioActions &a = m_window->actions();
        a.nextFrame->trigger();
        QCOMPARE(m_window->context()->currentFrame(), 1);
        a.lastFrame->trigger();
        QCOMPARE(m_window->context()->currentFrame(), 74);
        // The transport counts frames from 1, as every caption does; typing a frame goes there.
        auto *spin = m_window->findChild<TransportBar *>()->findChild<QSpinBox *>();
        QVERIFY(spin);
        QCOMPARE(spin->value(), 75);
        QCOMPARE(spin->maximum(), 75);
        spin->setValue(10);
        QCOMPARE(m_window->context()->currentFrame(), 9);
        a.lastFrame->trigger();
        a.nextFrame->trigger();
        QCOMPARE(m_window->context()->currentFrame(), 74); // clamped
        a.firstFrame->trigger();
        QCOMPARE(m_window->context()->currentFrame(), 0);
        QTest::keyClick(m_window, Qt::Key_Right);
        QCOMPARE(m_window->context()->currentFrame(), 1);
        QTest::keyClick(m_window, Qt::Key_Home);
        QCOMPARE(m_window->context()->currentFrame(), 0);
    }

    void nextSequenceLoadsIt()
    {
        QSignalSpy loaded(m_window->context(), &StudioContext::sequenceLoaded);
        m_window->actions().nextSequence->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(loaded.count(), 1, 60000);
        QCOMPARE(m_window->context()->currentSequence(), 1);
        QCOMPARE(m_window->context()->media()->sequenceId, QStringLiteral("bgin3a"));
        QCOMPARE(m_window->sequenceView()->currentIndex().row(), 1);
    }

    void canceledLoadChangesNothing()
    {
        const int before = m_window->context()->currentSequence();
        const auto media = m_window->context()->media();
        QSignalSpy ended(m_window->context(), &StudioContext::sequenceLoadEnded);
        m_window->context()->selectSequence(5);
        QCOMPARE(m_window->context()->taskRunner()->runningCount(), 1);
        m_window->context()->taskRunner()->cancelAll();
        QTRY_COMPARE_WITH_TIMEOUT(ended.count(), 1, 60000);
        QCOMPARE(ended.first().first().toBool(), false);
        QCOMPARE(m_window->context()->currentSequence(), before);
        QCOMPARE(m_window->context()->media(), media);
        QCOMPARE(m_window->sequenceView()->currentIndex().row(), before);
    }

    void transcriptEditUndoRedo()
    {
        QAbstractItemModel *model = m_window->sequenceView()->model();
        QUndoStack *undo = m_window->context()->undoStack();
        const QModelIndex cell = model->index(2, SequenceListModel::TranscriptColumn);
        const QString original = model->data(cell).toString();
        QVERIFY(!original.isEmpty());
        QVERIFY(!m_window->context()->document()->isModified());

        QVERIFY(!model->setData(cell, original)); // no change, no command
        QCOMPARE(undo->count(), 0);
        QVERIFY(model->setData(cell, QStringLiteral("bin green  in n three again")));
        QVERIFY(model->setData(cell, QStringLiteral("second edit")));
        const QString first = QStringLiteral("bin green in n three again"); // whitespace simplified
        QCOMPARE(undo->count(), 2);
        QCOMPARE(model->data(cell).toString(), QStringLiteral("second edit"));
        QVERIFY(m_window->context()->document()->isModified());

        // Every step back (through the Edit menu's actions) and forward again.
        m_window->actions().undo->trigger();
        QCOMPARE(model->data(cell).toString(), first);
        QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(model->data(cell).toString(), original);
        QCOMPARE(QString::fromStdString(m_window->context()->document()->sequence(2).transcript), original);
        QVERIFY(!m_window->context()->document()->isModified());
        QVERIFY(!m_window->actions().undo->isEnabled());
        m_window->actions().redo->trigger();
        QCOMPARE(model->data(cell).toString(), first);
        QTest::keyClick(m_window, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(model->data(cell).toString(), QStringLiteral("second edit"));
        QVERIFY(!m_window->actions().redo->isEnabled());

        undo->setIndex(0); // back to the demo as shipped
        QCOMPARE(model->data(cell).toString(), original);
    }

    void playbackStepsFrames()
    {
        PlaybackController *playback = m_window->context()->playback();
        playback->setAudioEnabled(false); // no sound device under Xvfb
        m_window->context()->setCurrentFrame(0);
        m_window->actions().playPause->trigger();
        QVERIFY(playback->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->currentFrame() >= 5, 5000);
        QTest::keyClick(m_window, Qt::Key_Space);
        QVERIFY(!playback->isPlaying());
        const int stopped = m_window->context()->currentFrame();
        QTest::qWait(200);
        QCOMPARE(m_window->context()->currentFrame(), stopped);
    }

    // At 1280 x 800 the timeline can be made tall enough for the spectrogram and the waveform
    // to be read; docks do not float off when dragged; View > Panels > Reset Layout brings the
    // default layout back.
    void layoutAt1280x800()
    {
        QCOMPARE(m_window->size(), QSize(1280, 800));
        auto *timeline = m_window->findChild<QDockWidget *>(QStringLiteral("timelineDock"));
        QVERIFY(timeline);
        for (QDockWidget *dock : m_window->findChildren<QDockWidget *>())
            QVERIFY2(!(dock->features() & QDockWidget::DockWidgetFloatable), qPrintable(dock->objectName()));
        m_window->resizeDocks({timeline}, {420}, Qt::Vertical);
        QCoreApplication::processEvents();
        qInfo("timeline dock: %d px tall when asked for 420", timeline->height());
        QVERIFY2(timeline->height() >= 380, qPrintable(QString::number(timeline->height())));

        // Showing the spectrogram at the default height leaves each lane legible.
        m_window->resetLayout();
        QCoreApplication::processEvents();
        QAction *spectrogram = m_window->findChild<TimelinePanel *>()->spectrogramAction();
        bool inViewMenu = false; // View ▸ Show Spectrogram
        for (QMenu *menu : m_window->menuBar()->findChildren<QMenu *>())
            inViewMenu = inViewMenu || menu->actions().contains(spectrogram);
        QVERIFY(inViewMenu);
        spectrogram->setChecked(true);
        QCoreApplication::processEvents();
        WaveformView *view = m_window->waveformView();
        const int waveform = view->laneRect(WaveformView::Lane::Waveform).height();
        const int spectrum = view->laneRect(WaveformView::Lane::Spectrogram).height();
        qInfo("with the spectrogram: waveform %d px, spectrogram %d px", waveform, spectrum);
        QVERIFY2(waveform >= 60 && spectrum >= 60, qPrintable(QStringLiteral("%1 %2").arg(waveform).arg(spectrum)));
        spectrogram->setChecked(false);

        // Reset Layout: every panel back, docked where it starts.
        timeline->hide();
        m_window->resetLayout();
        QVERIFY(timeline->isVisible());
        QCOMPARE(m_window->dockWidgetArea(timeline), Qt::BottomDockWidgetArea);
    }

    // The window lays out the panels' menus: File ▸ Export is ExportMenu's (tst_exportmenu).
    void exportMenuIsInTheFileMenu()
    {
        QMenu *file = nullptr;
        for (QAction *a : m_window->menuBar()->actions())
            if (a->menu() && a->menu()->actions().contains(m_window->exportMenu()->menu()->menuAction()))
                file = a->menu();
        QVERIFY(file);
        QCOMPARE(file->title().remove(QLatin1Char('&')), QStringLiteral("File"));
    }

    // Sound on and no audio device (Xvfb here): playback goes on and the status bar says why.
    void playbackWithoutADeviceSaysSo()
    {
        if (!QMediaDevices::defaultAudioOutput().isNull())
            QSKIP("this machine has an audio output device");
        PlaybackController *playback = m_window->context()->playback();
        playback->setAudioEnabled(true);
        QSignalSpy silent(playback, &PlaybackController::playingSilently);
        m_window->context()->setCurrentFrame(0);
        m_window->actions().playPause->trigger();
        QVERIFY(playback->isPlaying());
        QCOMPARE(silent.count(), 1);
        QVERIFY(silent.first().first().toString().contains(QStringLiteral("no audio output device")));
        const QString shown = m_window->statusBar()->currentMessage();
        QVERIFY2(shown.startsWith(QStringLiteral("Playing without sound")), qPrintable(shown));
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->currentFrame() >= 3, 5000); // the picture still moves
        m_window->actions().playPause->trigger();
        playback->setAudioEnabled(false);
    }

    void savedCopyOfTheDemoOpens()
    {
        QVERIFY(dir.isValid());
        const QString folder = dir.filePath(QStringLiteral("demo-copy"));
        m_window->context()->document()->saveTo(folder);
        QVERIFY(!m_window->context()->document()->isReadOnly());
        QCOMPARE(m_window->context()->document()->folder(), folder);
        QVERIFY(QFileInfo::exists(folder + QStringLiteral("/project.json")));
        const QString media = m_window->context()->document()->mediaPath(0);
        QVERIFY2(media.startsWith(folder) && QFileInfo::exists(media), qPrintable(media));

        QVERIFY(m_window->files()->open(folder));
        QCOMPARE(m_window->sequenceView()->model()->rowCount(), 10);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->currentSequence() == 0, 60000);
        QCOMPARE(m_window->context()->media()->mediaPath, media);
        // The next launch reopens it (the demo, once the demo was opened last).
        QCOMPARE(QDir(RecentProjects::lastSession()).canonicalPath(), QDir(folder).canonicalPath());
    }

    void missingMediaIsReportedAndChangesNothing()
    {
        // The copy saved above is open: take one of its clips away (never the bundled one).
        QVERIFY(m_window->context()->document()->folder().startsWith(QDir::tempPath()));
        const QString media = m_window->context()->document()->mediaPath(3);
        QVERIFY2(media.startsWith(m_window->context()->document()->folder()), qPrintable(media));
        QVERIFY(QFile::remove(media));
        const auto before = m_window->context()->media();
        QSignalSpy ended(m_window->context(), &StudioContext::sequenceLoadEnded);
        m_window->context()->selectSequence(3);
        QTRY_COMPARE_WITH_TIMEOUT(ended.count(), 1, 60000);
        QCOMPARE(ended.first().first().toBool(), false);
        QVERIFY2(ErrorReporter::lastMessage().contains(media), qPrintable(ErrorReporter::lastMessage()));
        QCOMPARE(m_window->context()->media(), before);
        QCOMPARE(m_window->context()->currentSequence(), 0);
        QCOMPARE(m_window->sequenceView()->currentIndex().row(), 0);
        m_window->context()->selectSequence(1); // still usable
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->currentSequence() == 1, 60000);
    }

    // At 1280x800 the window fits the screen's free area, so the status bar (progress, Cancel,
    // guidance) and the Models panel's actions are on screen: with no saved geometry, and with a
    // saved one larger than the screen.
    void fitsTheScreenAt1280x800()
    {
        const QRect screen = m_window->screen()->availableGeometry();
        QVERIFY2(screen.width() <= 1280 && screen.height() <= 800, "run under xvfb-run -s \"-screen 0 1280x800x24\"");
        QSettings().setValue(QStringLiteral("window/geometry"), QByteArray());
        for (const QRect saved : {QRect(), QRect(0, 0, 1600, 1000)}) {
            if (saved.isValid()) {
                MainWindow big;
                big.setGeometry(saved);
                big.show();
                QVERIFY(QTest::qWaitForWindowExposed(&big));
                big.close(); // saves the geometry, as at the end of a session
            }
            MainWindow window;
            window.showAsLastTime();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QTRY_VERIFY(screen.contains(window.frameGeometry()));
            auto onScreen = [&](QWidget *w) {
                return w->isVisible() && screen.contains(QRect(w->mapToGlobal(QPoint(0, 0)), w->size()));
            };
            QVERIFY(onScreen(window.statusBar()));
            const auto buttons = window.findChild<QDockWidget *>(QStringLiteral("modelsDock"))->findChildren<QAbstractButton *>();
            QVERIFY(!buttons.isEmpty());
            for (QAbstractButton *b : buttons)
                if (b->isVisibleTo(window.window()) && !b->text().isEmpty())
                    QVERIFY2(onScreen(b), qPrintable(b->text()));
        }
        QSettings().remove(QStringLiteral("window/geometry"));
    }

    // Help ▸ Keyboard Shortcuts lists the keys the actions really have (menus and panels);
    // Help ▸ User Guide shows the README, whose links open the docs inside it.
    void helpListsShortcutsAndOpensTheGuide()
    {
        const QList<ShortcutRow> rows = ShortcutsDialog::rows(m_window);
        auto has = [&](const QString &action, const QString &keys) {
            return std::any_of(rows.begin(), rows.end(),
                               [&](const ShortcutRow &r) { return r.action == action && r.keys == keys; });
        };
        QVERIFY(has(QStringLiteral("Save"), QKeySequence(QKeySequence::Save).toString(QKeySequence::NativeText)));
        QVERIFY(has(QStringLiteral("Merge with Next"), QStringLiteral("M"))); // the timeline's own
        QSet<QString> unique;
        for (const ShortcutRow &r : rows)
            unique.insert(r.group + r.action);
        QCOMPARE(unique.size(), rows.size());
        ShortcutsDialog dialog(m_window);
        auto *tree = dialog.findChild<QTreeWidget *>();
        int listed = 0;
        for (int g = 0; g < tree->topLevelItemCount(); ++g)
            listed += tree->topLevelItem(g)->childCount();
        QCOMPARE(listed, rows.size());

        auto *guideAction = m_window->findChild<QAction *>(QStringLiteral("userGuideAction"));
        QVERIFY(guideAction);
        guideAction->trigger();
        auto *guide = m_window->findChild<UserGuide *>();
        QVERIFY(guide);
        QTextBrowser *browser = guide->browser();
        QVERIFY2(browser->toPlainText().contains(QStringLiteral("lipsync")), "the README is not shown");
        browser->setSource(QUrl(QStringLiteral("qrc:/guide/docs/models.md")));
        QVERIFY2(browser->toPlainText().contains(QStringLiteral("DPDS")), "docs/models.md is not shown");
        guide->close();
    }

    void aboutNamesPaperAndData()
    {
        const QString about = AboutBox::text();
        for (const char *needle : {"Englebienne", "NIPS 2007", "GRID audio-visual corpus", "CC BY 4.0", "YuNet", LIPSYNC_VERSION})
            QVERIFY2(about.contains(QLatin1String(needle)), needle);
    }

    void badProjectIsReportedAndChangesNothing()
    {
        const int rows = m_window->sequenceView()->model()->rowCount();
        QVERIFY(!m_window->files()->open(QStringLiteral("/nonexistent/project")));
        QVERIFY(ErrorReporter::lastMessage().contains(QStringLiteral("/nonexistent/project")));
        QCOMPARE(m_window->sequenceView()->model()->rowCount(), rows);
        QVERIFY(m_window->context()->media());
    }

    // File ▸ New Project… from a folder of clips with transcripts beside them (as `lipsync project
    // create`): written there, opened, in the recent list; a folder that holds a project or no
    // clips is refused with a message and the open document stays.
    void newProjectFromAFolderOfClips()
    {
        QCOMPARE(m_window->actions().registry->action(QStringLiteral("file/new"))->shortcut(), QKeySequence(QKeySequence::New));
        const QString clips = dir.filePath(QStringLiteral("my-clips"));
        QVERIFY(QDir().mkpath(clips));
        const QString demoMedia = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/");
        for (const char *id : {"bbaf2n", "bgin3a"}) {
            QVERIFY(QFile::copy(demoMedia + QLatin1String(id) + QStringLiteral(".mpg"),
                                clips + QLatin1Char('/') + QLatin1String(id) + QStringLiteral(".mpg")));
            QFile transcript(clips + QLatin1Char('/') + QLatin1String(id) + QStringLiteral(".txt"));
            QVERIFY(transcript.open(QIODevice::WriteOnly));
            transcript.write(id == std::string("bbaf2n") ? "bin blue at f two now\n" : "bin green in three again\n");
        }
        // A damaged clip among them is listed and left out.
        QFile whole(demoMedia + QStringLiteral("bwbg8n.mpg"));
        QVERIFY(whole.open(QIODevice::ReadOnly));
        QFile cut(clips + QStringLiteral("/damaged.mpg"));
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(whole.read(20000));
        cut.close();
        const QString before = m_window->context()->document()->folder();

        // No clips: the task fails, says why, and the open document stays.
        const QString empty = dir.filePath(QStringLiteral("no-clips"));
        QVERIFY(QDir().mkpath(empty));
        Task *failing = m_window->files()->createFromMediaFolder(empty, empty);
        QVERIFY(failing);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->taskRunner()->runningCount(), 0, 30000);
        QVERIFY2(ErrorReporter::lastMessage().contains(QStringLiteral("no media files")),
                 qPrintable(ErrorReporter::lastMessage()));
        QCOMPARE(m_window->context()->document()->folder(), before);
        QVERIFY(!QFileInfo::exists(empty + QStringLiteral("/project.json")));

        QVERIFY(m_window->files()->createFromMediaFolder(clips, clips));
        QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->taskRunner()->runningCount(), 0, 30000);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->document()->folder(), clips, 10000);
        QVERIFY(QFileInfo::exists(clips + QStringLiteral("/project.json")));
        QVERIFY(!m_window->context()->document()->isReadOnly());
        QVERIFY(!m_window->context()->document()->isModified());
        QCOMPARE(m_window->sequenceView()->model()->rowCount(), 2);
        QVERIFY2(ErrorReporter::lastMessage().contains(QStringLiteral("damaged.mpg")),
                 qPrintable(ErrorReporter::lastMessage()));
        // A project of one's own: its speaker is nobody the shipped model knows, so it says the
        // generic aligner, adapted to the speaker, and the studio says so.
        QCOMPARE(m_window->context()->document()->project().aligner, std::string(Project::kGenericAligner));
        if (SphinxAligner::available())
            QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("Generic US English, adapted")),
                     qPrintable(m_window->statusBar()->currentMessage()));
        QCOMPARE(m_window->context()->document()->sequence(1).transcript, std::string("bin green in three again"));
        QCOMPARE(m_window->context()->document()->sequence(0).frameCount, 75);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->currentSequence() == 0, 60000);
        QCOMPARE(QSettings().value(QStringLiteral("recentProjects")).toStringList().value(0), clips);

        // Again into the same folder: refused, nothing changes.
        QVERIFY(!m_window->files()->createFromMediaFolder(clips, clips));
        QVERIFY(ErrorReporter::lastMessage().contains(QStringLiteral("already holds a project")));
        QCOMPARE(RecentProjects::lastSession(), clips);
        // The demo opened last: the next launch opens the demo.
        QVERIFY(m_window->files()->openDemo());
        QVERIFY(RecentProjects::lastSession().isEmpty());
    }

private:
    MainWindow *m_window = nullptr;
    QTemporaryDir dir; // the saved copy of the demo
};

QTEST_MAIN(TestMainWindow)
#include "tst_mainwindow.moc"
