// The landmark editor on the Annotate tab, driven through the real widgets: clicks place points
// in scheme order, a drag is one undo step (undo restores the point exactly, redo re-applies) and
// makes the point Fixed, Delete undefines a point, C copies the previous frame's points, O toggles
// the onion skin; automatic detection gives 23 Automatic points on the face; an AAM built from
// labelled frames (and the demo's shipped AAM) tracks a whole clip into per-frame features, undone
// in one step; W walks the worst fits; the modes view synthesises a face per mode.
#include "DemoWindow.h"

#include "aam/AamModel.h"
#include "aam/PtsFile.h"
#include "annotate/FacesController.h"
#include "annotate/FrameView.h"
#include "app/MainWindow.h"
#include "app/ProjectFiles.h"
#include "build/ModesView.h"
#include "context/ErrorReporter.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QDir>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QStatusBar>
#include <QTest>
#include <QUndoStack>

#include <cmath>
#include <set>

using namespace lipsync;
using namespace lipsync::studio;
using lipsync::studio::testing::openDemoWindow;

class TestLandmarkEditor : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private:
    MainWindow *m_window = nullptr;

    FrameView *view() const { return m_window->frameView(); }
    std::optional<LandmarkSet> landmarksAt(int frame) const
    {
        const Sequence &s = m_window->context()->document()->sequence(m_window->context()->currentSequence());
        const auto it = s.landmarks.find(frame);
        return it != s.landmarks.end() ? std::optional<LandmarkSet>(it->second) : std::nullopt;
    }
    QPoint widgetPoint(double x, double y) const { return view()->imageToWidget(QPointF(x, y)).toPoint(); }

