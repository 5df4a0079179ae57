// The timeline's speech tools on the demo project, the panel on a studio context without the main
// window.
//  - Project pronunciations: aligning a transcript with a word outside the CMU dictionary lists
//    it with espeak-ng's guess in the Pronunciations dialog; setting its phones there (validated
//    against the 41 phones: a bad phone changes nothing) is one undo step, the next alignment uses
//    them (the phone tier shows them), and undo/redo restore the overrides.
//  - The spectrogram lane: View > Show Spectrogram shows it under the waveform with the clip's
//    spectrum (non-uniform pixels), remembers the choice in QSettings, and hides it again.
#include "DemoWindow.h"

#include "align/Aligner.h"
#include "app/SequenceListModel.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/TaskRunner.h"
#include "timeline/PronunciationsDialog.h"
#include "timeline/TimelinePanel.h"
#include "timeline/WaveformView.h"

#include <QAbstractItemView>
#include <QAction>
#include <QIcon>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenu>
#include <QMenuBar>
#include <QSet>
#include <QSettings>
#include <QPushButton>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>

#include <algorithm>

using namespace lipsync;
using namespace lipsync::studio;

class TestSpeechTools : public QObject
{
    Q_OBJECT
public:
    static void initMain() { testing::initStudioTest(); }

private slots:
    void initTestCase()
    {
        testing::openDemoTimeline(m_context, m_host, m_panel);
    }

