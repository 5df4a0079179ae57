// The Live view on a copy of the demo project, without a microphone: the sound of a demo clip
// (pbav2n, 2.96 s) is fed from code through the same pipeline a microphone feeds.
//  - Before a dynamic model is trained the view says to train one and offers no Start; a DPDS
//    model trained in the Models panel is then preselected.
//  - Fed at real-time pace, the session shows one frame per 1/25 s of sound (74), the phone
//    strip holds recognised phones and the latency read-out a number of milliseconds.
//  - Save as Sequence adds one sequence live_0001 (74 frames, the AAM's feature dimension, a
//    phone tier, its sound as a WAV in the project's live folder) as one undo step; Undo
//    removes it.
//  - Export Video writes an MP4 of 74 frames with sound.
//  - Over a camera's pictures the face is drawn where the face is found in them; without, into the
//    still again.
//  - Hiding the view stops a running session; closing the window with a session running
//    neither hangs nor crashes.
//  - With the timeline aligning with CMU Sphinx, its US-English recogniser hears the phones (the
//    view says so): the same clip gives its 74 frames and recognised phones, some of them speech;
//    a Sphinx model folder that is not there is said instead of offering Start. Skipped without
//    pocketsphinx-en-us.
// LIPSYNC_PREVIEW_SHOT=DIR keeps pictures of the window with the Live view (at its 1280x800 and,
// where the screen is large enough, at 1920x1080).
#include "../SanitizedBuild.h"
#include "DemoWindow.h"

#include "annotate/FrameView.h"
#include "app/DemoProject.h"
#include "app/MainWindow.h"
#include "build/ModelsPanel.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "live/LiveController.h"
#include "live/LiveView.h"
#include "live/PhoneStrip.h"

#include "aam/AamModel.h"
#include "align/SphinxAligner.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/VideoReader.h"
#include "live/CameraFeed.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QMenuBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QScreen>
#include <QSignalSpy>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <cmath>

#include <opencv2/imgproc.hpp>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");

void saveShot(QWidget *window, const QString &name)
{
    if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
        window->grab().save(dir + QLatin1Char('/') + name);
}

} // namespace