private slots:
    void initTestCase()
    {
        openDemoWindow(m_window);
        if (QTest::currentTestFailed())
            return;
        QVERIFY(view()->isEditable());
    }

    void cleanupTestCase() { delete m_window; }

    void clicksPlacePointsInSchemeOrder()
    {
        m_window->context()->setCurrentFrame(5);
        QVERIFY(!landmarksAt(5));
        QUndoStack *undo = m_window->context()->undoStack();
        const int before = undo->count();
        const QList<QPointF> targets{{150, 120}, {160, 115}, {170, 120}};
        for (const QPointF &t : targets)
            QTest::mouseClick(view(), Qt::LeftButton, {}, widgetPoint(t.x(), t.y()));
        QCOMPARE(undo->count(), before + 3);
        const std::optional<LandmarkSet> set = landmarksAt(5);
        QVERIFY(set);
        QCOMPARE(set->definedCount(), 3);
        const double tolerance = 1.0 / view()->zoom(); // one widget pixel in image pixels, and more
        for (int i = 0; i < 3; ++i) {
            const LandmarkPoint &p = set->points[std::size_t(i)];
            QCOMPARE(p.state, PointState::Placed);
            QVERIFY2(std::abs(p.x - targets[i].x()) <= tolerance && std::abs(p.y - targets[i].y()) <= tolerance,
                     qPrintable(QStringLiteral("point %1 at %2,%3").arg(i).arg(p.x).arg(p.y)));
        }
        QCOMPARE(view()->nextUndefinedPoint(), 3);
        QCOMPARE(m_window->context()->document()->sequence(0).landmarks.size(), std::size_t(1));
    }

    void dragIsOneUndoStepAndFixesThePoint()
    {
        QUndoStack *undo = m_window->context()->undoStack();
        const LandmarkSet before = *landmarksAt(5);
        const LandmarkPoint p1 = before.points[1];
        const int count = undo->count();
        const QPoint start = widgetPoint(p1.x, p1.y);
        QTest::mousePress(view(), Qt::LeftButton, {}, start);
        QTest::mouseMove(view(), start + QPoint(10, 4));
        QTest::mouseMove(view(), start + QPoint(20, 8));
        QTest::mouseMove(view(), start + QPoint(30, 12));
        QTest::mouseRelease(view(), Qt::LeftButton, {}, start + QPoint(30, 12));
        QCOMPARE(undo->count(), count + 1); // the whole drag
        const LandmarkSet after = *landmarksAt(5);
        QCOMPARE(after.points[1].state, PointState::Fixed);
        const QPointF moved = view()->widgetToImage(QPointF(start + QPoint(30, 12)));
        QVERIFY(std::abs(after.points[1].x - moved.x()) < 1e-6 && std::abs(after.points[1].y - moved.y()) < 1e-6);
        QCOMPARE(after.points[0], before.points[0]);
        QCOMPARE(after.points[2], before.points[2]);

        undo->undo();
        QCOMPARE(*landmarksAt(5), before); // exactly, state included
        QCOMPARE(*view()->landmarks(), before);
        undo->redo();
        QCOMPARE(*landmarksAt(5), after);
        QCOMPARE(*view()->landmarks(), after);
    }

    void deleteUndefinesTheSelectedPoint()
    {
        QUndoStack *undo = m_window->context()->undoStack();
        const LandmarkSet before = *landmarksAt(5);
        const LandmarkPoint p2 = before.points[2];
        QTest::mouseClick(view(), Qt::LeftButton, {}, widgetPoint(p2.x, p2.y)); // selects, places nothing
        QCOMPARE(*landmarksAt(5), before);
        QCOMPARE(view()->selectedPoint(), 2);
        QTest::keyClick(view(), Qt::Key_Delete);
        QVERIFY(!landmarksAt(5)->points[2].isDefined());
        QCOMPARE(view()->nextUndefinedPoint(), 2); // the next click fills the gap
        undo->undo();
        QCOMPARE(*landmarksAt(5), before);
    }

    void copyPreviousFrameAndOnionSkin()
    {
        const LandmarkSet source = *landmarksAt(5);
        m_window->context()->setCurrentFrame(6);
        QVERIFY(!landmarksAt(6));
        QTest::keyClick(m_window, Qt::Key_C);
        const std::optional<LandmarkSet> copy = landmarksAt(6);
        QVERIFY(copy);
        QCOMPARE(copy->definedCount(), source.definedCount());
        for (int i = 0; i < LandmarkSet::kPointCount; ++i) {
            QCOMPARE(copy->points[std::size_t(i)].x, source.points[std::size_t(i)].x);
            QCOMPARE(copy->points[std::size_t(i)].isDefined(), source.points[std::size_t(i)].isDefined());
        }
        m_window->context()->undoStack()->undo();
        QVERIFY(!landmarksAt(6));
        QVERIFY(!view()->landmarks());

        QVERIFY(!view()->isOnionSkinVisible());
        const QImage without = view()->grab().toImage();
        QTest::keyClick(m_window, Qt::Key_O);
        QVERIFY(view()->isOnionSkinVisible());
        const QImage with = view()->grab().toImage();
        QVERIFY(with != without); // frame 5's points drawn over frame 6
        QTest::keyClick(m_window, Qt::Key_O);
        QVERIFY(!view()->isOnionSkinVisible());
    }

    void detectionGivesAutomaticPointsOnTheFace()
    {
        m_window->context()->setCurrentFrame(10);
        const int index = m_window->context()->undoStack()->index();
        QVERIFY(testing::waitFor(m_window->faces()->detectLandmarks()));
        QCOMPARE(m_window->context()->undoStack()->index(), index + 1);
        const std::optional<LandmarkSet> set = landmarksAt(10);
        QVERIFY(set);
        QVERIFY(set->isComplete());
        const QImage &image = m_window->context()->media()->frames[10];
        double cx = 0, cy = 0;
        for (const LandmarkPoint &p : set->points) {
            QCOMPARE(p.state, PointState::Automatic);
            QVERIFY(p.x >= 0 && p.y >= 0 && p.x < image.width() && p.y < image.height());
            cx += p.x / LandmarkSet::kPointCount;
            cy += p.y / LandmarkSet::kPointCount;
        }
        // GRID s1 sits in the middle of the 360x288 frame; the eyes are apart by a face's width.
        QVERIFY2(cx > 0.3 * image.width() && cx < 0.7 * image.width() && cy > 0.3 * image.height()
                     && cy < 0.8 * image.height(),
                 qPrintable(QStringLiteral("centroid %1,%2").arg(cx).arg(cy)));
        const double eyes = std::hypot(set->points[6].x - set->points[0].x, set->points[6].y - set->points[0].y);
        QVERIFY2(eyes > 30 && eyes < 150, qPrintable(QStringLiteral("eye distance %1").arg(eyes)));
        QVERIFY(set->points[0].x < set->points[6].x);             // image-left eye on the left
        QVERIFY(set->points[20].y > set->points[10].y);            // chin below the upper lip
        // For looking at: the Annotate tab with the detected points (and the onion skin of 9).
        if (const QByteArray dir = qgetenv("LIPSYNC_SCREENSHOT_DIR"); !dir.isEmpty()) {
            view()->setZoom(2.0, view()->imageToWidget(QPointF(cx, cy)));
            m_window->grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("annotate-landmarks.png")));
            view()->fitToView();
        }
        m_window->context()->undoStack()->undo();
        QVERIFY(!landmarksAt(10));
        m_window->context()->undoStack()->redo();
        QVERIFY(landmarksAt(10));

        // N skips labelled frames: from 9, frame 10 is complete, 11 is not.
        m_window->context()->setCurrentFrame(9);
        QTest::keyClick(m_window, Qt::Key_N);
        QCOMPARE(m_window->context()->currentFrame(), 11);
    }

    // Faces > Pick Frames to Label: diverse frames across the clips get automatic points in one
    // undo step, and Shift+W walks them, the most doubtful first, loading other clips on the way.
    void pickedFramesAreLabelledAndReviewedWorstFirst()
    {
        ProjectDocument *doc = m_window->context()->document();
        auto labelled = [doc] {
            std::set<std::pair<std::string, int>> out;
            for (int row = 0; row < doc->sequenceCount(); ++row)
                for (const auto &[frame, set] : doc->sequence(row).landmarks)
                    out.insert({doc->sequence(row).id, frame});
            return out;
        };
        const auto before = labelled();
        const int index = m_window->context()->undoStack()->index();
        const int startRow = m_window->context()->currentSequence(), startFrame = m_window->context()->currentFrame();
        QVERIFY(m_window->faces()->pickFramesAction()->isEnabled());
        QVERIFY(!m_window->faces()->nextPickedAction()->isEnabled());
        // Every 15th frame a candidate (5 per clip): enough to spread over the clips, a third of
        // the default's work.
        QVERIFY(testing::waitFor(m_window->faces()->pickFramesToLabel(12, 15), 300000));
        QCOMPARE(m_window->context()->undoStack()->index(), index + 1);
        const auto &queue = m_window->faces()->reviewQueue();
        QCOMPARE(int(queue.size()), 12);
        std::set<std::string> clips;
        for (size_t k = 0; k < queue.size(); ++k) {
            const std::string &id = queue[k].sequenceId;
            const int frame = queue[k].frame;
            QVERIFY(queue[k].disagreement >= 0);
            if (k > 0)
                QVERIFY(queue[k].disagreement <= queue[k - 1].disagreement); // the most doubtful first
            clips.insert(id);
            int row = 0;
            while (row < doc->sequenceCount() && doc->sequence(row).id != id)
                ++row;
            QVERIFY(row < doc->sequenceCount());
            const auto it = doc->sequence(row).landmarks.find(frame);
            QVERIFY(it != doc->sequence(row).landmarks.end() && it->second.isComplete());
        }
        QVERIFY2(clips.size() >= 4, "the picks should spread over the clips");
        QVERIFY(m_window->faces()->nextPickedAction()->isEnabled());
        // Shift+W goes to the first and then the second of the queue, in whichever clip.
        for (int k = 0; k < 2; ++k) {
            QTest::keyClick(m_window, Qt::Key_W, Qt::ShiftModifier);
            const std::string &id = queue[size_t(k)].sequenceId;
            QTRY_COMPARE_WITH_TIMEOUT(doc->sequence(m_window->context()->currentSequence()).id, id, 60000);
            QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->currentFrame(), queue[size_t(k)].frame, 60000);
            // Where in the queue and how doubtful, in the status bar.
            const QString status = m_window->statusBar()->currentMessage();
            QVERIFY2(status.startsWith(QStringLiteral("Picked frame %1 of 12").arg(k + 1)), qPrintable(status));
            QVERIFY2(status.contains(QStringLiteral("% of the eye distance")), qPrintable(status));
        }
        // One undo takes every picked frame's points away again (and leaves the demo as the
        // tests after this one expect it).
        QVERIFY(labelled().size() > before.size());
        m_window->context()->undoStack()->undo();
        QCOMPARE(labelled(), before);
        m_window->context()->selectSequence(startRow);
        QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->currentSequence(), startRow, 60000);
        QTRY_VERIFY_WITH_TIMEOUT(m_window->context()->media() && m_window->context()->currentFrame() >= 0, 60000);
        m_window->context()->setCurrentFrame(startFrame);
    }

    void tracksWithTheProjectsAam()
    {
        // The demo references a shipped AAM: tracking loads it without building one.
        ProjectDocument *doc = m_window->context()->document();
        bool hasAam = false;
        for (const ModelReference &m : doc->project().models)
            hasAam = hasAam || m.kind == "aam";
        if (!hasAam)
            QSKIP("the demo ships no AAM");
        const std::vector<ModelReference> models = doc->project().models;
        const int index = m_window->context()->undoStack()->index();
        QVERIFY(testing::waitFor(m_window->faces()->trackSequences({4})));
        QVERIFY(m_window->faces()->model());
        QVERIFY(doc->project().models == models); // no AAM was built
        const Sequence &s = doc->sequence(4);
        QCOMPARE(int(s.features.rows()), s.frameCount);
        QCOMPARE(int(s.features.cols()), m_window->faces()->model()->combinedModes());
        QVERIFY(int(s.landmarks.size()) >= s.frameCount - 5);
        QCOMPARE(m_window->context()->undoStack()->index(), index + 1);
        m_window->context()->undoStack()->undo();
        QVERIFY(doc->sequence(4).landmarks.empty());
    }

    void buildAamAndTrackASequence()
    {
        // Label a few frames of the first clips with dlib's points of held-out frames of the same
        // speaker (tests/data/faces/grid): same camera, so near enough to train on.
        ProjectDocument *doc = m_window->context()->document();
        const QDir data(QStringLiteral(LIPSYNC_TEST_DATA "/faces/grid"));
        const QStringList pts = data.entryList({QStringLiteral("*_22.pts")}, QDir::Files, QDir::Name);
        QVERIFY(pts.size() >= 6);
        for (int i = 0; i < 6; ++i) {
            const LandmarkSet set = readLandmarkSet(data.filePath(pts[i]).toStdString(), PointState::Placed);
            QVERIFY(doc->requestLandmarks(1 + i % 3, 20 + 10 * i, set, QStringLiteral("label")));
        }
        Task *build = m_window->faces()->buildAam();
        QVERIFY(testing::waitFor(build));
        const auto model = m_window->faces()->model();
        QVERIFY(model);
        QVERIFY(model->combinedModes() >= 1);
        QCOMPARE(doc->project().models.back().kind, std::string("aam"));
        QVERIFY(doc->isModified()); // the read-only demo keeps the model in memory

        const Eigen::MatrixXd featuresBefore = doc->sequence(0).features; // the demo ships some
        Task *track = m_window->faces()->trackSequences({0});
        QVERIFY(testing::waitFor(track));
        const Sequence &s = doc->sequence(0);
        QCOMPARE(int(s.features.rows()), 75);
        QCOMPARE(int(s.features.cols()), model->combinedModes());
        QVERIFY(s.features.allFinite());
        QVERIFY(s.landmarks.size() >= 70);
        // The user's points on frame 5 stayed as they were.
        const LandmarkSet &five = s.landmarks.at(5);
        QCOMPARE(five.points[1].state, PointState::Fixed);
        QCOMPARE(five.points[0].state, PointState::Placed);
        const std::vector<double> errors = s.fitErrors;
        QCOMPARE(int(errors.size()), 75);

        // W walks the worst-fitted frames.
        m_window->context()->setCurrentFrame(0);
        QTest::keyClick(m_window, Qt::Key_W);
        const int worst = m_window->context()->currentFrame();
        for (double e : errors)
            QVERIFY(e <= errors[std::size_t(worst)] || errors[std::size_t(worst)] < 0);
        QTest::keyClick(m_window, Qt::Key_W);
        const int second = m_window->context()->currentFrame();
        QVERIFY(second != worst);
        for (std::size_t f = 0; f < errors.size(); ++f)
            if (int(f) != worst && errors[std::size_t(worst)] >= 0)
                QVERIFY(errors[f] <= errors[std::size_t(second)] || errors[std::size_t(second)] < 0);

        // Undo takes the whole track back in one step.
        QCOMPARE(m_window->context()->undoStack()->undoText(), QStringLiteral("Track bbaf2n"));
        m_window->context()->undoStack()->undo();
        QVERIFY(doc->sequence(0).features.rows() == featuresBefore.rows()
                && doc->sequence(0).features.cols() == featuresBefore.cols());
        QVERIFY(featuresBefore.size() == 0 || doc->sequence(0).features == featuresBefore);
        QCOMPARE(doc->sequence(0).landmarks.size(), std::size_t(2)); // frames 5 and 10 again
        QVERIFY(doc->sequence(0).fitErrors.empty());

        // The modes view synthesises a face that changes with the first mode.
        m_window->faces()->showModes();
        ModesView *modes = m_window->findChild<ModesView *>();
        QVERIFY(modes);
        const QImage mean = modes->face();
        QVERIFY(!mean.isNull());
        modes->setMode(0, 3.0);
        QVERIFY(modes->face() != mean);
        if (const QByteArray dir = qgetenv("LIPSYNC_SCREENSHOT_DIR"); !dir.isEmpty())
            modes->grab().save(QDir(QString::fromLocal8Bit(dir)).filePath(QStringLiteral("annotate-modes.png")));

        // Undoing Build AAM puts the project's previous AAM back in use everywhere (Modes of
        // Variation included); redo brings back the same built model, which exists in memory only.
        QCOMPARE(m_window->context()->undoStack()->undoText(), QStringLiteral("Build AAM %1").arg(QString::fromStdString(doc->project().models.back().name)));
        m_window->context()->undoStack()->undo();
        const ModelReference *previous = doc->project().model("aam");
        QVERIFY(previous);
        const auto restored = m_window->faces()->model();
        QVERIFY(restored && restored != model);
        QCOMPARE(restored->combinedModes(),
                 AamModel::load(doc->project().resolve(previous->file)).combinedModes());
        QVERIFY(modes->face() != mean); // re-rendered with the demo's AAM
        auto *active = m_window->findChild<QLabel *>(QStringLiteral("activeModels"));
        QVERIFY(active);
        QVERIFY2(active->text().startsWith(QStringLiteral("AAM: %1 ").arg(QString::fromStdString(previous->name))),
                 qPrintable(active->text()));
        m_window->context()->undoStack()->redo();
        QCOMPARE(m_window->faces()->model(), model);
        QVERIFY2(active->text().startsWith(
                     QStringLiteral("AAM: %1 ").arg(QString::fromStdString(doc->project().model("aam")->name))),
                 qPrintable(active->text()));
        modes->close();

        // Building again gives the AAM a file of its own, so undoing the rebuild brings back the
        // first build (not the demo's, and not a file overwritten meanwhile).
        const std::string firstFile = doc->project().model("aam")->file;
        QVERIFY(testing::waitFor(m_window->faces()->buildAam()));
        const auto rebuilt = m_window->faces()->model();
        QVERIFY(rebuilt && rebuilt != model);
        QVERIFY(doc->project().model("aam")->file != firstFile);
        m_window->context()->undoStack()->undo();
        QCOMPARE(doc->project().model("aam")->file, firstFile);
        QCOMPARE(m_window->faces()->model(), model);
        m_window->context()->undoStack()->redo();
        QCOMPARE(m_window->faces()->model(), rebuilt);
    }

    void fitErrorsSurviveReopening()
    {
        // The worst-fit queue comes from the project: saved, reopened, W still knows the worst frame.
        ProjectDocument *doc = m_window->context()->document();
        const Sequence &first = doc->sequence(0);
        std::vector<double> errors(std::size_t(first.frameCount), 0.01);
        errors[40] = 0.3;
        errors[12] = 0.2;
        errors[3] = Sequence::kNoFace;
        QVERIFY(doc->requestFaces({{0, first.landmarks, first.features, errors}}, QStringLiteral("fit errors")));
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        Project copy = doc->project();
        copy.saveAs(dir.path().toStdString());
        QVERIFY(m_window->files()->open(dir.path()));
        QTRY_COMPARE_WITH_TIMEOUT(m_window->context()->taskRunner()->runningCount(), 0, 60000);
        QCOMPARE(m_window->context()->document()->sequence(0).fitErrors, errors);
        m_window->context()->selectSequence(0);
        m_window->context()->setCurrentFrame(0);
        QTest::keyClick(m_window, Qt::Key_W);
        QCOMPARE(m_window->context()->currentFrame(), 3); // no face ranks first
        QTest::keyClick(m_window, Qt::Key_W);
        QCOMPARE(m_window->context()->currentFrame(), 40);
        QTest::keyClick(m_window, Qt::Key_W);
        QCOMPARE(m_window->context()->currentFrame(), 12);
    }
};

QTEST_MAIN(TestLandmarkEditor)
#include "tst_landmarkeditor.moc"
