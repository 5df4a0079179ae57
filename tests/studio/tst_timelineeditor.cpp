// The speech workflow in the studio's timeline: "Align" on the demo's first clip fills the word
// and phone tiers (words = the transcript) and the 75-frame label strip; a phone boundary dragged
// with the mouse in the real widget moves by the snapped amount, is marked user-edited and is ONE
// undo step that restores the tiers exactly (redo re-applies); split (S), merge (M), relabel
// (double-click, the phone combo, validation), insert silence (I), Tab and Space in the view;
// re-aligning a selection keeps the edited boundary; "Align all" is one undo step and canceling
// it changes nothing; a transcript that cannot fit is reported naming the clip. The panel on a
// studio context, without the main window.
#include "DemoWindow.h"

#include "align/Lexicon.h"
#include "align/SphinxAligner.h"
#include "app/DemoProject.h"
#include "context/ErrorReporter.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "document/TierEdits.h"
#include "tasks/TaskRunner.h"
#include "timeline/TimelinePanel.h"
#include "timeline/WaveformView.h"
#include "util/PhoneSet.h"

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QMessageBox>
#include <QSettings>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>

using namespace lipsync;
using namespace lipsync::studio;

namespace {

bool near(double a, double b, double tolerance = 1e-9)
{
    return std::abs(a - b) <= tolerance;
}

} // namespace