class TestLiveView : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    LiveView *live() const { return m_window->liveView(); }
    LiveController *controller() const { return live()->controller(); }

    // Feeds `samples` in blocks of 40 ms, one block per 40 ms, as a microphone would.
    void feedAtRealTime(const std::vector<float> &samples, std::size_t end)
    {
        const std::size_t block = 640;
        for (std::size_t at = 0; at < end; at += block) {
            const std::size_t n = std::min(block, end - at);
            controller()->feed(std::vector<float>(samples.begin() + std::ptrdiff_t(at),
                                                  samples.begin() + std::ptrdiff_t(at + n)));
            QTest::qWait(40);
        }
    }

    bool startFed()
    {
        if (!live()->startWithFedSound())
            return false;
        return QTest::qWaitFor([this] { return controller()->state() == LiveController::State::Running; }, 60000);
    }

    MainWindow *m_window = nullptr;
    QTemporaryDir m_dir;
    QString m_project;
    std::vector<float> m_sound;
    int m_frames = 0; // of the last session

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_sound = AudioDecoder::decode((kDemo + "/media/pbav2n.mpg").toStdString(), 16000).samples;
        QVERIFY(m_sound.size() > 40000);
        m_project = m_dir.filePath(QStringLiteral("project"));
        QVERIFY(testing::copyFolder(kDemo, m_project));
        testing::openWindowOnProject(m_window, m_project);
    }

    void cleanupTestCase()
    {
        // Closed with a session running: the worker thread ends with the window.
        if (m_window && live()->isVisible() && startFed()) {
            controller()->feed(std::vector<float>(m_sound.begin(), m_sound.begin() + 16000));
            QTest::qWait(100);
        }
        delete m_window;
    }

    void viewMenuShowsTheLiveTab()
    {
        QAction *show = m_window->findChild<QAction *>(QStringLiteral("showLiveAction"));
        QVERIFY(show);
        QMenu *view = m_window->menuBar()->actions().value(2)->menu();
        QVERIFY(view && view->actions().contains(show));
        auto *tabs = m_window->findChild<QTabWidget *>();
        QVERIFY(tabs && tabs->indexOf(live()) >= 0);
        QVERIFY(!live()->isVisible());
        show->trigger();
        QCOMPARE(tabs->currentWidget(), live());
        QVERIFY(live()->isVisible());
    }

    void saysToTrainAModelFirst()
    {
        QVERIFY(m_window->context()->modelStore()->aam());
        QVERIFY(controller()->trainedKinds().isEmpty());
        QVERIFY(!live()->startButton()->isEnabled());
        QVERIFY(!live()->saveButton()->isEnabled());
        QVERIFY(!live()->exportButton()->isEnabled());
        QVERIFY2(live()->recogniserLabel()->text().contains(QStringLiteral("HMMs")),
                 qPrintable(live()->recogniserLabel()->text()));
        // Said where the face would be.
        QVERIFY2(live()->face()->placeholderText().contains(QStringLiteral("Train one in the Models panel")),
                 qPrintable(live()->face()->placeholderText()));
        QVERIFY(live()->face()->image().isNull());
        QVERIFY(!live()->startWithFedSound());
        QCOMPARE(controller()->state(), LiveController::State::Idle);
        // The refused start says why once, not the problem twice.
        QCOMPARE(live()->face()->placeholderText().count(QStringLiteral("Train one in the Models panel")), 1);
        saveShot(m_window, QStringLiteral("live-untrained.png"));
    }

    void trainedDpdsIsPreselected()
    {
        ModelsPanel *models = m_window->modelsPanel();
        for (const QString &k : ModelKinds::ids())
            models->kindCheck(k)->setChecked(k == QLatin1String("hmm") || k == QLatin1String("dpds"));
        QTest::mouseClick(models->trainButton(), Qt::LeftButton);
        testing::waitForTasks(m_window);
        QVERIFY(m_window->context()->modelStore()->dynamicModel(QStringLiteral("dpds")));
        QCOMPARE(controller()->trainedKinds().size(), 2);
        QCOMPARE(live()->modelCombo()->count(), 2);
        QCOMPARE(live()->chosenKind(), QStringLiteral("dpds"));
        QVERIFY(controller()->problem(QStringLiteral("dpds")).isEmpty());
        // Trained with phones in context (the panel's default), its face does not wait for every
        // phone to end (Live guesses the context of a phone that runs long), and the view has no
        // warning.
        QVERIFY(controller()->waitsForPhones(QStringLiteral("dpds")) == false);
        QVERIFY2(!live()->face()->placeholderText().contains(QStringLiteral("phones in context")),
                 qPrintable(live()->face()->placeholderText()));
    }

    void showsTheFaceAsTheSoundComes()
    {
        QVERIFY(startFed());
        QCOMPARE(controller()->sampleRate(), 16000);
        QVERIFY(live()->stopButton()->isEnabled());
        QVERIFY(!live()->startButton()->isEnabled());
        const std::size_t half = m_sound.size() / 2;
        feedAtRealTime(m_sound, half);
        QTRY_VERIFY_WITH_TIMEOUT(controller()->framesShown() > 20, 20000);
        QVERIFY(!live()->face()->image().isNull());
        saveShot(m_window, QStringLiteral("live-running.png"));
        feedAtRealTime(std::vector<float>(m_sound.begin() + std::ptrdiff_t(half), m_sound.end()), m_sound.size() - half);
        live()->stopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Idle, 30000);

        // One frame per 1/25 s of sound.
        const int expected = int(std::lround(double(m_sound.size()) / 16000 * 25));
        QCOMPARE(expected, 74);
        QCOMPARE(controller()->frameRate(), 25.0);
        QCOMPARE(controller()->framesShown(), expected);
        QCOMPARE(controller()->recordedFrames(), expected);
        m_frames = expected;
        QVERIFY(!live()->face()->image().isNull());
        // Recognised phones in the strip, some of them speech.
        const QStringList phones = live()->phoneStrip()->visibleLabels();
        QVERIFY2(phones.size() >= 5, qPrintable(phones.join(u' ')));
        QVERIFY(phones.contains(QStringLiteral("sil")) || phones.size() > 5);
        // The latency read-out: a number of milliseconds, and it is sane.
        const QRegularExpression latency(QStringLiteral("^Latency: (\\d+) ms mean, (\\d+) ms max$"));
        const QRegularExpressionMatch m = latency.match(live()->latencyLabel()->text());
        QVERIFY2(m.hasMatch(), qPrintable(live()->latencyLabel()->text()));
        QVERIFY(m.captured(1).toInt() > 0 && m.captured(1).toInt() <= m.captured(2).toInt());
        // Under the sanitizers the recogniser runs several times slower than real time on a shared
        // machine (3.2 s mean there), so the bound is only that of a number in milliseconds.
