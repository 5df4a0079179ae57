#include "timeline/TimelinePanel.h"

#include "timeline/IntervalLabelEditor.h"

#include "align/FrameLabels.h"
#include "align/ProjectAligner.h"
#include "align/SphinxAligner.h"
#include "audio/WaveformPeaks.h"
#include "context/CommandRegistry.h"
#include "context/ErrorReporter.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "render/SpeechToFace.h"
#include "tasks/TaskRunner.h"
#include "timeline/AlignTask.h"
#include "timeline/PronunciationsDialog.h"
#include "timeline/SpeakerAlignerTrainer.h"
#include "timeline/WaveformView.h"
#include "util/PhoneSet.h"

#include <QAction>
#include <QActionGroup>
#include <QMenu>
#include <QComboBox>
#include <QFileInfo>
#include <QFocusEvent>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QScrollBar>
#include <QSettings>
#include <QSignalBlocker>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

#include <cmath>
#include <utility>

namespace lipsync::studio {

namespace {
// The scroll bar counts milliseconds.
constexpr double kUnitsPerSecond = 1000.0;
} // namespace

TimelinePanel::TimelinePanel(QWidget *parent)
    : QWidget(parent), m_banner(new QLabel(this)), m_waveform(new WaveformView(this)),
      m_scroll(new QScrollBar(Qt::Horizontal, this)), m_labelEditor(new IntervalLabelEditor(m_waveform, this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    m_banner->setObjectName(QStringLiteral("timelineBanner"));
    m_banner->setContentsMargins(6, 2, 6, 2);
    m_banner->setAutoFillBackground(true);
    m_banner->setBackgroundRole(QPalette::ToolTipBase);
    m_banner->setForegroundRole(QPalette::ToolTipText);
    m_banner->hide();
    layout->addWidget(m_banner);
    layout->addWidget(m_waveform, 1);

    createActions();
    layout->addLayout(createButtonBar());
    connectActions();
    syncScrollBar();
}

// Actions: buttons below the view, the editing ones in the view's context menu with keys that
// work while the view has focus; the aligner's choices and the spectrogram, remembered.
void TimelinePanel::createActions()
{
    auto makeAction = [this](const QString &text, const QString &tip, const QKeySequence &key = {}) {
        auto *a = new QAction(text, this);
        a->setToolTip(key.isEmpty() ? tip : QStringLiteral("%1 (%2)").arg(tip, key.toString(QKeySequence::NativeText)));
        if (!key.isEmpty()) {
            a->setShortcut(key);
            a->setShortcutContext(Qt::WidgetShortcut);
        }
        return a;
    };
    m_align = makeAction(tr("Align"), tr("Align this sequence's transcript to its audio (words and phones)"));
    m_alignAll = makeAction(tr("Align All"), tr("Align every sequence that has a transcript"));
    m_realign = makeAction(tr("Re-align Selection"),
                           tr("Align the selected stretch again, keeping the words whose timing you edited"));
    // Speaker adaptation (SpeakerAdaptation of the built-in model, SphinxAdaptation of CMU
    // Sphinx's): for voices unlike the models' training speakers; about five times the built-in
    // alignment's time and twice CMU Sphinx's, so a choice, remembered.
    m_adaptAction = makeAction(tr("Adapt to Speaker"),
                               tr("Adapt the aligner to each recording's voice before aligning it (slower; "
                                  "better for voices unlike the model's training speakers)"));
    m_adaptAction->setCheckable(true);
    m_adaptAction->setChecked(QSettings().value(QStringLiteral("timeline/adaptToSpeaker"), false).toBool());
    connect(m_adaptAction, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue(QStringLiteral("timeline/adaptToSpeaker"), on);
        publishAlignerChoice();
    });
    // The aligner's acoustic model: the built-in one knows only the GRID speaker; CMU Sphinx's
    // generic US-English model (SphinxAligner) has heard many. A choice, remembered like the above.
    m_builtInAlignerAction = makeAction(tr("Built-in Model (GRID Speaker)"),
                                        tr("Align with the model shipped with the studio, trained on one GRID speaker"));
    m_sphinxAlignerAction = makeAction(tr("Generic US English (CMU Sphinx)"),
                                       tr("Align with CMU Sphinx's US-English model trained on many speakers "
                                          "(Debian package pocketsphinx-en-us)"));
    auto *alignerGroup = new QActionGroup(this);
    for (QAction *a : {m_builtInAlignerAction, m_sphinxAlignerAction}) {
        a->setCheckable(true);
        alignerGroup->addAction(a);
    }
    const bool sphinxAvailable = SphinxAligner::available();
    m_sphinxAlignerAction->setEnabled(sphinxAvailable);
    const bool sphinxChosen = sphinxAvailable
                              && QSettings().value(QStringLiteral("timeline/aligner")).toString() == QLatin1String("sphinx");
    (sphinxChosen ? m_sphinxAlignerAction : m_builtInAlignerAction)->setChecked(true);
    connect(m_sphinxAlignerAction, &QAction::toggled, this, [this](bool on) {
        QSettings().setValue(QStringLiteral("timeline/aligner"), on ? QStringLiteral("sphinx") : QStringLiteral("builtin"));
        publishAlignerChoice();
        updateActions();
    });
    m_split = makeAction(tr("Split at Cursor"), tr("Split the interval under the cursor"), QKeySequence(Qt::Key_S));
    m_merge = makeAction(tr("Merge with Next"), tr("Join the selected interval with the next one"),
                         QKeySequence(Qt::Key_M));
    m_relabel = makeAction(tr("Relabel…"), tr("Change the label of the selected interval"),
                           QKeySequence(Qt::Key_Return));
    m_insertSilence = makeAction(tr("Insert Silence"), tr("Make the selection a silence"), QKeySequence(Qt::Key_I));
    m_insertBreath = makeAction(tr("Insert Breath"), tr("Make the selection a breath"), QKeySequence(Qt::Key_B));
    m_playSelection = makeAction(tr("Play Selection"), tr("Play the selected stretch (Space in the timeline)"));
    m_playWord = makeAction(tr("Play Word"), tr("Play the word under the cursor"));
    m_playAll = makeAction(tr("Play All"), tr("Play the whole sequence"));
    m_pronunciationsAction = makeAction(tr("Pronunciations…"),
                                        tr("The project's pronunciations, and the words espeak-ng guessed"));
    m_relabel->setShortcuts({QKeySequence(Qt::Key_Return), QKeySequence(Qt::Key_Enter)});
    for (QAction *a : {m_split, m_merge, m_relabel, m_insertSilence, m_insertBreath, m_playSelection})
        m_waveform->addAction(a);
    m_waveform->setContextMenuPolicy(Qt::ActionsContextMenu);

    m_spectrogramAction = new QAction(tr("Show Spectrogram"), this);
    m_spectrogramAction->setToolTip(tr("Show the spectrogram under the waveform in the timeline"));
    m_spectrogramAction->setCheckable(true);
    m_spectrogramAction->setChecked(QSettings().value(QStringLiteral("timeline/spectrogram"), false).toBool());
    m_waveform->setSpectrogramVisible(m_spectrogramAction->isChecked());
    connect(m_spectrogramAction, &QAction::toggled, this, [this](bool on) {
        m_waveform->setSpectrogramVisible(on);
        QSettings().setValue(QStringLiteral("timeline/spectrogram"), on);
    });
}

// The bar under the view: alignment, the aligner's model, playback, the scroll bar and zoom.
QHBoxLayout *TimelinePanel::createButtonBar()
{
    auto *bar = new QHBoxLayout;
    bar->setContentsMargins(4, 0, 4, 2);
    bar->setSpacing(2);
    auto addButton = [this, bar](QAction *action) {
        auto *b = new QToolButton(this);
        b->setDefaultAction(action);
        b->setAutoRaise(true);
        bar->addWidget(b);
        return b;
    };
    auto makeButton = [this, bar](const QString &text, const QString &tip) {
        auto *b = new QToolButton(this);
        b->setText(text);
        b->setToolTip(tip);
        b->setAutoRaise(true);
        bar->addWidget(b);
        return b;
    };
    for (QAction *a : {m_align, m_alignAll, m_realign})
        addButton(a);
    auto *alignerButton = new QToolButton(this);
    alignerButton->setText(tr("Model"));
    alignerButton->setToolTip(tr("The acoustic model the aligner uses"));
    alignerButton->setPopupMode(QToolButton::InstantPopup);
    alignerButton->setAutoRaise(true);
    m_alignerMenu = new QMenu(alignerButton);
    m_alignerMenu->addActions({m_builtInAlignerAction, m_sphinxAlignerAction});
    alignerButton->setMenu(m_alignerMenu);
    bar->addWidget(alignerButton);
    for (QAction *a : {m_adaptAction, m_pronunciationsAction, m_playSelection, m_playWord, m_playAll})
        addButton(a);
    bar->addWidget(m_scroll, 1);
    QToolButton *zoomOut = makeButton(QStringLiteral("−"), tr("Zoom out (wheel down)"));
    QToolButton *zoomIn = makeButton(QStringLiteral("+"), tr("Zoom in (wheel up)"));
    QToolButton *fit = makeButton(tr("Fit"), tr("Show the whole sequence"));

    connect(zoomIn, &QToolButton::clicked, this, [this] { m_waveform->zoomBy(2.0, m_waveform->width() / 2.0); });
    connect(zoomOut, &QToolButton::clicked, this, [this] { m_waveform->zoomBy(0.5, m_waveform->width() / 2.0); });
    connect(fit, &QToolButton::clicked, m_waveform, &WaveformView::zoomToFit);
    connect(m_waveform, &WaveformView::viewChanged, this, &TimelinePanel::syncScrollBar);
    connect(m_scroll, &QScrollBar::valueChanged, this, [this](int value) {
        if (!m_syncing)
            m_waveform->setViewStart(value / kUnitsPerSecond);
    });
    return bar;
}

void TimelinePanel::connectActions()
{
    connect(m_waveform, &WaveformView::boundaryDragStarted, this, &TimelinePanel::onDragStarted);
    connect(m_waveform, &WaveformView::boundaryDragged, this, &TimelinePanel::onDragged);
    connect(m_waveform, &WaveformView::boundaryDragFinished, this, [this] { m_dragKey = -1; });
    connect(m_waveform, &WaveformView::relabelRequested, this, &TimelinePanel::openLabelEditor);
    connect(m_labelEditor, &IntervalLabelEditor::labelChosen, this, &TimelinePanel::relabel);
    connect(m_waveform, &WaveformView::playRequested, this, &TimelinePanel::togglePlay);
    connect(m_waveform, &WaveformView::selectionChanged, this, &TimelinePanel::updateActions);
}

void TimelinePanel::syncScrollBar()
{
    m_syncing = true;
    const int page = int(std::lround(m_waveform->visibleDuration() * kUnitsPerSecond));
    const int total = int(std::lround(m_waveform->duration() * kUnitsPerSecond));
    m_scroll->setRange(0, std::max(0, total - page));
    m_scroll->setPageStep(std::max(1, page));
    m_scroll->setSingleStep(std::max(1, page / 10));
    m_scroll->setValue(int(std::lround(m_waveform->viewStart() * kUnitsPerSecond)));
    m_scroll->setEnabled(total > page);
    m_syncing = false;
}

void TimelinePanel::attach(StudioContext *context)
{
    m_context = context;
    m_document = context->document();
    adoptCommands();
    m_speakerAligner = new SpeakerAlignerTrainer(context, this);
    m_alignerMenu->addSeparator();
    m_alignerMenu->addAction(m_speakerAligner->action());
    publishAlignerChoice();
    m_waveform->setEditable(true);
    // A click moves what the timeline shows: the sequence, or the Preview's new speech.
    connect(m_waveform, &WaveformView::timeClicked, context, &StudioContext::seek);
    connect(m_document, &ProjectDocument::documentReset, this, [this] {
        applyProjectAligner();
        publishAlignerChoice(); // another project: perhaps its own aligner
        // Which aligner the timeline uses, said once the project's first sequence is shown, after
        // that sequence's own message: a project of the user's own aligned with the model of
        // GRID's one speaker is told what fits another speaker better (the demo is GRID's
        // speaker); one whose speaker is another is told that the generic model is in use.
        m_alignerHintPending = m_document->isOpen() && !m_document->isReadOnly() && m_document->sequenceCount() > 0
                               && !m_document->project().model("aligner")
                               && (m_builtInAlignerAction->isChecked() || m_document->project().alignsGeneric());
        showSequence(-1);
    });
    connect(m_document, &ProjectDocument::modelsChanged, this, &TimelinePanel::publishAlignerChoice);
    connect(m_document, &ProjectDocument::sequenceChanged, this, [this](int row) {
        if (row == m_row)
            refresh();
        updateActions();
    });
    connect(context, &StudioContext::sequenceLoaded, this, [this] {
        showSequence(m_context->currentSequence());
        if (std::exchange(m_alignerHintPending, false))
            m_context->showStatus((m_sphinxAlignerAction->isChecked() && m_adaptAction->isChecked()
                                       ? tr("The timeline aligns with Generic US English, adapted to each recording's "
                                            "speaker (Model menu): the built-in model knows only GRID's speaker s1.")
                                       : tr("The timeline aligns with the built-in model of GRID's speaker s1. For "
                                            "another speaker, choose Model ▸ Generic US English and Adapt to Speaker."))
                                      + m_speakerAligner->offer(),
                                  20000);
    });
    // The one player: the main window follows its frames; the timeline's cursor follows its
    // exact position (between frame centres), whoever started it.
    m_player = context->playback();
    connect(m_player, &PlaybackController::positionChanged, this, [this](double t) {
        if (m_player->mediaPath() == m_mediaPath)
            m_waveform->setCursorTime(t);
    });
    connect(context->taskRunner(), &TaskRunner::taskFinished, this, [this] { updateActions(); });
    connect(context, &StudioContext::shownSpeechChanged, this, [this] { showGeneratedSpeech(m_context->shownSpeech()); });
    // The selected stretch is the context's (the preview's Loop selection plays it).
    connect(m_waveform, &WaveformView::selectionChanged, this, [this] {
        double a = 0, b = 0;
        if (!m_waveform->selection(&a, &b))
            a = b = 0.0;
        m_context->setSelection(a, b);
    });
    updateActions();
}

void TimelinePanel::showSequence(int row)
{
    m_labelEditor->close();
    m_speech.reset();
    m_banner->hide();
    m_waveform->setEditable(m_document != nullptr);
    m_row = m_document && row < m_document->sequenceCount() ? row : -1;
    m_dragKey = -1;
    m_mediaPath = m_row >= 0 ? m_document->mediaPath(m_row) : QString();
    const std::shared_ptr<const SequenceMedia> media = m_row >= 0 && m_context ? m_context->media() : nullptr;
    if (media) {
        m_waveform->setPeaks(media->peaks);
        m_waveform->setThumbnails(media->thumbnails, media->clock);
        // The whole timeline: to the last frame's end or the sound's, whichever is later.
        m_waveform->setDuration(std::max(media->clock.endTime(),
                                         media->peaks ? double(media->peaks->samples().size()) / media->peaks->sampleRate() : 0.0));
        m_waveform->setPlaceholderText(media->peaks ? QString() : tr("No audio: %1").arg(media->audioError));
    }
    m_waveform->setSpectrogram(media ? media->spectrogram : nullptr);
    m_waveform->clearSelection();
    refresh();
}

void TimelinePanel::showGeneratedSpeech(std::shared_ptr<const SpeechToFaceResult> speech)
{
    if (!speech) {
        if (m_speech)
            showSequence(m_context ? m_context->currentSequence() : -1);
        return;
    }
    m_labelEditor->close();
    m_speech = std::move(speech);
    m_row = -1; // no sequence of the document is shown: nothing here can be edited
    m_dragKey = -1;
    m_mediaPath = QString::fromStdString(m_speech->mediaPath);
    m_banner->setText(tr("Alignment of the speech in the Preview: %1 (read-only; Back to Sequence there to edit)")
                          .arg(QFileInfo(m_mediaPath).fileName()));
    m_banner->show();
    m_waveform->setEditable(false);
    m_waveform->clearSelection();
    m_waveform->setSpectrogram(nullptr);
    m_waveform->setPeaks(m_speech->audio.samples.empty()
                             ? nullptr
                             : std::make_shared<const WaveformPeaks>(m_speech->audio.samples, m_speech->audio.sampleRate));
    m_waveform->setThumbnails({}, m_speech->frames);
    m_waveform->setWords(m_speech->words);
    m_waveform->setPhones(m_speech->phones);
    m_waveform->setFrameLabels(voteFrameLabels(m_speech->phones, m_speech->frames), m_speech->frames);
    m_waveform->setDuration(m_speech->frames.endTime());
    m_waveform->setPlaceholderText(m_speech->audio.samples.empty() ? tr("No audio") : QString());
    m_waveform->setCursorTime(0.0);
    updateActions();
}

void TimelinePanel::refresh()
{
    if (m_speech)
        return; // the generated speech's tiers stay until showSequence
    if (!m_document || m_row < 0) {
        m_waveform->setPhones({});
        m_waveform->setFrameLabels({}, {});
        updateActions();
        return;
    }
    const Sequence &s = m_document->sequence(m_row);
    m_waveform->setWords(s.words);
    m_waveform->setPhones(s.phones);
    // The media's own clock when loaded (the timestamps as decoded), else the project's record.
    const FrameClock clock = m_context->media() && m_context->media()->frameCount() > 0 ? m_context->media()->clock
                                                                                         : s.clock();
    m_waveform->setFrameLabels(s.phones.isEmpty() ? std::vector<std::string>{} : voteFrameLabels(s.phones, clock),
                               clock);
    updateActions();
}

void TimelinePanel::updateActions()
{
    if (m_context)
        m_context->commands()->revalidate();
}

void TimelinePanel::adoptCommands()
{
    // The row shown may be gone already when the registry asks (it hears of a removal first).
    auto open = [this] { return m_document && m_row >= 0 && m_row < m_document->sequenceCount(); };
    auto aligning = [this] { return m_alignTask && m_alignTask->isRunning(); };
    auto selection = [this, open] {
        double a = 0, b = 0;
        return open() && m_waveform->selection(&a, &b);
    };
    auto adopt = [this](const char *name, QAction *action, void (TimelinePanel::*run)(), std::function<bool()> can) {
        connect(action, &QAction::triggered, this, run);
        m_context->commands()->adopt(QLatin1String(name), action, [can](const StudioContext &) { return can(); }, this);
    };
    adopt("timeline/align", m_align, &TimelinePanel::alignSequence, [this, open, aligning] {
        return open() && !m_document->sequence(m_row).transcript.empty() && !aligning();
    });
    adopt("timeline/align-all", m_alignAll, &TimelinePanel::alignAll,
          [this, aligning] { return m_document->sequenceCount() > 0 && !aligning(); });
    adopt("timeline/realign-selection", m_realign, &TimelinePanel::realignSelection, [this, selection, aligning] {
        return selection() && !aligning() && !m_waveform->words().isEmpty();
    });
    adopt("timeline/split", m_split, &TimelinePanel::splitAtCursor, open);
    adopt("timeline/merge", m_merge, &TimelinePanel::mergeWithNext, open);
    adopt("timeline/relabel", m_relabel, &TimelinePanel::relabelSelected, open);
    adopt("timeline/insert-silence", m_insertSilence, &TimelinePanel::insertSilence, selection);
    adopt("timeline/insert-breath", m_insertBreath, &TimelinePanel::insertBreath, selection);
    adopt("timeline/play-selection", m_playSelection, &TimelinePanel::playSelection, open);
    adopt("timeline/play-word", m_playWord, &TimelinePanel::playWord, open);
    adopt("timeline/play-all", m_playAll, &TimelinePanel::playAll, open);
    adopt("timeline/pronunciations", m_pronunciationsAction, &TimelinePanel::showPronunciations,
          [this] { return m_document->isOpen(); });
}

TierPair TimelinePanel::currentTiers() const
{
    if (!m_document || m_row < 0)
        return {};
    const Sequence &s = m_document->sequence(m_row);
    return TierPair{s.words, s.phones, s.transcriptFit};
}

bool TimelinePanel::edit(const TierPair &next, const QString &text, int mergeKey)
{
    if (!m_document || m_row < 0)
        return false;
    return m_document->requestTiersChange(m_row, next.words, next.phones, text, mergeKey);
}

// --- alignment ---

void TimelinePanel::alignSequence()
{
    if (!m_document || m_row < 0)
        return;
    std::vector<AlignJob> jobs = alignmentJobs({m_row});
    if (jobs.empty())
        return;
    const QString title = tr("Align %1").arg(jobs.front().sequenceId);
    startAlignment(title, std::move(jobs));
}

void TimelinePanel::alignAll()
{
    if (!m_document)
        return;
    std::vector<int> rows;
    for (int row = 0; row < m_document->sequenceCount(); ++row)
        if (!m_document->sequence(row).transcript.empty())
            rows.push_back(row);
    if (rows.empty()) {
        ErrorReporter::report(this, tr("No sequence has a transcript to align."), QString(), QString());
        return;
    }
    std::vector<AlignJob> jobs = alignmentJobs(rows);
    if (!jobs.empty())
        startAlignment(tr("Align all sequences"), std::move(jobs));
}

std::vector<AlignJob> TimelinePanel::alignmentJobs(const std::vector<int> &rows)
{
    // Edited boundaries stay (alignmentFor): only where the transcript changed since they were
    // made would aligning replace them, and then the user decides.
    std::vector<SequenceAlignment> plans;
    QStringList discarding, untouched;
    for (int row : rows) {
        plans.push_back(alignmentFor(row, m_document->sequence(row), m_document->mediaPath(row),
                                     m_document->project().pronunciations));
        if (plans.back().discardsEdits)
            discarding << plans.back().job.sequenceId;
        if (plans.back().nothingToAlign)
            untouched << plans.back().job.sequenceId;
    }
    if (!discarding.isEmpty() && !ErrorReporter::isBatchMode()
        && QMessageBox::question(this, tr("Align"),
                                 tr("The transcript of %1 changed since its boundaries were edited. Aligning "
                                    "it again replaces the edited boundaries. Align anyway?")
                                     .arg(discarding.join(QStringLiteral(", "))))
               != QMessageBox::Yes)
        return {};
    std::vector<AlignJob> jobs;
    for (SequenceAlignment &plan : plans)
        if (!plan.nothingToAlign)
            jobs.push_back(std::move(plan.job));
    if (!untouched.isEmpty() && m_context)
        m_context->showStatus(
            tr("Every word of %1 is user-edited: nothing to align there.").arg(untouched.join(QStringLiteral(", "))),
            8000);
    return jobs;
}

void TimelinePanel::realignSelection()
{
    double a = 0, b = 0;
    if (!m_document || m_row < 0 || !m_waveform->selection(&a, &b))
        return;
    const TierPair tiers = currentTiers();
    AlignJob job;
    job.row = m_row;
    job.sequenceId = QString::fromStdString(m_document->sequence(m_row).id);
    job.mediaPath = m_document->mediaPath(m_row);
    job.current = tiers;
    job.pronunciations = m_document->project().pronunciations;
    job.stretches = realignStretches(tiers, a, b);
    if (job.stretches.empty()) {
        if (m_context)
            m_context->showStatus(
                tr("Nothing to re-align: the selection holds no words, or only words you edited."), 5000);
        return;
    }
    startAlignment(tr("Re-align %1").arg(job.sequenceId), {job});
}

void TimelinePanel::applyProjectAligner()
{
    if (!m_document || !m_document->isOpen())
        return;
    // The project says whose aligner (Project::aligner, or a model of its own): that, for as
    // long as it is open; a project that does not say keeps the last choice. Not remembered as
    // the user's choice.
    const std::optional<AlignerChoice> said = projectAlignerChoice(m_document->project());
    if (!said || (said->isSphinx() && !m_sphinxAlignerAction->isEnabled()))
        return;
    const bool generic = said->isSphinx();
    const QSignalBlocker blockBuiltIn(m_builtInAlignerAction), blockSphinx(m_sphinxAlignerAction),
        blockAdapt(m_adaptAction);
    m_builtInAlignerAction->setChecked(!generic);
    m_sphinxAlignerAction->setChecked(generic);
    m_adaptAction->setChecked(generic);
}

void TimelinePanel::publishAlignerChoice()
{
    if (!m_context)
        return;
    // Ours: the project's own aligner when it names one (its speaker's), else the shipped model.
    const bool open = m_document && m_document->isOpen();
    const std::string model = open ? projectAlignerModel(m_document->project()) : std::string();
    m_builtInAlignerAction->setText(
        model.empty() ? tr("Built-in Model (GRID Speaker)")
                      : tr("The Project's Aligner (%1)")
                            .arg(QString::fromStdString(m_document->project().model("aligner")->name)));
    m_context->modelStore()->setAlignerChoice(
        AlignerChoice{m_sphinxAlignerAction->isChecked() ? "sphinx" : model, m_adaptAction->isChecked()});
}

void TimelinePanel::startAlignment(const QString &title, std::vector<AlignJob> jobs)
{
    if (!m_context)
        return;
    for (AlignJob &job : jobs) {
        job.aligner = m_context->modelStore()->alignerChoice();
        // How well each transcript fits its sound, for the sequence list's mark.
        job.aligner.transcriptFit = true;
    }
    QPointer<TimelinePanel> self(this);
    Task *task = lipsync::studio::startAlignment(*m_context->taskRunner(), title, std::move(jobs),
                                                 m_context->modelStore()->aligners(),
                                                 [self, title](std::vector<AlignOutcome> outcomes) {
                                                     if (self)
                                                         self->applyAlignment(title, std::move(outcomes));
                                                 });
    m_alignTask = task;
    connect(task, &Task::finished, this, [this, task](Task::State state) {
        if (state == Task::State::Failed)
            ErrorReporter::report(this, tr("The alignment failed."), QString(), task->errorMessage());
        updateActions();
    });
    updateActions();
    emit alignmentStarted(task);
}

void TimelinePanel::applyAlignment(const QString &title, std::vector<AlignOutcome> outcomes)
{
    if (!m_document)
        return;
    QStringList failed, misfits;
    QString file;
    QUndoStack *undo = m_context->undoStack();
    int ok = 0;
    int guessed = 0;
    for (const AlignOutcome &o : outcomes) {
        ok += o.ok ? 1 : 0;
        for (const auto &[word, phones] : o.guessed)
            guessed += m_guessed.insert_or_assign(word, phones).second ? 1 : 0;
    }
    if (m_pronunciations)
        m_pronunciations->setGuesses(m_guessed);
    if (guessed > 0 && m_context)
        m_context->showStatus(
            tr("espeak-ng guessed the pronunciation of %n word(s): check them in Pronunciations…", "", guessed), 8000);
    if (ok > 1)
        undo->beginMacro(title);
    int changed = 0;
    for (const AlignOutcome &o : outcomes) {
        // The document may have changed meanwhile: find the sequence by id.
        if (!o.ok) {
            failed << QStringLiteral("%1: %2").arg(o.sequenceId, o.error);
            file = o.errorFile;
            continue;
        }
        int row = o.row;
        if (row >= m_document->sequenceCount()
            || QString::fromStdString(m_document->sequence(row).id) != o.sequenceId)
            continue;
        changed += m_document->requestAlignedTiers(row, o.tiers, title) ? 1 : 0;
        if (transcriptMisfit(o.tiers.transcriptFit))
            misfits << o.sequenceId;
    }
    if (ok > 1)
        undo->endMacro();
    if (ok > 0 && changed == 0 && m_context)
        m_context->showStatus(tr("%1: the alignment came out as it was; nothing changed.").arg(title),
                                           8000);
    // A transcript that does not fit its sound (TranscriptFit): said now, marked in
    // the sequence list until the sequence is aligned again. When none fits a model of ours, it is
    // more likely not the speaker's than every transcript wrong (the generic one adapts to them).
    if (!misfits.isEmpty() && m_context) {
        if (ok >= 3 && misfits.size() == ok && !m_context->modelStore()->alignerChoice().isSphinx())
            m_context->showStatus(tr("No transcript fits its sound by this aligner: its model probably does not know "
                                     "this speaker. Choose Model ▸ Generic US English and Adapt to Speaker, or "
                                     "train the project's own aligner."),
                                  20000);
        else
            m_context->showStatus(tr("%n transcript(s) do not fit the sound: %1. Check that they are the clips' words "
                                     "(marked in the sequence list).", "", int(misfits.size()))
                                      .arg(misfits.join(QStringLiteral(", "))),
                                  20000);
    }
    if (!failed.isEmpty())
        ErrorReporter::report(this, tr("%n sequence(s) could not be aligned; the others were.", "", int(failed.size())),
                              failed.size() == 1 ? file : QString(), failed.join(QLatin1Char('\n')));
}

PronunciationsDialog *TimelinePanel::pronunciationsDialog() const
{
    return m_pronunciations;
}

void TimelinePanel::showPronunciations()
{
    if (!m_document)
        return;
    if (!m_pronunciations)
        m_pronunciations = new PronunciationsDialog(m_document, this);
    m_pronunciations->setGuesses(m_guessed);
    m_pronunciations->show();
    m_pronunciations->raise();
    m_pronunciations->activateWindow();
}

// --- edits ---

void TimelinePanel::onDragStarted(TierKind, int, int drag)
{
    m_labelEditor->close();
    m_dragBase = currentTiers();
    m_dragKey = drag;
    ++m_dragMergeKey;
}

void TimelinePanel::onDragged(TierKind kind, int boundary, double time, int drag)
{
    if (drag != m_dragKey)
        return;
    TierPair next = m_dragBase;
    tieredit::moveBoundary(next, kind, boundary, time);
    // Every move of one drag carries the same key: the stack merges them into one step, and
    // back at the start the step disappears.
    edit(next, kind == TierKind::Words ? tr("Move word boundary") : tr("Move phone boundary"), m_dragMergeKey);
}

void TimelinePanel::splitAtCursor()
{
    const TierKind kind = m_waveform->activeTier();
    TierPair next = currentTiers();
    if (tieredit::split(next, kind, m_waveform->cursorTime()))
        edit(next, tr("Split interval"));
}

void TimelinePanel::mergeWithNext()
{
    const TierKind kind = m_waveform->activeTier();
    TierPair next = currentTiers();
    int index = m_waveform->selectedInterval();
    if (index < 0)
        index = next[kind].indexAt(m_waveform->cursorTime());
    // Two phones of different words: joined only with their words, if the user says so.
    const int word = kind == TierKind::Phones ? tieredit::wordBetweenPhones(next, index) : -1;
    if (word >= 0) {
        const auto &words = next.words.intervals;
        const QString first = QString::fromStdString(words[size_t(word)].label);
        const QString second = QString::fromStdString(words[size_t(word) + 1].label);
        QMessageBox box(QMessageBox::Question, tr("Merge with Next"),
                        tr("These phones belong to two words, “%1” and “%2”. Merge the words as well?").arg(first, second),
                        QMessageBox::NoButton, this);
        box.setObjectName(QStringLiteral("mergeAcrossWordsBox"));
        QPushButton *both = box.addButton(tr("Merge Phones and Words"), QMessageBox::AcceptRole);
        box.setDefaultButton(box.addButton(QMessageBox::Cancel));
        box.exec();
        if (box.clickedButton() != both || !tieredit::mergeWithNext(next, TierKind::Words, word))
            return;
    }
    if (tieredit::mergeWithNext(next, kind, index) && edit(next, word >= 0 ? tr("Merge phones and words") : tr("Merge intervals")))
        m_waveform->selectInterval(kind, index);
}

void TimelinePanel::relabelSelected()
{
    const TierKind kind = m_waveform->activeTier();
    int index = m_waveform->selectedInterval();
    if (index < 0)
        index = m_waveform->tier(kind).indexAt(m_waveform->cursorTime());
    if (index >= 0)
        openLabelEditor(kind, index);
}

void TimelinePanel::insertSilence()
{
    insertInterval(std::string(PhoneSet::kSilenceLabel));
}

void TimelinePanel::insertBreath()
{
    insertInterval(std::string(PhoneSet::kBreathLabel));
}

void TimelinePanel::insertInterval(const std::string &label)
{
    double a = 0, b = 0;
    if (!m_waveform->selection(&a, &b))
        return;
    const TierKind kind = m_waveform->activeTier();
    TierPair next = currentTiers();
    if (tieredit::insertInterval(next, kind, a, b, label)
        && edit(next, PhoneSet::isBreath(label) ? tr("Insert breath") : tr("Insert silence")))
        m_waveform->selectInterval(kind, next[kind].indexAt((tieredit::snap(a) + tieredit::snap(b)) / 2));
}

// --- relabel editor ---

QWidget *TimelinePanel::relabelEditor() const
{
    return m_labelEditor->widget();
}

void TimelinePanel::openLabelEditor(TierKind kind, int index)
{
    if (m_document && m_row >= 0)
        m_labelEditor->open(kind, index);
}

void TimelinePanel::relabel(TierKind kind, int index, const std::string &label)
{
    TierPair next = currentTiers();
    if (tieredit::relabel(next, kind, index, label))
        edit(next, tr("Relabel as %1").arg(QString::fromStdString(label)));
    m_waveform->selectInterval(kind, index);
    m_waveform->setFocus(Qt::OtherFocusReason);
}

// --- playback ---

bool TimelinePanel::preparePlayer()
{
    const auto media = m_context ? m_context->media() : nullptr;
    if (!m_player || !media || media->mediaPath != m_mediaPath)
        return false;
    if (m_player->mediaPath() != m_mediaPath) // it played other media (the preview's new speech)
        m_player->setSequence(media->mediaPath, media->clock);
    m_player->setAudioEnabled(!ErrorReporter::isBatchMode());
    return true;
}

void TimelinePanel::playSelection()
{
    double a = 0, b = 0;
    if (!m_waveform->selection(&a, &b)) {
        a = m_waveform->cursorTime();
        b = m_waveform->duration();
    }
    if (!preparePlayer())
        return;
    m_player->playRange(a, b);
}

void TimelinePanel::playWord()
{
    const Tier &words = m_waveform->words();
    const int i = words.indexAt(m_waveform->cursorTime());
    if (i < 0)
        return;
    if (!preparePlayer())
        return;
    m_player->playRange(words.intervals[size_t(i)].start, words.intervals[size_t(i)].end);
}

void TimelinePanel::playAll()
{
    if (!preparePlayer())
        return;
    m_player->playRange(0.0, m_waveform->duration());
}

void TimelinePanel::togglePlay()
{
    if (m_player && m_player->isPlaying())
        m_player->stop();
    else
        playSelection();
}

} // namespace lipsync::studio
