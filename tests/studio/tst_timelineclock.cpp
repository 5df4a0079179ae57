// The studio on recordings whose frames are not every 1/25 s from 0 (tests/data/media/timing): a
// variable frame rate and sound that starts 0.5 s after the picture. A project made from them
// records every frame's time; a click on the timeline shows the frame on screen at that moment
// (not time x fps); the transport shows the frame's own time; the player maps its clock to the
// same frames; the frame-label strip has one label per frame, voted over its time on screen, and
// aligning the late sound puts its words 0.5 s after the picture's start.
#include "DemoWindow.h"

#include "app/TransportBar.h"
#include "align/FrameLabels.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "project/Project.h"
#include "timeline/WaveformView.h"

#include <QFile>
#include <QLabel>
#include <QTableView>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;

namespace {
const QString kTiming = QStringLiteral(LIPSYNC_SOURCE_DIR "/tests/data/media/timing/");
const QString kTranscript = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.align");
} // namespace

class TestTimelineClock : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void framesAtTheirOwnTimes()
    {
        QTemporaryDir media, projectDir;
        for (const QString stem : {"audio_late_0.5s", "vfr"}) {
            QVERIFY(QFile::copy(kTiming + stem + ".mp4", media.filePath(stem + ".mp4")));
            QVERIFY(QFile::copy(kTranscript, media.filePath(stem + ".align")));
        }
        Project made = Project::fromMediaFolder(media.path().toStdString(), projectDir.path().toStdString());
        QCOMPARE(int(made.sequences.size()), 2);
        const Sequence &vfrSequence = made.sequences[1];
        QVERIFY(vfrSequence.clock().isVariable());
        QCOMPARE(vfrSequence.frameCount, 51);
        made.saveAs(projectDir.path().toStdString());
        QFile manifest(projectDir.filePath("project.json"));
        QVERIFY(manifest.open(QIODevice::ReadOnly));
        QVERIFY(manifest.readAll().contains("\"frameTimes\""));
        manifest.close();

        MainWindow *window = nullptr;
        testing::openDemoWindow(window);
        if (QTest::currentTestFailed())
            return;
        const std::unique_ptr<MainWindow> owner(window);
        window->context()->playback()->setAudioEnabled(false);
        QVERIFY(window->files()->open(projectDir.path()));
        window->sequenceView()->selectRow(1);
        QTRY_VERIFY_WITH_TIMEOUT(window->context()->media() && window->context()->media()->sequenceId == "vfr", 60000);
        testing::waitForTasks(window);
        const FrameClock &clock = window->context()->media()->clock;
        QVERIFY(clock.isVariable());
        QCOMPARE(window->context()->media()->frameCount(), 51);

        // Frame 22 (1.16 s) stays on screen until frame 23 at 1.52 s: a click at 1.3 s shows it.
        WaveformView *view = window->waveformView();
        QVERIFY(view->xAt(1.3) > 0 && view->xAt(1.3) < view->width());
        const int y = view->laneRect(WaveformView::Lane::Waveform).center().y();
        QTest::mouseClick(view, Qt::LeftButton, {}, QPoint(int(std::lround(view->xAt(1.3))), y));
        QCOMPARE(window->context()->currentFrame(), 22);
        QVERIFY(std::abs(clock.time(22) - 1.16) < 1e-6);
        auto *transport = window->findChild<TransportBar *>();
        QVERIFY(transport);
        bool shown = false;
        for (QLabel *label : transport->findChildren<QLabel *>())
            shown = shown || label->text().startsWith(QLocale().toString(1.16, 'f', 2));
        QVERIFY2(shown, "the transport shows the frame's own time");
        // The player's clock picks the same frames.
        QCOMPARE(window->context()->playback()->frames().frameAt(1.3), 22);
        QCOMPARE(window->context()->playback()->frames().frameAt(1.52), 23);
        // Aligned: one label per frame, the long frame voted over its whole time on screen.
        window->findChild<TimelinePanel *>()->alignSequence();
        testing::waitForTasks(window);
        QCOMPARE(int(view->frameLabels().size()), 51);
        const Sequence &vfr = window->context()->document()->sequence(1);
        QCOMPARE(view->frameLabels(), voteFrameLabels(vfr.phones, clock));
        QVERIFY(voteFrameLabels(vfr.phones, FrameClock::uniform(25.0, 51)) != view->frameLabels());

        // The late sound: its words start 0.5 s later than in the clean clip (GRID's "bin" at
        // 0.95 s in bbaf2n).
        window->sequenceView()->selectRow(0);
        QTRY_VERIFY_WITH_TIMEOUT(window->context()->media() && window->context()->media()->sequenceId == "audio_late_0.5s", 60000);
        testing::waitForTasks(window);
        window->findChild<TimelinePanel *>()->alignSequence();
        testing::waitForTasks(window);
        const Tier &words = window->context()->document()->sequence(0).words;
        int bin = -1;
        for (size_t i = 0; i < words.intervals.size(); ++i)
            if (words.intervals[i].label == "bin")
                bin = int(i);
        QVERIFY(bin >= 0);
        QVERIFY2(std::abs(words.intervals[size_t(bin)].start - 1.45) < 0.03,
                 qPrintable(QString::number(words.intervals[size_t(bin)].start)));
    }
};

QTEST_MAIN(TestTimelineClock)
#include "tst_timelineclock.moc"