#ifdef LIPSYNC_SANITIZED_BUILD
        constexpr int kSaneMeanLatencyMs = 20000;
#else
        constexpr int kSaneMeanLatencyMs = 2000;
#endif
        QVERIFY2(m.captured(1).toInt() < kSaneMeanLatencyMs, qPrintable(live()->latencyLabel()->text()));
        QVERIFY(controller()->algorithmicLatency() > 0);
        qInfo("%s (of which %.0f ms algorithmic)", qPrintable(live()->latencyLabel()->text()),
              1000 * controller()->algorithmicLatency());
        // The window fits the smallest screen the studio is made for.
        QVERIFY2(m_window->width() <= 1280, qPrintable(QString::number(m_window->width())));
        QVERIFY(live()->saveButton()->isEnabled());
        QVERIFY(live()->exportButton()->isEnabled());
        QVERIFY(live()->startButton()->isEnabled() || live()->microphoneCombo()->currentData().isNull());
        saveShot(m_window, QStringLiteral("live.png"));
        if (!qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT").isEmpty()) {
            const QSize screen = m_window->screen()->availableSize();
            if (screen.width() >= 1920 && screen.height() >= 1080) {
                const QSize before = m_window->size();
                m_window->resize(1920, 1080);
                QTest::qWait(200);
                saveShot(m_window, QStringLiteral("live-1920.png"));
                m_window->resize(before);
                QTest::qWait(200);
            }
        }
    }

    // "A recording…" in the microphone list: a file's sound drives the face at its own pace, and
    // the session ends by itself when the sound does, its recording kept like a spoken one.
    void playsARecording()
    {
        QComboBox *inputs = live()->microphoneCombo();
        QVERIFY(inputs->isEnabled());
        const int file = inputs->findData(QByteArray(LiveView::kFileInput));
        QVERIFY(file >= 0);
        inputs->setCurrentIndex(file);
        QVERIFY(live()->startButton()->isEnabled());
        const QString clip = QDir(DemoProject::locate()).filePath(QStringLiteral("media/pbav2n.mpg"));
        QVERIFY(live()->startWithFile(clip, false));
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Running, 30000);
        QCOMPARE(controller()->input(), LiveController::Input::File);
        QVERIFY2(live()->messageLabel()->text().contains(QStringLiteral("pbav2n.mpg")) ||
                     live()->face()->placeholderText().contains(QStringLiteral("pbav2n.mpg")),
                 qPrintable(live()->face()->placeholderText()));
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Idle, 30000); // by itself
        QCOMPARE(controller()->recordedFrames(), 74); // 2.98 s at 25 frames/s, as spoken
        QVERIFY(controller()->hasRecording());
        // A file without sound is refused with its name.
        QTemporaryDir dir;
        const QString silent = dir.filePath(QStringLiteral("silent.wav"));
        QFile empty(silent);
        QVERIFY(empty.open(QIODevice::WriteOnly));
        empty.write("not a wav");
        empty.close();
        QSignalSpy failed(controller(), &LiveController::failed);
        QVERIFY(live()->startWithFile(silent, false));
        QTRY_COMPARE_WITH_TIMEOUT(failed.count(), 1, 30000);
        QVERIFY2(failed.first().first().toString().contains(QStringLiteral("silent.wav")),
                 qPrintable(failed.first().first().toString()));
        QTRY_COMPARE(controller()->state(), LiveController::State::Idle);
        inputs->setCurrentIndex(0);
    }

    void savesTheSessionAsASequence()
    {
        ProjectDocument *doc = m_window->context()->document();
        QUndoStack *undo = m_window->context()->undoStack();
        const int count = doc->sequenceCount();
        const int undoIndex = undo->index();
        QSignalSpy saved(live(), &LiveView::sequenceSaved);
        live()->saveButton()->click();
        QCOMPARE(saved.count(), 1);
        QCOMPARE(saved.first().first().toString(), QStringLiteral("live_0001"));
        QCOMPARE(doc->sequenceCount(), count + 1);
        QCOMPARE(undo->index(), undoIndex + 1);
        QCOMPARE(undo->undoText(), QStringLiteral("Save Live Session as live_0001"));
        const Sequence &s = doc->sequence(count);
        QCOMPARE(QString::fromStdString(s.id), QStringLiteral("live_0001"));
        QCOMPARE(s.frameCount, m_frames);
        QCOMPARE(s.frameRate, 25.0);
        QVERIFY(s.transcript.empty());
        QCOMPARE(int(s.features.rows()), m_frames);
        QCOMPARE(int(s.features.cols()), m_window->context()->modelStore()->aam()->combinedModes());
        QVERIFY(s.features.allFinite());
        QVERIFY(!s.phones.isEmpty());
        QVERIFY(!s.phones.defect());
        const QString wav = doc->mediaPath(count);
        QCOMPARE(wav, QDir(m_project).filePath(QStringLiteral("live/live_0001.wav")));
        QVERIFY(QFileInfo(wav).isFile());
        const MediaInfo info = MediaInfo::probe(wav.toStdString());
        QVERIFY(info.hasAudio);
        QVERIFY(std::abs(info.audioDuration - double(m_sound.size()) / 16000) < 0.01);

        undo->undo();
        QCOMPARE(doc->sequenceCount(), count);
        QCOMPARE(undo->index(), undoIndex);
        QVERIFY(QFileInfo(wav).isFile()); // kept for the redo
        undo->redo();
        QCOMPARE(doc->sequenceCount(), count + 1);
        undo->undo();
        QCOMPARE(doc->sequenceCount(), count);
    }

    void exportsTheSessionAsVideo()
    {
        const QString path = m_dir.filePath(QStringLiteral("live.mp4"));
        QString why;
        QSignalSpy ended(controller(), &LiveController::exportEnded);
        Task *task = controller()->exportVideo(path, &why);
        QVERIFY2(task, qPrintable(why));
        QVERIFY(!live()->startButton()->isEnabled());
        QVERIFY(!live()->exportButton()->isEnabled());
        QTRY_COMPARE_WITH_TIMEOUT(ended.count(), 1, 60000);
        QCOMPARE(ended.first().first().toString(), path);
        const MediaInfo info = MediaInfo::probe(path.toStdString());
        QCOMPARE(info.frameCount, m_frames);
        QVERIFY(info.hasAudio);
        QVERIFY(live()->exportButton()->isEnabled());
    }

    // A camera's pictures (here a GRID frame of another clip at twice the size, handed in as a
    // camera delivers them): the face is drawn over each picture where the face is found in it,
    // the picture left as it is away from the face; without pictures, into the still again.
    void drawsOverTheCamerasPicture()
    {
        QVERIFY(live()->cameraCombo()->count() >= 1);
        QCOMPARE(live()->cameraCombo()->itemText(0), QStringLiteral("No camera"));
        VideoReader clip((kDemo + "/media/bbaf2n.mpg").toStdString());
        cv::Mat frame;
        cv::resize(clip.frame(30), frame, cv::Size(), 2.0, 2.0, cv::INTER_CUBIC);
        const QImage picture =
            QImage(frame.data, frame.cols, frame.rows, int(frame.step), QImage::Format_BGR888).copy();
        controller()->camera()->setFrame(picture);
        QVERIFY(startFed());
        feedAtRealTime(m_sound, m_sound.size() / 2);
        QTRY_VERIFY_WITH_TIMEOUT(controller()->framesShown() > 20, 20000);
        const QImage shown = controller()->lastImage().convertToFormat(QImage::Format_BGR888);
        QCOMPARE(shown.size(), picture.size());
        QCOMPARE(shown.pixel(10, 10), picture.pixel(10, 10)); // the background, untouched
        // Around the mouth (the lower middle of the face) the generated face differs from the
        // camera's own.
        const QRect mouth(300, 400, 120, 60);
        double difference = 0;
        for (int y = mouth.top(); y <= mouth.bottom(); ++y)
            for (int x = mouth.left(); x <= mouth.right(); ++x)
                difference += std::abs(qGray(shown.pixel(x, y)) - qGray(picture.pixel(x, y)));
        difference /= mouth.width() * mouth.height();
        QVERIFY2(difference > 1.0, qPrintable(QString::number(difference)));
        saveShot(m_window, QStringLiteral("live-camera.png"));
        live()->stopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Idle, 30000);
        // No camera: the still of the person (the demo's 360 x 288) again.
        controller()->camera()->close();
        QVERIFY(startFed());
        feedAtRealTime(m_sound, 16000);
        QTRY_VERIFY_WITH_TIMEOUT(controller()->framesShown() > 5, 20000);
        QCOMPARE(controller()->lastImage().size(), QSize(360, 288));
        live()->stopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Idle, 30000);
    }

    void hidingTheViewStopsTheSession()
    {
        QVERIFY(startFed());
        feedAtRealTime(m_sound, 8000);
        auto *tabs = m_window->findChild<QTabWidget *>();
        tabs->setCurrentIndex(0);
        QVERIFY(!live()->isVisible());
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Idle, 30000);
        QCOMPARE(controller()->recordedFrames(), 13); // 0.5 s at 25 fps
        tabs->setCurrentWidget(live());
        QVERIFY(live()->isVisible());
    }

    void recognisesWithSphinxWhenTheTimelineAlignsWithIt()
    {
        if (!SphinxAligner::available({}))
            QSKIP("CMU Sphinx's US-English models are not installed (Debian package pocketsphinx-en-us)");
        ModelStore *store = m_window->context()->modelStore();
        const AlignerChoice before = store->alignerChoice();
        QVERIFY(!before.isSphinx());
        const auto restore = qScopeGuard([store, before] { store->setAlignerChoice(before); });
        const QString kind = QStringLiteral("dpds");

        // A model folder that is not there: said instead of offering Start.
        const std::string missing = m_dir.filePath(QStringLiteral("no-sphinx")).toStdString();
        store->setAlignerChoice(AlignerChoice{"sphinx:" + missing, false});
        QVERIFY2(controller()->problem(kind).contains(QStringLiteral("pocketsphinx-en-us")),
                 qPrintable(controller()->problem(kind)));
        QVERIFY(!live()->startButton()->isEnabled());

        store->setAlignerChoice(AlignerChoice{"sphinx", false});
        QVERIFY2(controller()->problem(kind).isEmpty(), qPrintable(controller()->problem(kind)));
        QVERIFY(controller()->recognisesWithSphinx());
        QVERIFY2(live()->recogniserLabel()->text().contains(QStringLiteral("CMU Sphinx")),
                 qPrintable(live()->recogniserLabel()->text()));
        QVERIFY(startFed());
        QCOMPARE(controller()->sampleRate(), 16000);
        feedAtRealTime(m_sound, m_sound.size());
        QTRY_VERIFY_WITH_TIMEOUT(controller()->framesShown() > 20, 20000);
        saveShot(m_window, QStringLiteral("live-sphinx.png"));
        live()->stopButton()->click();
        QTRY_COMPARE_WITH_TIMEOUT(controller()->state(), LiveController::State::Idle, 30000);
        QCOMPARE(controller()->framesShown(), 74);
        QCOMPARE(controller()->recordedFrames(), 74);
        QVERIFY(!live()->face()->image().isNull());
        const QStringList phones = live()->phoneStrip()->visibleLabels();
        QVERIFY2(phones.size() >= 5, qPrintable(phones.join(u' ')));
        QVERIFY2(phones.size() > phones.count(QStringLiteral("sil")) + 2, qPrintable(phones.join(u' ')));
        qInfo("Sphinx: %s; %s", qPrintable(phones.join(u' ')), qPrintable(live()->latencyLabel()->text()));
        QVERIFY2(live()->recogniserLabel()->text().contains(QStringLiteral("CMU Sphinx")),
                 qPrintable(live()->recogniserLabel()->text()));

        store->setAlignerChoice(before);
        QVERIFY(!controller()->recognisesWithSphinx());
        QVERIFY2(live()->recogniserLabel()->text().contains(QStringLiteral("HMMs")),
                 qPrintable(live()->recogniserLabel()->text()));
    }
};

QTEST_MAIN(TestLiveView)
#include "tst_liveview.moc"
