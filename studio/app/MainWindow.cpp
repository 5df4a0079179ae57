#include "app/MainWindow.h"

#include "annotate/FacesController.h"
#include "annotate/FrameView.h"
#include "app/AppCommands.h"
#include "app/Autosave.h"
#include "app/LongRecordingImporter.h"
#include "app/ProjectFiles.h"
#include "app/SequenceDetailsView.h"
#include "app/SequenceListModel.h"
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
      m_actions(std::make_unique<StudioActions>(this, m_context))
{
    // First, so the window's own views show a frame before the panels hear of it.
    connect(m_context, &StudioContext::currentFrameChanged, this, &MainWindow::showFrame);
    connect(m_context, &StudioContext::sequenceLoaded, this, &MainWindow::onSequenceLoaded);
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
    connect(m_context, &StudioContext::sequenceRequested, this, &MainWindow::showSequenceRow);
    connect(m_context, &StudioContext::sequenceLoadEnded, this, [this](bool loaded) {
        if (!loaded) // canceled or failed: the list shows the sequence the views still show
            showSequenceRow(m_context->currentSequence());
    });
    connect(m_context, &StudioContext::sequenceLoadFailed, this, [this](const QString &mediaPath, const QString &problem) {
        ErrorReporter::report(this, tr("The media of this sequence could not be read."), mediaPath, problem);
    });
    connect(m_context->modelStore(), &ModelStore::writeFailed, this, [this](const QString &problems) {
        ErrorReporter::report(this, tr("Models could not be written into the project's folder."), QString(), problems);
    });
    connect(m_context->document(), &ProjectDocument::editRefused, this, [this](const QString &edit, const QString &why) {
        statusBar()->showMessage(tr("%1 was not applied: it would leave the project unsaveable (%2).").arg(edit, why),
                                 15000);
    });
    connect(m_context->document(), &ProjectDocument::modelsChanged, this, &MainWindow::updateActiveModels);
    connect(m_context->document(), &ProjectDocument::documentReset, this, &MainWindow::updateActiveModels);
    connect(m_context->document(), &ProjectDocument::sequenceChanged, this, [this](int row) {
        if (row == m_context->currentSequence() && m_context->media()) // "Landmarks: n of m frames"
            m_details->showSequence(m_context->document()->sequence(row), m_context->media()->mediaPath, *m_context->media());
    });
    connect(m_context->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(m_transport, &TransportBar::frameRequested, m_context, &StudioContext::setCurrentFrame);
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
                        "lower face is moved to the generated lips' opening and width and only the inside of the mouth is "
                        "drawn"));
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
    QAction *closures = face->addAction(tr("Closed &Lips from the Footage"));
    closures->setObjectName(QStringLiteral("recordedClosuresAction"));
    closures->setToolTip(tr("Lips closed where the recording's are open are the person's own closed lips from another "
                            "moment of the video; otherwise the AAM draws them"));
    QAction *insides = face->addAction(tr("&Open Mouths from the Footage"));
    insides->setObjectName(QStringLiteral("recordedInsidesAction"));
    insides->setToolTip(tr("The inside of a mouth opened wider than recorded (teeth, tongue) is the person's own "
                           "open mouth from another moment of the video; otherwise the AAM draws it"));
    const CompositeOptions &current = m_context->compositeOptions();
    for (auto [action, on] : {std::pair{skin, current.synthesizeSkin}, std::pair{whole, current.region == FaceRegion::Full},
                              std::pair{detail, current.detail}, std::pair{colour, current.matchColour},
                              std::pair{closures, current.recordedClosures}, std::pair{insides, current.recordedInsides}}) {
        action->setCheckable(true);
        action->setChecked(on);
        connect(action, &QAction::toggled, this, [this, skin, whole, detail, colour, closures, insides] {
            CompositeOptions options;
            options.synthesizeSkin = skin->isChecked();
            options.region = whole->isChecked() ? FaceRegion::Full : FaceRegion::Lower;
            options.detail = detail->isChecked();
            options.matchColour = colour->isChecked();
            options.recordedClosures = closures->isChecked();
            options.recordedInsides = insides->isChecked();
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
    auto command = [this](const char *name) { return m_actions->registry->action(QLatin1String(name)); };
    QMenu *file = menuBar()->addMenu(tr("&File"));
    QMenu *recent = new QMenu(tr("Open &Recent"), this);
    m_files = new ProjectFiles(m_context->document(), this, recent, m_context->taskRunner());
    m_files->autosave()->watch(m_context->taskRunner());
    AppCommands::add(*m_actions->registry, m_files, m_frameView, this);
    file->addAction(command("file/new"));
    file->addAction(command("file/open"));
    file->addMenu(recent);
    file->addAction(command("file/open-demo"));
    file->addSeparator();
    file->addAction(command("file/save"));
    file->addAction(command("file/save-as"));
    file->addSeparator();
    m_importer = new LongRecordingImporter(m_context, [this] { return m_files->save(); }, this);
    file->addAction(m_importer->action());
    connect(m_importer, &LongRecordingImporter::imported, m_context, [this](int first) { m_context->selectSequence(first); });
    m_export = new ExportMenu(m_context, file, this);
    file->addSeparator();
    file->addAction(command("app/quit"));

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
    view->addAction(command("view/fit-frame"));
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
    help->addAction(command("help/about"));

    QToolBar *bar = addToolBar(tr("Main"));
    bar->setObjectName(QStringLiteral("mainToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    bar->setMovable(false);
    for (QAction *act : {command("file/open"), command("file/save"), a.undo, a.redo})
        bar->addAction(act);
    // Undo and redo name their step ("Undo Train DPDS"): icons here, the name in the tooltip and
    // the Edit menu, rather than a label elided as it changes.
    for (QAction *act : {a.undo, a.redo})
        if (auto *button = qobject_cast<QToolButton *>(bar->widgetForAction(act)))
            button->setToolButtonStyle(Qt::ToolButtonIconOnly);
    bar->addSeparator();
    bar->addAction(a.previousSequence);
    bar->addAction(a.nextSequence);

}

void MainWindow::clearViews()
{
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
    // The context dropped the old document's media and selects its first sequence.
    clearViews();
    m_sequenceView->resizeColumnsToContents();
    m_sequenceView->horizontalHeader()->setStretchLastSection(true);
    m_context->selectSequence(0);
}

void MainWindow::showSequenceRow(int row)
{
    const QSignalBlocker block(m_sequenceView->selectionModel());
    if (row < 0)
        m_sequenceView->selectionModel()->clearSelection();
    else
        m_sequenceView->selectionModel()->setCurrentIndex(m_sequenceModel->index(row, 0),
                                                          QItemSelectionModel::ClearAndSelect | QItemSelectionModel::Rows);
    m_sequenceView->viewport()->update();
}

void MainWindow::onSelectionChanged()
{
    const QModelIndexList rows = m_sequenceView->selectionModel()->selectedRows();
    if (!rows.isEmpty())
        m_context->selectSequence(rows.first().row());
}

void MainWindow::onSequenceLoaded()
{
    const std::shared_ptr<const SequenceMedia> shown = m_context->media();
    if (!shown) { // the sequence shown was removed
        clearViews();
        return;
    }
    const Sequence &s = m_context->document()->sequence(m_context->currentSequence());
    const int frames = shown->frameCount();
    m_transport->setClock(shown->clock);
    showChart(); // the timeline shows the media itself
    m_frameView->setPlaceholderText(shown->audioOnly ? tr("Sound only: no video to show")
                                    : frames > 0      ? QString()
                                                      : tr("The video has no frames"));
    m_details->showSequence(s, shown->mediaPath, *shown);
    // The frame is shown already (currentFrameChanged comes first); the transport's range and the
    // chart's series came after it.
    if (const int frame = m_context->currentFrame(); frame >= 0 && frame < frames) {
        m_transport->setFrame(frame);
        m_chart->setCursor(shown->clock.centre(frame));
    }
    updateTitle();
    statusBar()->showMessage(tr("%1: %n frames at %2 fps", "", frames)
                                 .arg(shown->sequenceId, QLocale().toString(shown->frameRate, 'f', 2)),
                             5000);
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
