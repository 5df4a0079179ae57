#include "app/MainWindow.h"

#include "annotate/FacesController.h"
#include "annotate/FrameView.h"
#include "app/AboutBox.h"
#include "app/Autosave.h"
#include "app/LongRecordingImporter.h"
#include "app/ProjectFiles.h"
#include "app/SequenceDetailsView.h"
#include "app/SequenceListModel.h"
#include "app/SequenceLoader.h"
#include "app/ShortcutsDialog.h"
#include "app/TranscriptProposer.h"
#include "app/TransportBar.h"
#include "app/UserGuide.h"
#include "app/WheelGuard.h"
#include "build/ModelsPanel.h"
#include "compare/StudyController.h"
#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioActions.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "export/ExportMenu.h"
#include "live/LiveView.h"
#include "plots/LineChartView.h"
#include "preview/PreviewPanel.h"
#include "tasks/TaskRunner.h"
#include "tasks/TaskStatusWidget.h"
#include "timeline/TimelinePanel.h"
#include "timeline/WaveformView.h"

#include <algorithm>

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QHeaderView>
#include <QItemSelectionModel>
#include <QMenuBar>
#include <QMessageBox>
#include <QScreen>
#include <QSettings>
#include <QSignalBlocker>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QLabel>
#include <QTableView>
#include <QTimer>
#include <QToolBar>
#include <QToolButton>
#include <QUndoStack>
#include <QVBoxLayout>