class TestTimelineEditor : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase()
    {
        testing::openDemoTimeline(m_context, m_host, m_panel);
        if (QTest::currentTestFailed())
            return;
        m_view = m_panel->waveform();
    }

    void cleanupTestCase() { QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000); }

    // The panel needs a context, not a window: on its own it shows the context's current
    // sequence and turns an edit into one undo step of the context's stack.
    void worksWithAContextAndNoWindow()
    {
        StudioContext context;
        const QString demo = DemoProject::locate();
        context.document()->reset(DemoProject::load(demo), demo, true);
        TimelinePanel panel;
        panel.attach(&context);
        context.setCurrentSequence(3, nullptr);
        context.announceSequenceLoaded();
        QCOMPARE(panel.row(), 3);
        const size_t before = context.document()->sequence(3).phones.intervals.size();
        QCOMPARE(panel.waveform()->phones().intervals.size(), before);
        // Split the phone under 1.3 s.
        const auto &intervals = context.document()->sequence(3).phones.intervals;
        const int index = int(std::find_if(intervals.begin(), intervals.end(),
                                           [](const Interval &iv) { return iv.start < 1.3 && iv.end > 1.3; })
                              - intervals.begin());
        QVERIFY(index < int(before));
        panel.waveform()->setCursorTime(1.3);
        panel.waveform()->selectInterval(TierKind::Phones, index);
        panel.splitAtCursor();
        QCOMPARE(context.undoStack()->count(), 1);
        QCOMPARE(context.document()->sequence(3).phones.intervals.size(), before + 1);
        QCOMPARE(panel.waveform()->phones().intervals.size(), before + 1);
        context.undoStack()->undo();
        QCOMPARE(panel.waveform()->phones().intervals.size(), before);

        // The Speech menu's aligner is the studio's (the preview's generation aligns with it too).
        panel.adaptToSpeakerAction()->setChecked(true);
        QVERIFY(context.modelStore()->alignerChoice().adapt);
        if (SphinxAligner::available()) {
            panel.sphinxAlignerAction()->setChecked(true);
            QVERIFY(context.modelStore()->alignerChoice().isSphinx());
            panel.builtInAlignerAction()->setChecked(true);
            QVERIFY(!context.modelStore()->alignerChoice().isSphinx());
        }
        panel.adaptToSpeakerAction()->setChecked(false);
        QVERIFY(!context.modelStore()->alignerChoice().adapt);
        // A project that names its speaker's own aligner aligns with it (and the menu says so);
        // Undo brings back the shipped one.
        QVERIFY(context.modelStore()->alignerChoice().model.empty());
        QVERIFY(context.document()->requestAddModel({"aligner", "speaker", "aligners/speaker.aligner"},
                                                    QStringLiteral("Add aligner")));
        QVERIFY(QString::fromStdString(context.modelStore()->alignerChoice().model).endsWith("aligners/speaker.aligner"));
        QVERIFY(panel.builtInAlignerAction()->text().contains(QStringLiteral("speaker")));
        context.undoStack()->undo();
        QVERIFY(context.modelStore()->alignerChoice().model.empty());
    }

    // A project says whose aligner aligns it (Project::aligner): opening one whose speaker is not
    // GRID's chooses Generic US English adapted to the speaker, one that says builtin (the demo)
    // the shipped model; neither is remembered as the user's own choice, and one that does not
    // say keeps the last choice.
    void projectSaysWhoseAligner()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        StudioContext context;
        TimelinePanel panel;
        panel.attach(&context);
        const QString demo = DemoProject::locate();
        Project project = DemoProject::load(demo);
        QCOMPARE(project.aligner, std::string(Project::kBuiltinAligner));
        const QVariant remembered = QSettings().value(QStringLiteral("timeline/aligner"));
        project.aligner = Project::kGenericAligner;
        context.document()->reset(project, demo, true);
        QVERIFY(panel.sphinxAlignerAction()->isChecked() && !panel.builtInAlignerAction()->isChecked());
        QVERIFY(panel.adaptToSpeakerAction()->isChecked());
        QVERIFY(context.modelStore()->alignerChoice().isSphinx() && context.modelStore()->alignerChoice().adapt);
        QCOMPARE(QSettings().value(QStringLiteral("timeline/aligner")), remembered);
        // A project that does not say keeps it.
        project.aligner.clear();
        context.document()->reset(project, demo, true);
        QVERIFY(context.modelStore()->alignerChoice().isSphinx());
        // The demo says builtin.
        context.document()->reset(DemoProject::load(demo), demo, true);
        QVERIFY(panel.builtInAlignerAction()->isChecked() && !panel.adaptToSpeakerAction()->isChecked());
        QVERIFY(!context.modelStore()->alignerChoice().isSphinx() && !context.modelStore()->alignerChoice().adapt);
        QCOMPARE(QSettings().value(QStringLiteral("timeline/aligner")), remembered);
    }

    void alignSequenceFillsTiers()
    {
        QCOMPARE(m_context.currentSequence(), 0);
        // Start from a sequence without tiers (the demo ships its alignment).
        QVERIFY(m_context.document()->requestTiersChange(0, Tier{"words", {}}, Tier{"phones", {}}, QStringLiteral("clear")));
        const TierPair before = tiers();
        QVERIFY(before.phones.isEmpty());
        QVERIFY(m_view->phones().isEmpty());
        QVERIFY(m_view->frameLabels().empty());
        QVERIFY(m_panel->alignAction()->isEnabled());
        QElapsedTimer timer;
        timer.start();
        m_panel->alignAction()->trigger();
        QCOMPARE(m_context.taskRunner()->runningCount(), 1);
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
        qInfo("aligning one clip took %lld ms", timer.elapsed());

        const Sequence &s = m_context.document()->sequence(0);
        QVERIFY(s.phones.intervals.size() > 10);
        QVERIFY(!(s.phones == before.phones));
        for (const Interval &p : s.phones.intervals)
            QVERIFY2(PhoneSet::index(p.label) >= 0, p.label.c_str());
        QStringList spoken;
        for (const Interval &w : s.words.intervals)
            if (!PhoneSet::isSilence(w.label))
                spoken << QString::fromStdString(w.label).toLower();
        QStringList transcript;
        for (const std::string &w : Lexicon::splitWords(s.transcript))
            transcript << QString::fromStdString(w).toLower();
        QCOMPARE(spoken, transcript);
        QCOMPARE(m_context.undoStack()->index(), 2);
        // The view shows them, with the per-video-frame labels (75 frames at 25 fps).
        QVERIFY(m_view->phones() == s.phones);
        QCOMPARE(int(m_view->frameLabels().size()), 75);
        QCOMPARE(m_view->frameLabels().front(), std::string("sil"));
        // Undo takes the alignment back, redo brings it again.
        const TierPair aligned = tiers();
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
        QVERIFY(m_view->phones() == before.phones);
        m_context.undoStack()->redo();
        QVERIFY(tiers() == aligned);
        QCOMPARE(int(m_view->frameLabels().size()), 75);
    }

    void dragPhoneBoundaryIsOneUndoStep()
    {
        const TierPair before = tiers();
        // A phone boundary inside a word (not on a word edge), both neighbours long enough.
        int b = -1;
        for (int i = 2; i + 1 < int(before.phones.intervals.size()) && b < 0; ++i) {
            const Interval &l = before.phones.intervals[size_t(i - 1)];
            const Interval &r = before.phones.intervals[size_t(i)];
            if (l.end - l.start > 0.06 && r.end - r.start > 0.06 && !PhoneSet::isSilence(l.label)
                && !PhoneSet::isSilence(r.label) && tieredit::boundaryNear(before.words, r.start, 1e-3) < 0)
                b = i;
        }
        QVERIFY(b > 0);
        m_view->zoomToFit();
        const double t0 = before.phones.intervals[size_t(b)].start;
        const int y = m_view->laneRect(WaveformView::Lane::Phones).center().y();
        const int x0 = int(std::lround(m_view->xAt(t0)));
        const int dx = 7;
        const double expected = tieredit::snap(t0 + dx * m_view->secondsPerPixel());
        QVERIFY(!near(expected, t0));
        double lower = 0, upper = 0;
        tieredit::boundaryLimits(before, TierKind::Phones, b, &lower, &upper);
        QVERIFY(expected > lower && expected < upper);

        const int steps = m_context.undoStack()->index();
        QTest::mousePress(m_view, Qt::LeftButton, {}, QPoint(x0, y));
        for (int x = x0 + 1; x <= x0 + dx; ++x)
            QTest::mouseMove(m_view, QPoint(x, y));
        QTest::mouseRelease(m_view, Qt::LeftButton, {}, QPoint(x0 + dx, y));

        const TierPair after = tiers();
        QVERIFY2(near(after.phones.intervals[size_t(b)].start, expected),
                 qPrintable(QStringLiteral("%1 -> %2, expected %3")
                                .arg(t0).arg(after.phones.intervals[size_t(b)].start).arg(expected)));
        QVERIFY(near(after.phones.intervals[size_t(b - 1)].end, expected)); // the shared edge
        QVERIFY(after.phones.intervals[size_t(b)].userEdited);
        QVERIFY(after.phones.intervals[size_t(b - 1)].userEdited);
        QVERIFY(after.words == before.words);
        QCOMPARE(m_context.undoStack()->index(), steps + 1); // the whole drag: one step
        QVERIFY(m_view->phones() == after.phones);          // the view follows

        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
        QVERIFY(m_view->phones() == before.phones);
        m_context.undoStack()->redo();
        QVERIFY(tiers() == after);
        // For looking at: the window with the aligned, edited tiers.
        const QString shots = qEnvironmentVariable("LIPSYNC_TEST_SCREENSHOTS");
        if (!shots.isEmpty()) {
            m_host.grab().save(shots + QStringLiteral("/timeline-window.png"));
            m_view->grab().save(shots + QStringLiteral("/timeline-view.png"));
            m_view->selectInterval(TierKind::Phones, b);
            m_view->zoomBy(3.0, m_view->xAt(expected));
            m_view->grab().save(shots + QStringLiteral("/timeline-zoomed.png"));
            m_view->zoomToFit();
        }
    }

    void dragCannotCrossNeighbours()
    {
        const TierPair before = tiers();
        const int b = int(before.phones.intervals.size()) / 2;
        const double t0 = before.phones.intervals[size_t(b)].start;
        double lower = 0, upper = 0;
        tieredit::boundaryLimits(before, TierKind::Phones, b, &lower, &upper);
        const int y = m_view->laneRect(WaveformView::Lane::Phones).center().y();
        const int x0 = int(std::lround(m_view->xAt(t0)));
        QTest::mousePress(m_view, Qt::LeftButton, {}, QPoint(x0, y));
        QTest::mouseMove(m_view, QPoint(x0 + 150, y));
        QTest::mouseRelease(m_view, Qt::LeftButton, {}, QPoint(x0 + 150, y));
        const double moved = tiers().phones.intervals[size_t(b)].start;
        QVERIFY2(near(moved, upper), qPrintable(QStringLiteral("%1 vs limit %2").arg(moved).arg(upper)));
        QVERIFY(tiers().phones.intervals[size_t(b)].end - moved >= tieredit::kSnap - 1e-9);
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
    }

    void wordBoundaryTakesThePhoneBoundaryAlong()
    {
        // After alignment every word edge is a phone edge: dragging it in the words lane moves both.
        const TierPair before = tiers();
        int w = -1, p = -1;
        for (int i = 1; i < int(before.words.intervals.size()) && w < 0; ++i) {
            const double t = before.words.intervals[size_t(i)].start;
            const int k = tieredit::boundaryNear(before.phones, t, 1e-6);
            if (k > 0 && !PhoneSet::isSilence(before.words.intervals[size_t(i)].label)
                && !PhoneSet::isSilence(before.words.intervals[size_t(i - 1)].label)) {
                w = i;
                p = k;
            }
        }
        QVERIFY(w > 0);
        const double t0 = before.words.intervals[size_t(w)].start;
        double lower = 0, upper = 0;
        tieredit::boundaryLimits(before, TierKind::Words, w, &lower, &upper);
        const int y = m_view->laneRect(WaveformView::Lane::Words).center().y();
        const int x0 = int(std::lround(m_view->xAt(t0)));
        const int dx = -5;
        const double expected = std::clamp(tieredit::snap(t0 + dx * m_view->secondsPerPixel()), lower, upper);
        QVERIFY(!near(expected, t0));
        QTest::mousePress(m_view, Qt::LeftButton, {}, QPoint(x0, y));
        QTest::mouseMove(m_view, QPoint(x0 - 2, y));
        QTest::mouseMove(m_view, QPoint(x0 + dx, y));
        QTest::mouseRelease(m_view, Qt::LeftButton, {}, QPoint(x0 + dx, y));
        const TierPair after = tiers();
        QVERIFY(near(after.words.intervals[size_t(w)].start, expected));
        QVERIFY(near(after.words.intervals[size_t(w - 1)].end, expected));
        QVERIFY(near(after.phones.intervals[size_t(p)].start, expected));
        QVERIFY(near(after.phones.intervals[size_t(p - 1)].end, expected));
        QVERIFY(after.words.intervals[size_t(w)].userEdited && after.phones.intervals[size_t(p)].userEdited);
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
    }

    // M on the last phone of a word asks first: Cancel (Enter) leaves the tiers; "Merge Phones and
    // Words" joins both phones and both words in one undo step.
    void mergeAcrossAWordAsks()
    {
        const TierPair before = tiers();
        const int steps = m_context.undoStack()->index();
        int p = -1;
        for (int k = 0; k + 1 < int(before.phones.intervals.size()) && p < 0; ++k)
            if (tieredit::wordBetweenPhones(before, k) >= 0)
                p = k;
        QVERIFY(p >= 0);
        const int w = tieredit::wordBetweenPhones(before, p);
        // Two phones of one word are no such pair.
        const Interval &word = before.words.intervals[size_t(w)];
        const int inside = before.phones.indexAt(word.start + 1e-3);
        QVERIFY(before.phones.intervals[size_t(inside)].end < word.end - 1e-3); // "bin": B IH N
        QCOMPARE(tieredit::wordBetweenPhones(before, inside), -1);
        const std::string joined = before.words.intervals[size_t(w)].label + ' ' + before.words.intervals[size_t(w + 1)].label;
        // Answers the question box once it shows: looked for every 10 ms (over a bare widget, with no
        // window manager under Xvfb, it need not become the active modal widget, and the key that
        // opens it may let a timer run before it is shown).
        auto answer = [this](bool merge, QString *text) {
            auto *poll = new QTimer(this);
            poll->setInterval(10);
            connect(poll, &QTimer::timeout, this, [poll, merge, text, tries = 0]() mutable {
                QMessageBox *box = nullptr;
                for (QWidget *w : QApplication::topLevelWidgets())
                    if (auto *b = qobject_cast<QMessageBox *>(w); b && b->isVisible())
                        box = b;
                if (!box && ++tries < 1000)
                    return;
                poll->stop();
                poll->deleteLater();
                QVERIFY(box);
                *text = box->text();
                // Enter answers with the default button, which keeps the words apart; it is
                // clicked rather than sent the key (with no window manager under Xvfb the box
                // need not get the keyboard, and then nothing would close it).
                QAbstractButton *keepApart = box->defaultButton();
                const bool safeDefault = keepApart && box->buttonRole(keepApart) != QMessageBox::AcceptRole;
                for (QAbstractButton *b : box->buttons())
                    if ((box->buttonRole(b) == QMessageBox::AcceptRole) == merge) {
                        b->click();
                        break;
                    }
                QVERIFY2(safeDefault, "Enter would merge the words");
            });
            poll->start();
        };
        // The box takes the focus while it is open: the view gets it back before each key.
        auto focusView = [this] {
            m_host.activateWindow();
            m_view->setFocus();
            QTRY_VERIFY(m_view->hasFocus());
        };
        QString asked;
        m_view->selectInterval(TierKind::Phones, p);
        focusView();
        answer(false, &asked);
        QTest::keyClick(m_view, Qt::Key_M);
        QVERIFY2(asked.contains(QString::fromStdString(before.words.intervals[size_t(w)].label)), qPrintable(asked));
        QVERIFY(tiers() == before);
        QCOMPARE(m_context.undoStack()->index(), steps);

        m_view->selectInterval(TierKind::Phones, p);
        focusView();
        answer(true, &asked);
        QTest::keyClick(m_view, Qt::Key_M);
        const TierPair after = tiers();
        QCOMPARE(after.phones.intervals.size(), before.phones.intervals.size() - 1);
        QCOMPARE(after.words.intervals.size(), before.words.intervals.size() - 1);
        QCOMPARE(after.words.intervals[size_t(w)].label, joined);
        QVERIFY(near(after.words.intervals[size_t(w)].end, before.words.intervals[size_t(w + 1)].end));
        QCOMPARE(m_context.undoStack()->index(), steps + 1);
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
        focusView();
    }

    void splitMergeRelabelWithKeysAndUndo()
    {
        const TierPair before = tiers();
        const int steps = m_context.undoStack()->index();
        // Click the middle of a long phone: selects it and puts the cursor there.
        int i = 0;
        for (int k = 1; k < int(before.phones.intervals.size()); ++k)
            if (!PhoneSet::isSilence(before.phones.intervals[size_t(k)].label)
                && before.phones.intervals[size_t(k)].end - before.phones.intervals[size_t(k)].start
                       > before.phones.intervals[size_t(i)].end - before.phones.intervals[size_t(i)].start)
                i = k;
        const Interval &iv = before.phones.intervals[size_t(i)];
        const int y = m_view->laneRect(WaveformView::Lane::Phones).center().y();
        const int x = int(std::lround(m_view->xAt((iv.start + iv.end) / 2)));
        QTest::mouseClick(m_view, Qt::LeftButton, {}, QPoint(x, y));
        QCOMPARE(m_view->activeTier(), TierKind::Phones);
        QCOMPARE(m_view->selectedInterval(), i);
        QVERIFY(m_view->hasFocus());

        // S: split at the cursor (snapped to 10 ms).
        QTest::keyClick(m_view, Qt::Key_S);
        TierPair now = tiers();
        QCOMPARE(now.phones.intervals.size(), before.phones.intervals.size() + 1);
        const double cut = tieredit::snap(m_view->cursorTime());
        QVERIFY(near(now.phones.intervals[size_t(i)].end, cut));
        QCOMPARE(now.phones.intervals[size_t(i + 1)].label, iv.label);
        QVERIFY(now.phones.intervals[size_t(i + 1)].userEdited);
        QCOMPARE(m_context.undoStack()->index(), steps + 1);

        // M: merge the selected interval with the next (the two halves again).
        m_view->selectInterval(TierKind::Phones, i);
        QTest::keyClick(m_view, Qt::Key_M);
        now = tiers();
        QCOMPARE(now.phones.intervals.size(), before.phones.intervals.size());
        QVERIFY(near(now.phones.intervals[size_t(i)].end, iv.end));
        QCOMPARE(m_context.undoStack()->index(), steps + 2);
        m_context.undoStack()->undo();
        QCOMPARE(tiers().phones.intervals.size(), before.phones.intervals.size() + 1);
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);

        // Double-click: the phone combo; an unknown phone is refused, a valid one relabels.
        QTest::mouseDClick(m_view, Qt::LeftButton, {}, QPoint(x, y));
        auto *combo = qobject_cast<QComboBox *>(m_panel->relabelEditor());
        QVERIFY(combo);
        QCOMPARE(combo->count(), PhoneSet::kCount);
        QCOMPARE(combo->currentText(), QString::fromStdString(iv.label));
        combo->lineEdit()->setText(QStringLiteral("XQ"));
        QTest::keyClick(combo->lineEdit(), Qt::Key_Return);
        QVERIFY(m_panel->relabelEditor()); // still open
        QVERIFY(tiers() == before);
        const std::string target = iv.label == "AA" ? "IY" : "AA";
        combo->lineEdit()->setText(QString::fromStdString(target).toLower() + QStringLiteral("1")); // stress dropped
        QTest::keyClick(combo->lineEdit(), Qt::Key_Return);
        QTRY_VERIFY(!m_panel->relabelEditor());
        now = tiers();
        QCOMPARE(now.phones.intervals[size_t(i)].label, target);
        QVERIFY(now.phones.intervals[size_t(i)].userEdited);
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);

        // Enter on the words tier: a line edit; one word only.
        const int wy = m_view->laneRect(WaveformView::Lane::Words).center().y();
        QTest::mouseClick(m_view, Qt::LeftButton, {}, QPoint(x, wy));
        QCOMPARE(m_view->activeTier(), TierKind::Words);
        const int w = m_view->selectedInterval();
        QVERIFY(w >= 0);
        QTest::keyClick(m_view, Qt::Key_Return);
        auto *line = qobject_cast<QLineEdit *>(m_panel->relabelEditor());
        QVERIFY(line);
        line->setText(QStringLiteral("two words"));
        QTest::keyClick(line, Qt::Key_Return);
        QVERIFY(m_panel->relabelEditor());
        line->setText(QStringLiteral("please"));
        QTest::keyClick(line, Qt::Key_Return);
        QTRY_VERIFY(!m_panel->relabelEditor());
        QCOMPARE(tiers().words.intervals[size_t(w)].label, std::string("please"));
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
    }

    void insertSilenceOnASelectedStretch()
    {
        const TierPair before = tiers();
        // Select the phones tier (a click inside its longest interval, away from any boundary),
        // then drag a stretch over the waveform and press I.
        const Interval iv = *std::max_element(before.phones.intervals.begin(), before.phones.intervals.end(),
                                              [](const Interval &x, const Interval &y) {
                                                  return x.end - x.start < y.end - y.start;
                                              });
        const int py = m_view->laneRect(WaveformView::Lane::Phones).center().y();
        QTest::mouseClick(m_view, Qt::LeftButton, {}, QPoint(int(m_view->xAt((iv.start + iv.end) / 2)), py));
        const int wy = m_view->laneRect(WaveformView::Lane::Waveform).center().y();
        const int xa = int(m_view->xAt(1.0));
        const int xb = int(m_view->xAt(1.2));
        QTest::mousePress(m_view, Qt::LeftButton, {}, QPoint(xa, wy));
        QTest::mouseMove(m_view, QPoint((xa + xb) / 2, wy));
        QTest::mouseMove(m_view, QPoint(xb, wy));
        QTest::mouseRelease(m_view, Qt::LeftButton, {}, QPoint(xb, wy));
        QVERIFY(m_view->hasRange());
        const double a = tieredit::snap(m_view->rangeStart());
        const double b = tieredit::snap(m_view->rangeEnd());
        QVERIFY(b - a > 0.1);
        QTest::keyClick(m_view, Qt::Key_I);
        const Tier phones = tiers().phones;
        const int k = phones.indexAt((a + b) / 2);
        QVERIFY(k >= 0);
        QCOMPARE(phones.intervals[size_t(k)].label, std::string("sil"));
        QVERIFY(near(phones.intervals[size_t(k)].start, a));
        QVERIFY2(near(phones.intervals[size_t(k)].end, b),
                 qPrintable(QStringLiteral("[%1, %2] for the range [%3, %4]")
                                .arg(phones.intervals[size_t(k)].start).arg(phones.intervals[size_t(k)].end)
                                .arg(a).arg(b)));
        QVERIFY(phones.intervals[size_t(k)].userEdited);
        // Still contiguous.
        for (std::size_t j = 1; j < phones.intervals.size(); ++j)
            QVERIFY(near(phones.intervals[j].start, phones.intervals[j - 1].end));
        m_context.undoStack()->undo();
        QVERIFY(tiers() == before);
    }

    void tabWalksAndSpacePlaysTheSelection()
    {
        const int py = m_view->laneRect(WaveformView::Lane::Phones).center().y();
        const Interval first = tiers().phones.intervals[1];
        QTest::mouseClick(m_view, Qt::LeftButton, {}, QPoint(int(m_view->xAt((first.start + first.end) / 2)), py));
        QCOMPARE(m_view->selectedInterval(), 1);
        QTest::keyClick(m_view, Qt::Key_Tab);
        QCOMPARE(m_view->selectedInterval(), 2);
        QVERIFY(m_view->hasFocus()); // Tab did not move the focus
        QTest::keyClick(m_view, Qt::Key_Tab, Qt::ShiftModifier);
        QCOMPARE(m_view->selectedInterval(), 1);

        // Space in the timeline plays the selected interval (not the video from the cursor).
        const Interval iv = tiers().phones.intervals[1];
        QTest::keyClick(m_view, Qt::Key_Space);
        QVERIFY(m_panel->player()->isPlaying());
        QCOMPARE(m_panel->player(), m_context.playback()); // one player
        QVERIFY(near(m_context.playback()->rangeStart(), iv.start));
        QVERIFY(near(m_context.playback()->rangeEnd(), iv.end));
        QTRY_VERIFY_WITH_TIMEOUT(!m_panel->player()->isPlaying(), 5000);
        QVERIFY(near(m_panel->player()->position(), iv.end));
        QVERIFY(near(m_view->cursorTime(), iv.end));
        QCOMPARE(m_context.currentFrame(), int(iv.end * 25.0));
    }

    void realignKeepsEditedWords()
    {
        // Move one phone boundary (its word becomes user-fixed), then re-align everything.
        const TierPair aligned = tiers();
        int b = -1;
        for (int i = 2; i + 1 < int(aligned.phones.intervals.size()) && b < 0; ++i)
            if (aligned.phones.intervals[size_t(i)].end - aligned.phones.intervals[size_t(i)].start > 0.05
                && aligned.phones.intervals[size_t(i - 1)].end - aligned.phones.intervals[size_t(i - 1)].start > 0.05
                && tieredit::boundaryNear(aligned.words, aligned.phones.intervals[size_t(i)].start, 1e-3) < 0)
                b = i;
        QVERIFY(b > 0);
        TierPair edited = aligned;
        QVERIFY(tieredit::moveBoundary(edited, TierKind::Phones, b, aligned.phones.intervals[size_t(b)].start + 0.02));
        QVERIFY(m_context.document()->requestTiersChange(0, edited.words, edited.phones, QStringLiteral("edit")));
        const double moved = edited.phones.intervals[size_t(b)].start;
        m_view->setRange(0.0, m_view->duration());
        QVERIFY(m_panel->realignAction()->isEnabled());
        const int steps = m_context.undoStack()->index();
        m_panel->realignAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
        QVERIFY(m_context.undoStack()->index() <= steps + 1); // one step (none if nothing moved)
        const TierPair now = tiers();
        QVERIFY(tieredit::boundaryNear(now.phones, moved, 1e-6) > 0); // the edited boundary stays
        QStringList spoken;
        for (const Interval &w : now.words.intervals)
            if (!PhoneSet::isSilence(w.label))
                spoken << QString::fromStdString(w.label);
        QCOMPARE(spoken.size(), int(Lexicon::splitWords(m_context.document()->sequence(0).transcript).size()));
        for (std::size_t j = 1; j < now.phones.intervals.size(); ++j)
            QVERIFY(near(now.phones.intervals[j].start, now.phones.intervals[j - 1].end, 1e-6));
        if (m_context.undoStack()->index() == steps + 1) {
            m_context.undoStack()->undo();
            QVERIFY(tiers() == edited);
        }
    }

    // Align (and Align All) keep user-edited boundaries as Re-align Selection does; only where
    // the transcript changed since the edit are they replaced (after asking; batch mode: yes).
    void alignKeepsEditedBoundaries()
    {
        ProjectDocument *doc = m_context.document();
        const TierPair aligned = tiers();
        // An edited phone boundary inside the longest word.
        const Interval &word = *std::max_element(aligned.words.intervals.begin(), aligned.words.intervals.end(),
                                                 [](const Interval &x, const Interval &y) {
                                                     return PhoneSet::isSilence(x.label)
                                                            || (!PhoneSet::isSilence(y.label)
                                                                && x.end - x.start < y.end - y.start);
                                                 });
        int b = -1;
        for (int i = 1; i < int(aligned.phones.intervals.size()) && b < 0; ++i) {
            const double t = aligned.phones.intervals[size_t(i)].start;
            if (t > word.start + 0.03 && t < word.end - 0.03)
                b = i;
        }
        QVERIFY(b > 0);
        TierPair edited = aligned;
        QVERIFY(tieredit::moveBoundary(edited, TierKind::Phones, b, aligned.phones.intervals[size_t(b)].start - 0.02));
        QVERIFY(doc->requestTiersChange(0, edited.words, edited.phones, QStringLiteral("edit")));
        const Interval editedPhone = tiers().phones.intervals[size_t(b)];
        QVERIFY(editedPhone.userEdited);

        for (QAction *align : {m_panel->alignAction(), m_panel->alignAllAction()}) {
            align->trigger();
            QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000);
            const TierPair now = tiers();
            const int at = now.phones.indexAt((editedPhone.start + editedPhone.end) / 2);
            QVERIFY2(at >= 0 && now.phones.intervals[size_t(at)] == editedPhone, qPrintable(align->text()));
        }

        // A changed transcript: the whole clip is aligned to it, the edit replaced.
        const QString transcript = QString::fromStdString(doc->sequence(0).transcript);
        QVERIFY(doc->requestTranscriptChange(0, transcript + QStringLiteral(" please")));
        m_panel->alignAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000);
        for (const Interval &p : tiers().phones.intervals)
            QVERIFY(!p.userEdited);
        QCOMPARE(tiers().words.intervals.back().label == "please"
                     || tiers().words.intervals[tiers().words.intervals.size() - 2].label == "please",
                 true);
        QVERIFY(doc->requestTranscriptChange(0, transcript));
        m_context.undoStack()->undo(); // the transcript
        m_context.undoStack()->undo(); // the alignment
        m_context.undoStack()->undo(); // the transcript change
        QVERIFY(doc->requestTiersChange(0, aligned.words, aligned.phones, QStringLiteral("restore")));
    }

    // "Generic US English (CMU Sphinx)": remembered in the settings, keeps "Adapt to Speaker"
    // (which then adapts CMU Sphinx's model: SphinxAdaptation), and aligns the sequence through
    // the same task and undo, adapted too.
    void sphinxModelChoiceAligns()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        QVERIFY(m_panel->builtInAlignerAction()->isChecked());
        m_panel->sphinxAlignerAction()->trigger();
        QVERIFY(m_panel->sphinxAlignerAction()->isChecked());
        QVERIFY(!m_panel->builtInAlignerAction()->isChecked());
        QCOMPARE(QSettings().value(QStringLiteral("timeline/aligner")).toString(), QStringLiteral("sphinx"));
        QVERIFY(m_panel->adaptToSpeakerAction()->isEnabled());
        const int steps = m_context.undoStack()->index();
        QVERIFY(m_context.document()->requestTiersChange(0, Tier{"words", {}}, Tier{"phones", {}}, QStringLiteral("clear")));
        m_panel->alignAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
        QCOMPARE(m_context.undoStack()->index(), steps + 2);
        const Sequence &s = m_context.document()->sequence(0);
        QStringList spoken;
        for (const Interval &w : s.words.intervals)
            if (!PhoneSet::isSilence(w.label))
                spoken << QString::fromStdString(w.label).toLower();
        QCOMPARE(spoken.size(), int(Lexicon::splitWords(s.transcript).size()));
        QVERIFY(s.phones.intervals.size() > 10);
        QVERIFY(m_view->phones() == s.phones);
        m_context.undoStack()->undo();
        m_context.undoStack()->undo();
        // Adapted to the speaker: the same words, through the same task and undo.
        m_panel->adaptToSpeakerAction()->setChecked(true);
        m_panel->alignAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
        QCOMPARE(m_context.undoStack()->index(), steps + 1);
        QStringList adapted;
        for (const Interval &w : m_context.document()->sequence(0).words.intervals)
            if (!PhoneSet::isSilence(w.label))
                adapted << QString::fromStdString(w.label).toLower();
        QCOMPARE(adapted, spoken);
        m_context.undoStack()->undo();
        m_panel->adaptToSpeakerAction()->setChecked(false);
        m_panel->builtInAlignerAction()->trigger();
        QVERIFY(m_panel->adaptToSpeakerAction()->isEnabled());
        QCOMPARE(QSettings().value(QStringLiteral("timeline/aligner")).toString(), QStringLiteral("builtin"));
    }

    void alignAllIsOneStepAndCancelChangesNothing()
    {
        ProjectDocument *doc = m_context.document();
        std::vector<TierPair> before;
        for (int row = 0; row < doc->sequenceCount(); ++row)
            before.push_back(TierPair{doc->sequence(row).words, doc->sequence(row).phones});
        const int steps = m_context.undoStack()->index();

        // Canceled at once: nothing reaches the document.
        m_panel->alignAllAction()->trigger();
        QCOMPARE(m_context.taskRunner()->runningCount(), 1);
        m_context.taskRunner()->cancelAll();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
        QCOMPARE(m_context.undoStack()->index(), steps);
        for (int row = 0; row < doc->sequenceCount(); ++row)
            QVERIFY(TierPair(TierPair{doc->sequence(row).words, doc->sequence(row).phones}) == before[size_t(row)]);

        // Run to the end: every sequence aligned to its transcript, one undo step for all.
        m_panel->alignAllAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000);
        QCOMPARE(m_context.undoStack()->index(), steps + 1);
        for (int row = 0; row < doc->sequenceCount(); ++row) {
            const Sequence &s = doc->sequence(row);
            QStringList spoken;
            for (const Interval &w : s.words.intervals)
                if (!PhoneSet::isSilence(w.label))
                    spoken << QString::fromStdString(w.label);
            QCOMPARE(spoken.size(), int(Lexicon::splitWords(s.transcript).size()));
            QVERIFY(!s.phones.isEmpty());
        }
        m_context.undoStack()->undo();
        for (int row = 0; row < doc->sequenceCount(); ++row)
            QVERIFY(TierPair(TierPair{doc->sequence(row).words, doc->sequence(row).phones}) == before[size_t(row)]);
    }

    void failedAlignmentIsReportedAndChangesNothing()
    {
        // 300 words cannot fit 3 s of audio: the task fails, the error names the clip and why.
        ProjectDocument *doc = m_context.document();
        QStringList words;
        for (int i = 0; i < 150; ++i)
            words << QStringLiteral("bin blue");
        QVERIFY(doc->requestTranscriptChange(0, words.join(QLatin1Char(' '))));
        const TierPair before = tiers();
        const int steps = m_context.undoStack()->index();
        m_panel->alignAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
        const QString message = ErrorReporter::lastMessage();
        QVERIFY2(message.contains(QStringLiteral("bbaf2n.mpg")) && message.contains(QStringLiteral("does not fit")),
                 qPrintable(message));
        QVERIFY(tiers() == before);
        QCOMPARE(m_context.undoStack()->index(), steps);
        m_context.undoStack()->undo(); // the transcript
    }

private:
    TierPair tiers() const
    {
        const Sequence &s = m_context.document()->sequence(0);
        return TierPair{s.words, s.phones};
    }

    StudioContext m_context;
    QWidget m_host; // the timeline dock's place
    TimelinePanel *m_panel = nullptr;
    WaveformView *m_view = nullptr;
};

QTEST_MAIN(TestTimelineEditor)
#include "tst_timelineeditor.moc"