    void cleanupTestCase() { QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 60000); }

    void canonicalInput()
    {
        QString error;
        QCOMPARE(PronunciationsDialog::canonicalWord(QStringLiteral(" Nowzy, "), &error), std::string("nowzy"));
        QVERIFY(PronunciationsDialog::canonicalWord(QStringLiteral("two words"), &error).empty());
        QCOMPARE(PronunciationsDialog::canonicalPhones(QStringLiteral("n  aw1 z iy0"), &error), std::string("N AW Z IY"));
        QVERIFY(PronunciationsDialog::canonicalPhones(QStringLiteral("N QQ"), &error).empty());
        QVERIFY(error.contains(QStringLiteral("QQ")));
    }

    void guessedWordIsListedAndOverridden()
    {
        ProjectDocument *doc = m_context.document();
        QCOMPARE(m_context.currentSequence(), 0);
        QVERIFY(doc->project().pronunciations.empty());
        // The demo clip says "bin blue at f two now"; "nowzy" is no English word.
        QVERIFY(doc->requestTranscriptChange(0, QStringLiteral("bin blue at f two nowzy")));
        align();
        QVERIFY(m_panel->guessedPronunciations().count("nowzy"));

        QVERIFY(m_panel->pronunciationsAction()->isEnabled());
        m_panel->pronunciationsAction()->trigger();
        PronunciationsDialog *dialog = m_panel->pronunciationsDialog();
        QVERIFY(dialog && dialog->isVisible());
        QTableWidget *table = dialog->table();
        QCOMPARE(table->rowCount(), 1);
        QCOMPARE(table->item(0, 0)->text(), QStringLiteral("nowzy"));
        QVERIFY(!table->item(0, 1)->text().isEmpty());
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("espeak-ng guess"));

        // Selecting the row fills the editor; a phone outside the set is refused.
        table->selectRow(0);
        QCOMPARE(dialog->wordEdit()->text(), QStringLiteral("nowzy"));
        const int steps = m_context.undoStack()->index();
        dialog->phonesEdit()->setText(QStringLiteral("N AW QQ"));
        QTest::mouseClick(dialog->setButton(), Qt::LeftButton);
        QVERIFY(dialog->messageLabel()->text().contains(QStringLiteral("QQ")));
        QCOMPARE(m_context.undoStack()->index(), steps);
        QVERIFY(doc->project().pronunciations.empty());

        // A valid one: one undo step, shown as the project's.
        dialog->phonesEdit()->setText(QStringLiteral("n aw1"));
        QTest::mouseClick(dialog->setButton(), Qt::LeftButton);
        QCOMPARE(m_context.undoStack()->index(), steps + 1);
        QCOMPARE(doc->project().pronunciations, (std::map<std::string, std::string>{{"nowzy", "N AW"}}));
        QCOMPARE(table->rowCount(), 1);
        QCOMPARE(table->item(0, 1)->text(), QStringLiteral("N AW"));
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("project"));

        // The next alignment uses it: the word ends in N AW, and espeak guessed nothing new.
        align();
        QCOMPARE(lastSpokenPhones(2), (QStringList{"N", "AW"}));

        // Undo and redo of the override (the alignment first).
        m_context.undoStack()->undo();
        m_context.undoStack()->undo();
        QVERIFY(doc->project().pronunciations.empty());
        QCOMPARE(table->item(0, 2)->text(), QStringLiteral("espeak-ng guess"));
        m_context.undoStack()->redo();
        QCOMPARE(doc->project().pronunciations.at("nowzy"), std::string("N AW"));

        // Remove it again: one more step.
        dialog->wordEdit()->setText(QStringLiteral("nowzy"));
        QTest::mouseClick(dialog->removeButton(), Qt::LeftButton);
        QVERIFY(doc->project().pronunciations.empty());
        m_context.undoStack()->undo();
        QVERIFY(!doc->project().pronunciations.empty());
    }

    // A transcript that is not the clip's words is marked in the sequence list once aligned (the
    // aligner's transcriptFit below its threshold), with a tooltip that says why; the
    // mark is part of the alignment's undo step, is saved with the project, and goes when the
    // clip's own words are aligned again.
    void misfitTranscriptIsMarked()
    {
        ProjectDocument *doc = m_context.document();
        SequenceListModel model(m_context.document()); // what the sequence list shows
        QAbstractItemModel *list = &model;
        const QModelIndex cell = list->index(0, SequenceListModel::TranscriptColumn);
        auto marked = [&] { return !list->data(cell, Qt::DecorationRole).value<QIcon>().isNull(); };
        // The clip's own words fit.
        QVERIFY(doc->requestTranscriptChange(0, QStringLiteral("bin blue at f two now")));
        align();
        QVERIFY(doc->sequence(0).transcriptFit);
        const double own = doc->sequence(0).transcriptFit->value;
        QCOMPARE(doc->sequence(0).transcriptFit->threshold, kTranscriptFitThreshold); // the shipped aligner's
        QVERIFY2(own >= kTranscriptFitThreshold, qPrintable(QString::number(own)));
        QVERIFY(!marked());
        // Another demo clip's words do not.
        const QString other = QString::fromStdString(doc->sequence(1).transcript);
        QVERIFY(!other.isEmpty() && other != QStringLiteral("bin blue at f two now"));
        QVERIFY(doc->requestTranscriptChange(0, other));
        const int steps = m_context.undoStack()->index();
        align();
        QCOMPARE(m_context.undoStack()->index(), steps + 1); // tiers and mark: one step
        QVERIFY(doc->sequence(0).transcriptFit);
        const double swapped = doc->sequence(0).transcriptFit->value;
        qInfo("transcript fit: own words %.2f, another clip's %.2f nats per frame", own, swapped);
        QVERIFY2(swapped < kTranscriptFitThreshold, qPrintable(QString::number(swapped)));
        QVERIFY(marked());
        QVERIFY(list->data(cell, Qt::ToolTipRole).toString().contains(QStringLiteral("does not fit the sound")));
        // Saved with the project and read back.
        QTemporaryDir dir;
        const Project saved = Project::load([&] {
            Project p = doc->project();
            p.save(dir.path().toStdString());
            return dir.path().toStdString();
        }());
        QCOMPARE(saved.sequences[0].transcriptFit, doc->sequence(0).transcriptFit);
        // Undo takes the alignment and its mark back together.
        m_context.undoStack()->undo();
        QCOMPARE(doc->sequence(0).transcriptFit->value, own);
        QVERIFY(!marked());
        m_context.undoStack()->redo();
        QVERIFY(marked());
        // The right words aligned again: no mark.
        QVERIFY(doc->requestTranscriptChange(0, QStringLiteral("bin blue at f two now")));
        align();
        QVERIFY(!marked());
    }

    // With the generic model adapted to the speaker (the default for a speaker other than the
    // shipped model's) the mark comes from its own fit and threshold.
    void misfitIsMarkedWithTheGenericAligner()
    {
        ProjectDocument *doc = m_context.document();
        SequenceListModel model(doc);
        const QModelIndex cell = model.index(0, SequenceListModel::TranscriptColumn);
        auto marked = [&] { return !model.data(cell, Qt::DecorationRole).value<QIcon>().isNull(); };
        const AlignerChoice before = m_context.modelStore()->alignerChoice();
        m_context.modelStore()->setAlignerChoice(AlignerChoice{"sphinx", true});
        doc->requestTranscriptChange(0, QStringLiteral("bin blue at f two now")); // false: already so
        align();
        QVERIFY(doc->sequence(0).transcriptFit);
        QCOMPARE(doc->sequence(0).transcriptFit->threshold, kSphinxTranscriptFitThreshold);
        QVERIFY(!marked());
        // Words of a clip that shares none of this one's.
        QVERIFY(doc->requestTranscriptChange(0, QStringLiteral("lay red in k four please")));
        align();
        QVERIFY(doc->sequence(0).transcriptFit && doc->sequence(0).transcriptFit->misfit());
        QVERIFY(marked());
        QVERIFY(model.data(cell, Qt::ToolTipRole).toString().contains(QLocale().toString(kSphinxTranscriptFitThreshold, 'f', 1)));
        m_context.modelStore()->setAlignerChoice(before);
        QVERIFY(doc->requestTranscriptChange(0, QStringLiteral("bin blue at f two now")));
        align();
        QVERIFY(!marked());
    }

    void spectrogramFromTheViewMenu()
    {
        WaveformView *view = m_panel->waveform();
        QAction *toggle = m_panel->spectrogramAction(); // the View menu's (tst_mainwindow)
        toggle->setChecked(false);
        QCOMPARE(view->laneRect(WaveformView::Lane::Spectrogram).height(), 0);
        const int waveHeight = view->laneRect(WaveformView::Lane::Waveform).height();

        toggle->trigger();
        QVERIFY(toggle->isChecked() && view->isSpectrogramVisible());
        QVERIFY(QSettings().value(QStringLiteral("timeline/spectrogram")).toBool());
        // The timeline grows rather than squeezing the waveform: both lanes stay legible.
        QTRY_VERIFY(view->laneRect(WaveformView::Lane::Spectrogram).height() >= 60
                    && view->laneRect(WaveformView::Lane::Waveform).height() >= std::min(waveHeight, 60));
        const QRect lane = view->laneRect(WaveformView::Lane::Spectrogram);
        QVERIFY(lane.top() >= view->laneRect(WaveformView::Lane::Waveform).bottom());
        QVERIFY(lane.bottom() < view->laneRect(WaveformView::Lane::Words).top());
        view->zoomToFit();
        const QImage image = view->grab().toImage().convertToFormat(QImage::Format_RGB32);
        // Speech has structure: many distinct colours across the lane, low and high bands differ.
        QSet<QRgb> colours;
        for (int y = lane.top() + 2; y < lane.bottom() - 1; y += 2)
            for (int x = lane.width() / 10; x < lane.width() * 9 / 10; x += 3)
                colours.insert(image.pixel(x, y));
        QVERIFY2(colours.size() > 50, qPrintable(QString::number(colours.size())));

        toggle->trigger();
        QVERIFY(!view->isSpectrogramVisible());
        QVERIFY(!QSettings().value(QStringLiteral("timeline/spectrogram")).toBool());
        QCOMPARE(view->laneRect(WaveformView::Lane::Spectrogram).height(), 0);
    }

private:
    void align()
    {
        QVERIFY(m_panel->alignAction()->isEnabled());
        m_panel->alignAction()->trigger();
        QTRY_COMPARE_WITH_TIMEOUT(m_context.taskRunner()->runningCount(), 0, 30000);
    }

    QStringList lastSpokenPhones(int n) const
    {
        QStringList phones;
        for (const Interval &p : m_context.document()->sequence(0).phones.intervals)
            if (p.label != "sil")
                phones << QString::fromStdString(p.label);
        return phones.mid(phones.size() - n);
    }

    StudioContext m_context;
    QWidget m_host; // the timeline dock's place
    TimelinePanel *m_panel = nullptr;
};

QTEST_MAIN(TestSpeechTools)
#include "tst_speechtools.moc"