namespace lipsync::studio {

MainWindow::MainWindow(QWidget *parent)
    : QMainWindow(parent), m_context(new StudioContext(this)),
      m_actions(std::make_unique<StudioActions>(this, m_context->undoStack()))
{
    // First, so the window's own views show a frame before the panels hear of it.
    connect(m_context, &StudioContext::currentFrameChanged, this, &MainWindow::showFrame);
    connect(m_context, &StudioContext::statusMessage, this,
            [this](const QString &message, int milliseconds) { statusBar()->showMessage(message, milliseconds); });
    setObjectName(QStringLiteral("MainWindow"));
    setDockNestingEnabled(true);

    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_tabs = new QTabWidget(central);
    m_tabs->setDocumentMode(true);
    m_frameView = new FrameView(m_tabs);
    m_frameView->setObjectName(QStringLiteral("frameView"));
    m_preview = new PreviewPanel(*m_actions, m_tabs);
    m_tabs->addTab(m_frameView, tr("Annotate"));
    m_tabs->addTab(m_preview, tr("Preview && Compare"));
    m_live = new LiveView(m_context, [this] { return m_files->save(); }, m_tabs);
    m_tabs->addTab(m_live, tr("Live"));
    m_transport = new TransportBar(*m_actions, central);
    layout->addWidget(m_tabs, 1);
    layout->addWidget(m_transport);
    // One transport in view: the annotator's below it; the Preview has its own (for the new
    // speech too), Live none.
    connect(m_tabs, &QTabWidget::currentChanged, this,
            [this] { m_transport->setVisible(m_tabs->currentWidget() == m_frameView); });
    setCentralWidget(central);

    createDocks();
    createMenus();
    m_faces = new FacesController(m_context, m_frameView, this);
    connect(m_faces, &FacesController::sequenceRequested, this, &MainWindow::selectSequence);
    const QList<QAction *> top = menuBar()->actions();
    menuBar()->insertMenu(top.isEmpty() ? nullptr : top.last(), m_faces->menu()); // before Help
    m_models->setBuildAamAction(m_faces->buildAamAction());
    m_preview->attach(m_context);
    m_taskStatus = new TaskStatusWidget(m_context->taskRunner(), this);
    m_activeModels = new QLabel(this);
    m_activeModels->setObjectName(QStringLiteral("activeModels"));
    statusBar()->addPermanentWidget(m_activeModels);
    statusBar()->addPermanentWidget(m_taskStatus);

    connect(m_context->document(), &ProjectDocument::documentReset, this, &MainWindow::onDocumentReset);
    connect(m_context->document(), &ProjectDocument::locationChanged, this, &MainWindow::updateTitle);
    connect(m_context->document(), &ProjectDocument::sequencesRemoved, this, &MainWindow::onSequencesRemoved);
    connect(m_context->modelStore(), &ModelStore::writeFailed, this, [this](const QString &problems) {
        ErrorReporter::report(this, tr("Models could not be written into the project's folder."), QString(), problems);
    });
    connect(m_context->document(), &ProjectDocument::editRefused, this, [this](const QString &edit, const QString &why) {
        statusBar()->showMessage(tr("%1 was not applied: it would leave the project unsaveable (%2).").arg(edit, why),
                                 15000);
    });
    connect(m_context->document(), &ProjectDocument::modelsChanged, this, [this] {
        m_models->setProject(m_context->document()->project());
        updateActiveModels();
    });
    connect(m_context->document(), &ProjectDocument::documentReset, this, &MainWindow::updateActiveModels);
    connect(m_context->document(), &ProjectDocument::sequenceChanged, this, [this](int row) {
        if (row == m_context->currentSequence() && m_context->media()) // "Landmarks: n of m frames"
            m_details->showSequence(m_context->document()->sequence(row), m_context->media()->mediaPath, *m_context->media());
    });
    connect(m_context->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(m_transport, &TransportBar::frameRequested, this, &MainWindow::setCurrentFrame);
    connect(m_context->playback(), &PlaybackController::frameReached, this, [this](int frame) {
        if (m_context->media() && m_context->playback()->mediaPath() == m_context->media()->mediaPath) // not the preview's new speech
            setCurrentFrame(frame);
    });
    connect(m_context->playback(), &PlaybackController::playingSilently, this, [this](const QString &why) {
        statusBar()->showMessage(tr("Playing without sound: %1.").arg(why), 10000);
    });
    connect(m_context->playback(), &PlaybackController::playingChanged, this, [this](bool playing) {
        m_actions->playPause->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });

    m_frameView->setPlaceholderText(tr("No project open"));
    m_preview->setPlaceholderText(tr("No project open"));
    updateTitle();
    restoreSettings();
    WheelGuard::install(this);
}

MainWindow::~MainWindow()
{
    // Workers must be gone before the views their results would reach.
    m_context->taskRunner()->cancelAll();
    m_context->taskRunner()->waitForAll();
    // QWidget's destructor deletes the undo stack after this one has run, and a dirty stack emits
    // cleanChanged while it dies — into updateTitle() of a MainWindow that is no longer one
    // (UBSan: downcast of a QWidget to MainWindow, in every GUI test that closes an edited window).
    disconnect(m_context->undoStack(), nullptr, this, nullptr);
}

void MainWindow::addGeneratedFaceMenu(QMenu *view)
{
    // How generated faces are drawn in the preview and in exported videos, and whether their lips
    // close on /p b m/ (StudioContext).
    QMenu *face = view->addMenu(tr("Generated &Face"));
    face->setObjectName(QStringLiteral("generatedFaceMenu"));
    QAction *skin = face->addAction(tr("&Synthesised Skin"));
    skin->setObjectName(QStringLiteral("synthesizeSkinAction"));
    skin->setToolTip(tr("Paste the AAM's synthesis of the lower face, skin included; otherwise the recording's own "
                        "lower face is moved to the generated shape and only the inside of the mouth is synthesised"));
    QAction *whole = face->addAction(tr("&Whole Face (Eyes Included)"));
    whole->setObjectName(QStringLiteral("wholeFaceAction"));
    whole->setToolTip(tr("Synthesise the whole modelled face; otherwise the recording's own eyes and upper face are "
                         "kept"));
    QAction *detail = face->addAction(tr("&Detail from Training Images"));
    detail->setObjectName(QStringLiteral("faceDetailAction"));
    detail->setToolTip(tr("Add the teeth, lip highlights and skin detail of the AAM's nearest training images to the "
                          "model's smooth texture"));
    QAction *colour = face->addAction(tr("&Match the Frame's Lighting"));
    colour->setObjectName(QStringLiteral("matchColourAction"));
    const CompositeOptions &current = m_context->compositeOptions();
    for (auto [action, on] : {std::pair{skin, current.synthesizeSkin}, std::pair{whole, current.region == FaceRegion::Full},
                              std::pair{detail, current.detail}, std::pair{colour, current.matchColour}}) {
        action->setCheckable(true);
        action->setChecked(on);
        connect(action, &QAction::toggled, this, [this, skin, whole, detail, colour] {
            CompositeOptions options;
            options.synthesizeSkin = skin->isChecked();
            options.region = whole->isChecked() ? FaceRegion::Full : FaceRegion::Lower;
            options.detail = detail->isChecked();
            options.matchColour = colour->isChecked();
            m_context->setCompositeOptions(options);
        });
    }
    face->addSeparator();
    QAction *closure = face->addAction(tr("&Close the Lips on /p b m/"));
    closure->setObjectName(QStringLiteral("lipClosureAction"));
    closure->setToolTip(tr("Close the generated lips on the bilabials /p b m/, as speakers do; off: the model's "
                           "trajectory as generated"));
    closure->setCheckable(true);
    closure->setChecked(m_context->closesLips());
    connect(closure, &QAction::toggled, m_context, &StudioContext::setClosesLips);
}

WaveformView *MainWindow::waveformView() const
{
    return m_timeline->waveform();
}

void MainWindow::createDocks()
{
    auto makeDock = [this](const QString &title, const QString &name, QWidget *content, Qt::DockWidgetArea area) {
        auto *dock = new QDockWidget(title, this);
        dock->setObjectName(name);
        dock->setWidget(content);
        // Movable between the window's edges and closable, but never floating: a drag meant to
        // resize near a dock's title must not tear it off the window.
        dock->setFeatures(QDockWidget::DockWidgetClosable | QDockWidget::DockWidgetMovable);
        addDockWidget(area, dock);
        m_defaultDockAreas.emplace_back(dock, area);
        return dock;
    };

    m_sequenceModel = new SequenceListModel(m_context->document(), this);
    m_sequenceView = new QTableView(this);
    m_sequenceView->setObjectName(QStringLiteral("sequenceView"));
    m_sequenceView->setModel(m_sequenceModel);
    m_sequenceView->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_sequenceView->setSelectionMode(QAbstractItemView::SingleSelection);
    m_sequenceView->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
    m_sequenceView->verticalHeader()->hide();
    m_sequenceView->verticalHeader()->setDefaultSectionSize(m_sequenceView->fontMetrics().height() + 8);
    m_sequenceView->horizontalHeader()->setStretchLastSection(true);
    m_sequenceView->setAlternatingRowColors(true);
    m_sequenceView->setWordWrap(false);
    connect(m_sequenceView->selectionModel(), &QItemSelectionModel::selectionChanged, this,
            &MainWindow::onSelectionChanged);
    m_details = new SequenceDetailsView(this);
    auto *sequencePanel = new QSplitter(Qt::Vertical, this);
    sequencePanel->addWidget(m_sequenceView);
    sequencePanel->addWidget(m_details);
    sequencePanel->setStretchFactor(0, 1);
    sequencePanel->setChildrenCollapsible(false);
    makeDock(tr("Sequences"), QStringLiteral("sequencesDock"), sequencePanel, Qt::LeftDockWidgetArea);

    m_timeline = new TimelinePanel(this);
    m_timeline->attach(m_context);
    QDockWidget *timeline = makeDock(tr("Timeline"), QStringLiteral("timelineDock"), m_timeline,
                                     Qt::BottomDockWidgetArea);

    m_chart = new LineChartView(this);
    m_chart->setObjectName(QStringLiteral("chartView"));
    // The Plots dock: the audio energy, plus the dynamics plots the Models panel adds as tabs.
    auto *plotTabs = new QTabWidget(this);
    plotTabs->setObjectName(QStringLiteral("plotTabs"));
    plotTabs->setDocumentMode(true);
    plotTabs->addTab(m_chart, tr("Audio"));
    QDockWidget *plots = makeDock(tr("Plots"), QStringLiteral("plotsDock"), plotTabs, Qt::RightDockWidgetArea);

    m_models = new ModelsPanel(this);
    m_models->attach(m_context, plotTabs);
    QDockWidget *models = makeDock(tr("Models"), QStringLiteral("modelsDock"), m_models, Qt::RightDockWidgetArea);
    splitDockWidget(plots, models, Qt::Vertical);
    applyDefaultDockSizes();

    // The spectrogram needs a taller timeline: ask for it (the view's least height insists).
    connect(m_timeline->spectrogramAction(), &QAction::toggled, this, [this, timeline](bool on) {
        if (on && timeline->height() < kSpectrogramTimelineHeight)
            resizeDocks({timeline}, {kSpectrogramTimelineHeight}, Qt::Vertical);
    });
}

void MainWindow::updateActiveModels()
{
    // The AAM and the dynamic models the project uses now (the latest reference of each kind,
    // Project::model), always in view: undo and redo of Build AAM and Train change them.
    const Project &project = m_context->document()->project();
    QStringList dynamic;
    for (const QString &kind : ModelKinds::ids())
        if (project.model(kind.toStdString()))
            dynamic << ModelKinds::name(kind);
    const ModelReference *aam = project.aam();
    const QString text = tr("AAM: %1 · Models: %2")
                             .arg(aam ? QString::fromStdString(aam->name) : tr("none"),
                                  dynamic.isEmpty() ? tr("none trained") : dynamic.join(QStringLiteral(", ")));
    m_activeModels->setText(m_context->document()->isOpen() ? text : QString());
    m_activeModels->setToolTip(tr("The appearance model and the dynamic models the project uses now"));
}

void MainWindow::applyDefaultDockSizes()
{
    auto dock = [this](const char *name) { return findChild<QDockWidget *>(QLatin1String(name)); };
    resizeDocks({dock("sequencesDock"), dock("plotsDock")}, {385, 310}, Qt::Horizontal);
    resizeDocks({dock("timelineDock")},
                {m_timeline->spectrogramAction()->isChecked() ? kSpectrogramTimelineHeight : 230}, Qt::Vertical);
    // The plots first (a trajectory needs height to be read), the models panel at up to its full
    // height or a third of the window's (its list scrolls above its buttons otherwise).
    resizeDocks({dock("plotsDock"), dock("modelsDock")},
                {360, std::min(m_models->sizeHint().height() + 24, std::max(240, height() / 3))}, Qt::Vertical);
}

void MainWindow::resetLayout()
{
    for (const auto &[dock, area] : m_defaultDockAreas) {
        dock->setFloating(false);
        addDockWidget(area, dock);
        dock->show();
    }
    splitDockWidget(findChild<QDockWidget *>(QStringLiteral("plotsDock")),
                    findChild<QDockWidget *>(QStringLiteral("modelsDock")), Qt::Vertical);
    applyDefaultDockSizes();
}

void MainWindow::createMenus()
{
    const StudioActions &a = *m_actions;
    m_files = nullptr;
    QMenu *file = menuBar()->addMenu(tr("&File"));
    file->addAction(a.newProject);
    file->addAction(a.open);
    QMenu *recent = file->addMenu(tr("Open &Recent"));
    file->addAction(a.openDemo);
    file->addSeparator();
    file->addAction(a.save);
    file->addAction(a.saveAs);
    file->addSeparator();
    m_importer = new LongRecordingImporter(m_context, [this] { return m_files->save(); }, this);
    file->addAction(m_importer->action());
    connect(m_importer, &LongRecordingImporter::imported, this, [this](int first) { selectSequence(first); });
    m_export = new ExportMenu(m_context, file, this);
    file->addSeparator();
    file->addAction(a.quit);
    m_files = new ProjectFiles(m_context->document(), this, recent, m_context->taskRunner());
    m_files->autosave()->watch(m_context->taskRunner());

    QMenu *edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(a.undo);
    edit->addAction(a.redo);
    // The current sequence's transcript: also on the sequence list, where it is shown and edited.
    m_proposer = new TranscriptProposer(m_context, this);
    edit->addSeparator();
    for (QAction *act : {m_proposer->proposeAction(), m_proposer->acceptAction()}) {
        edit->addAction(act);
        m_sequenceView->addAction(act);
    }
    m_sequenceView->setContextMenuPolicy(Qt::ActionsContextMenu);

    QMenu *view = menuBar()->addMenu(tr("&View"));
    for (QAction *act : {a.previousFrame, a.nextFrame, a.firstFrame, a.lastFrame})
        view->addAction(act);
    view->addSeparator();
    view->addAction(a.playPause);
    view->addSeparator();
    view->addAction(a.previousSequence);
    view->addAction(a.nextSequence);
    view->addAction(a.fitFrame);
    view->addAction(m_timeline->spectrogramAction());
    view->addSeparator();
    QAction *live = view->addAction(tr("&Live: Speak and Watch the Face"));
    live->setObjectName(QStringLiteral("showLiveAction"));
    live->setToolTip(tr("Speak into the microphone and watch the face move"));
    connect(live, &QAction::triggered, this, [this] { m_tabs->setCurrentWidget(m_live); });
    view->addSeparator();
    addGeneratedFaceMenu(view);
    QMenu *panels = view->addMenu(tr("&Panels"));
    for (QDockWidget *dock : findChildren<QDockWidget *>())
        panels->addAction(dock->toggleViewAction());
    panels->addSeparator();
    panels->addAction(tr("&Reset Layout"), this, &MainWindow::resetLayout);

    menuBar()->addMenu((new StudyController(m_context, [this] { return m_files->save(); }, this))->menu());

    QMenu *help = menuBar()->addMenu(tr("&Help"));
    QAction *guide = help->addAction(tr("&User Guide"), this, [this] { (new UserGuide(this))->show(); });
    guide->setObjectName(QStringLiteral("userGuideAction"));
    guide->setShortcut(QKeySequence::HelpContents);
    QAction *keys = help->addAction(tr("&Keyboard Shortcuts"), this, [this] {
        auto *dialog = new ShortcutsDialog(this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        dialog->show();
    });
    keys->setObjectName(QStringLiteral("shortcutsAction"));
    help->addSeparator();
    help->addAction(a.about);

    QToolBar *bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->setMovable(false);
    for (QAction *act : {a.open, a.save, a.undo, a.redo})
        bar->addAction(act);
    // Undo and redo name their step ("Undo Train DPDS"): icons here, the name in the tooltip and
    // the Edit menu, rather than a label elided as it changes.
    for (QAction *act : {a.undo, a.redo})
        if (auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(act)))
            button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    bar->addSeparator();
    bar->addAction(a.previousSequence);
    bar->addAction(a.nextSequence);

    connect(a.open, &QAction::triggered, m_files, &ProjectFiles::openWithDialog);
    connect(a.newProject, &QAction::triggered, m_files, &ProjectFiles::newProjectWithDialog);
    connect(a.openDemo, &QAction::triggered, this, [this] {
        if (m_files->maybeSave())
            m_files->openDemo();
    });
    connect(a.save, &QAction::triggered, m_files, &ProjectFiles::save);
    connect(a.saveAs, &QAction::triggered, m_files, &ProjectFiles::saveAs);
    connect(a.quit, &QAction::triggered, this, &QWidget::close);
    connect(a.previousFrame, &QAction::triggered, this, [this] { setCurrentFrame(m_context->currentFrame() - 1); });
    connect(a.nextFrame, &QAction::triggered, this, [this] { setCurrentFrame(m_context->currentFrame() + 1); });
    connect(a.firstFrame, &QAction::triggered, this, [this] { setCurrentFrame(0); });
    connect(a.lastFrame, &QAction::triggered, this, [this] {
        if (m_context->media())
            setCurrentFrame(m_context->media()->frameCount() - 1);
    });
    connect(a.playPause, &QAction::triggered, this, &MainWindow::togglePlayback);
    connect(a.previousSequence, &QAction::triggered, this, [this] {
        selectSequence(std::max(0, (m_pendingRow >= 0 ? m_pendingRow : m_context->currentSequence()) - 1));
    });
    connect(a.nextSequence, &QAction::triggered, this, [this] {
        selectSequence(std::min(m_context->document()->sequenceCount() - 1, (m_pendingRow >= 0 ? m_pendingRow : m_context->currentSequence()) + 1));
    });
    connect(a.fitFrame, &QAction::triggered, m_frameView, &FrameView::fitToView);
    connect(a.about, &QAction::triggered, this, &MainWindow::showAbout);
}

void MainWindow::clearSequence()
{
    if (m_loadTask)
        m_loadTask->cancel();
    m_context->playback()->pause();
    m_context->clearCurrentSequence();
    m_pendingRow = -1;
    m_frameView->setImage({});
    m_frameView->setPlaceholderText(tr("Select a sequence"));
    m_preview->setFrame({}, {});
    waveformView()->clear();
    waveformView()->setDuration(0);
    m_chart->clearSeries();
    m_details->clear();
    m_transport->setClock({});
}

void MainWindow::onDocumentReset()
{
    // A new document: drop the old one's media and any load still running for it.
    clearSequence();
    m_models->setProject(m_context->document()->project());
    m_sequenceView->resizeColumnsToContents();
    m_sequenceView->horizontalHeader()->setStretchLastSection(true);
    if (m_context->document()->sequenceCount() > 0)
        selectSequence(0);
}

void MainWindow::onSequencesRemoved(int first)
{
    // The rows before `first` stay where they were. When the sequence shown (or loading) was
    // among the removed ones, the panels let it go (sequenceLoaded without media: none shown)
    // and the last remaining sequence takes its place.
    if (m_context->currentSequence() < first && m_pendingRow < first)
        return;
    clearSequence();
    m_context->announceSequenceLoaded();
    selectSequence(first - 1);
}

void MainWindow::selectSequence(int row)
{
    if (row < 0 || row >= m_context->document()->sequenceCount())
        return;
    const QModelIndex index = m_sequenceModel->index(row, 0);
    if (m_sequenceView->currentIndex().row() != row || !m_sequenceView->selectionModel()->isRowSelected(row))
        m_sequenceView->selectionModel()->setCurrentIndex(
            index, QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    else
        onSelectionChanged();
}

void MainWindow::onSelectionChanged()
{
    const QModelIndexList rows = m_sequenceView->selectionModel()->selectedRows();
    if (rows.isEmpty())
        return;
    const int row = rows.first().row();
    if (row == m_pendingRow || (row == m_context->currentSequence() && m_pendingRow < 0))
        return;
    if (m_loadTask)
        m_loadTask->cancel(); // superseded: its result must not arrive after this one's
    m_context->playback()->pause();
    m_pendingRow = row;
    const Sequence &s = m_context->document()->sequence(row);
    SequenceSource source{QString::fromStdString(s.id), m_context->document()->mediaPath(row), s.frameRate};
    Task *task = SequenceLoader::start(*m_context->taskRunner(), source, [this, row](std::shared_ptr<const SequenceMedia> media) {
        applyMedia(row, std::move(media));
    });
    m_loadTask = task;
    connect(task, &Task::finished, this, [this, task, path = source.mediaPath] { onLoadFinished(task, path); });
    statusBar()->showMessage(tr("Loading %1…").arg(source.id), 3000);
}

void MainWindow::onLoadFinished(Task *task, const QString &mediaPath)
{
    if (task->state() == Task::State::Finished)
        return; // applyMedia ran
    if (task->state() == Task::State::Failed)
        ErrorReporter::report(this, tr("The media of this sequence could not be read."), mediaPath, task->errorMessage());
    if (task != m_loadTask)
        return; // superseded by a newer load
    // Canceled or failed: the views keep the sequence they showed; so does the list.
    m_pendingRow = -1;
    if (m_context->currentSequence() >= 0) {
        const QSignalBlocker block(m_sequenceView->selectionModel());
        m_sequenceView->selectionModel()->setCurrentIndex(m_sequenceModel->index(m_context->currentSequence(), 0),
                                                          QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
        m_sequenceView->viewport()->update();
    } else {
        m_sequenceView->selectionModel()->clearSelection();
    }
    emit sequenceLoadEnded(false);
}

void MainWindow::applyMedia(int row, std::shared_ptr<const SequenceMedia> media)
{
    if (row >= m_context->document()->sequenceCount())
        return;
    const Sequence &s = m_context->document()->sequence(row);
    m_pendingRow = -1;
    m_context->setCurrentSequence(row, std::move(media));
    const std::shared_ptr<const SequenceMedia> shown = m_context->media();
    const int frames = shown->frameCount();
    m_transport->setClock(shown->clock);
    m_context->playback()->setSequence(shown->mediaPath, shown->clock);

    showChart(); // the timeline shows the media on sequenceLoaded
    m_frameView->setPlaceholderText(shown->audioOnly ? tr("Sound only: no video to show")
                                    : frames > 0      ? QString()
                                                      : tr("The video has no frames"));
    m_details->showSequence(s, shown->mediaPath, *shown);
    setCurrentFrame(0);
    updateTitle();
    statusBar()->showMessage(tr("%1: %n frames at %2 fps", "", frames)
                                 .arg(shown->sequenceId, QLocale().toString(shown->frameRate, 'f', 2)),
                             5000);
    m_context->announceSequenceLoaded();
    emit sequenceLoadEnded(true);
}

void MainWindow::showChart()
{
    const std::shared_ptr<const SequenceMedia> shown = m_context->media();
    m_chart->clearSeries();
    m_chart->setTitle(tr("Audio energy of %1").arg(shown->sequenceId));
    m_chart->setAxisTitles(tr("time (s)"), tr("RMS per video frame"));
    if (shown->frameRms.isEmpty())
        return;
    QVector<double> t(shown->frameRms.size());
    for (int i = 0; i < t.size(); ++i)
        t[i] = shown->clock.centre(i);
    m_chart->addSeries(tr("RMS"), t, shown->frameRms, QColor(0x1e, 0x88, 0xe5));
}

void MainWindow::setCurrentFrame(int frame)
{
    m_context->setCurrentFrame(frame); // showFrame first, then the panels
}

void MainWindow::showFrame(int frame)
{
    const std::shared_ptr<const SequenceMedia> shown = m_context->media();
    if (!shown || frame < 0 || frame >= shown->frameCount())
        return;
    const QImage &image = shown->frames[frame];
    m_frameView->setImage(image);
    const Sequence &s = m_context->document()->sequence(m_context->currentSequence());
    const auto it = s.landmarks.find(frame);
    m_frameView->setLandmarks(it != s.landmarks.end() ? std::optional<LandmarkSet>(it->second) : std::nullopt);
    m_preview->setFrame(image, tr("%1 — frame %2 of %3").arg(shown->sequenceId).arg(frame + 1).arg(shown->frameCount()));
    m_transport->setFrame(frame);
    waveformView()->setCursorTime(shown->clock.centre(frame));
    m_chart->setCursor(shown->clock.centre(frame));
}

void MainWindow::togglePlayback()
{
    m_context->togglePlayback();
}

void MainWindow::updateTitle()
{
    QString title = tr("LipSync Studio");
    if (m_context->document()->isOpen()) {
        QString name = QString::fromStdString(m_context->document()->project().name);
        if (name.isEmpty())
            name = QFileInfo(m_context->document()->folder()).fileName();
        title = name + QStringLiteral("[*]");
        if (m_context->document()->isReadOnly())
            title += tr(" (bundled demo, read-only)");
        title += QStringLiteral(" — ") + tr("LipSync Studio");
    }
    setWindowTitle(title);
    setWindowModified(m_context->document()->isModified());
}

void MainWindow::showAbout()
{
    AboutBox::show(this);
}

void MainWindow::restoreSettings()
{
    QSettings settings;
    m_geometryRestored = restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    if (!m_geometryRestored)
        resize(1280, 800);
    m_layoutRestored = restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
}

void MainWindow::showEvent(QShowEvent *event)
{
    QMainWindow::showEvent(event);
    // The default layout for the size the window is first shown at (maximised, or --size), not
    // the size it was built at; a restored layout stays as the user left it.
    if (!std::exchange(m_shownOnce, true) && !m_layoutRestored)
        QTimer::singleShot(0, this, &MainWindow::applyDefaultDockSizes);
}

void MainWindow::showAsLastTime()
{
    // The last session's geometry if it still fits the screen's free area (title bar and frame
    // included); otherwise maximised, so that the status bar and its Cancel stay on screen.
    const QScreen *screen = this->screen();
    if (!screen || (m_geometryRestored && screen->availableGeometry().contains(frameGeometry()))) {
        show();
        return;
    }
    setGeometry(screen->availableGeometry()); // where no window manager maximises
    showMaximized();
}

void MainWindow::closeEvent(QCloseEvent *event)
{
    if (!m_files->maybeSave()) {
        event->ignore();
        return;
    }
    m_context->playback()->pause();
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    m_context->taskRunner()->cancelAll();
    event->accept();
}

} // namespace lipsync::studio
