#include "preview/PreviewPanel.h"

#include "aam/FaceDetector.h"
#include "annotate/FacesController.h"
#include "annotate/FrameView.h"
#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "context/StudioActions.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneLabels.h"
#include "io/Transcript.h"
#include "preview/GeneratedFaces.h"
#include "preview/SpeechDialog.h"
#include "project/Project.h"
#include "render/BilabialClosure.h"
#include "render/FaceRenderer.h"
#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "timeline/WaveformView.h"
#include "util/Error.h"

#include <QAction>
#include <QCheckBox>
#include <QFileInfo>
#include <QGridLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>
#include <optional>
#include <utility>

namespace lipsync::studio {

namespace {

// The frame a renderer without a recording draws into: the AAM's mean face on grey.
QImage neutralFrame(FaceRenderer &renderer)
{
    const cv::Mat bgr = renderer.background(0);
    return QImage(bgr.data, bgr.cols, bgr.rows, int(bgr.step), QImage::Format_BGR888).copy();
}

// The AAM the project refers to (its file), or "" if it has none.
std::string projectAamPath(const Project &project)
{
    const ModelReference *aam = project.aam();
    return aam ? project.resolve(aam->file) : std::string();
}

} // namespace

PreviewPanel::PreviewPanel(const StudioActions &actions, QWidget *parent)
    : QWidget(parent), m_caption(new QLabel(this)), m_play(new QToolButton(this)), m_stepBack(new QToolButton(this)),
      m_stepForward(new QToolButton(this)), m_scrub(new QSlider(Qt::Horizontal, this)),
      m_loop(new QCheckBox(tr("Loop selection"), this)), m_landmarks(new QCheckBox(tr("Landmarks"), this)),
      m_speechButton(new QPushButton(tr("Generate from Speech…"), this)),
      m_back(new QPushButton(tr("Back to Sequence"), this)), m_grid(new QWidget(this)),
      m_gridLayout(new QGridLayout(m_grid)), m_recorded(new QImage)
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);

    auto *header = new QHBoxLayout;
    header->setContentsMargins(8, 4, 8, 0);
    header->setSpacing(8);
    m_play->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    m_play->setToolTip(actions.playPause->toolTip());
    m_stepBack->setIcon(style()->standardIcon(QStyle::SP_MediaSeekBackward));
    m_stepBack->setToolTip(tr("Previous frame"));
    m_stepForward->setIcon(style()->standardIcon(QStyle::SP_MediaSeekForward));
    m_stepForward->setToolTip(tr("Next frame"));
    for (QToolButton *b : {m_stepBack, m_play, m_stepForward})
        b->setAutoRaise(true);
    m_scrub->setRange(0, 0);
    m_scrub->setToolTip(tr("Scrub through the frames"));
    m_loop->setToolTip(tr("Play the timeline's selection (or everything) over and over"));
    m_landmarks->setToolTip(tr("Show the tracked points on the recorded video and the generated points on the generated faces"));
    m_speechButton->setToolTip(tr("Generate faces for any recording with a transcript"));
    m_back->setToolTip(tr("Show the current sequence again"));
    m_back->hide();
    // Transport on the first row, what to show on the second.
    header->addWidget(m_stepBack);
    header->addWidget(m_play);
    header->addWidget(m_stepForward);
    header->addWidget(m_scrub, 1);
    header->addWidget(m_caption);
    layout->addLayout(header);
    auto *options = new QHBoxLayout;
    options->setContentsMargins(8, 0, 8, 0);
    options->setSpacing(12);
    options->addWidget(m_loop);
    options->addWidget(m_landmarks);
    options->addStretch(1);
    options->addWidget(m_back);
    options->addWidget(m_speechButton);
    layout->addLayout(options);
    m_gridLayout->setContentsMargins(4, 0, 4, 4);
    m_gridLayout->setSpacing(6);
    layout->addWidget(m_grid, 1);

    connect(m_play, &QToolButton::clicked, this, &PreviewPanel::togglePlay);
    connect(m_stepBack, &QToolButton::clicked, this, [this] { step(-1); });
    connect(m_stepForward, &QToolButton::clicked, this, [this] { step(1); });
    connect(m_scrub, &QSlider::valueChanged, this, [this](int frame) {
        if (m_context && m_context->playback()->isPlaying() && m_scrub->isSliderDown())
            m_context->playback()->pause();
        setCurrent(frame);
    });
    connect(m_loop, &QCheckBox::toggled, this, &PreviewPanel::onLoopToggled);
    connect(m_landmarks, &QCheckBox::toggled, this, &PreviewPanel::showCurrent);
    connect(m_speechButton, &QPushButton::clicked, this, &PreviewPanel::openSpeechDialog);
    connect(m_back, &QPushButton::clicked, this, &PreviewPanel::showSequence);
    layoutPanels();
}

PreviewPanel::~PreviewPanel()
{
    delete m_recorded;
}

void PreviewPanel::attach(StudioContext *context)
{
    m_context = context;
    connect(context, &StudioContext::speechSeekRequested, this, &PreviewPanel::seekSpeech);
    PlaybackController *player = context->playback();
    connect(player, &PlaybackController::playingChanged, this, [this](bool playing) {
        m_play->setIcon(style()->standardIcon(playing ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    connect(player, &PlaybackController::frameReached, this, [this](int frame) {
        if (m_showingSpeech && m_context->playback()->mediaPath() == speechPath())
            setCurrent(frame);
    });
    connect(context, &StudioContext::currentFrameChanged, this, [this] {
        if (!m_showingSpeech)
            updateControls();
    });
    connect(context, &StudioContext::compositeOptionsChanged, this, &PreviewPanel::showCurrent);
    connect(context, &StudioContext::lipClosureChanged, this, &PreviewPanel::rebuild);
    connect(context, &StudioContext::sequenceLoaded, this, [this] {
        const bool wasSpeech = std::exchange(m_showingSpeech, false);
        m_faces.reset();
        m_facesSequence.clear();
        m_prepareFailed.clear();
        prepare();
        layoutPanels();
        updateControls();
        showCurrent();
        if (wasSpeech)
            m_context->setShownSpeech(nullptr, {});
    });
    // New or changed models, edited phones: generate again (the poses stay).
    auto invalidate = [this] {
        m_facesSequence.clear();
        prepare();
    };
    connect(context->document(), &ProjectDocument::modelsChanged, this, [this, invalidate] {
        if (projectAamPath(m_context->document()->project()) != m_aamPath) {
            // Another AAM (built anew): the poses were tracked with the old one.
            ++m_epoch;
            m_aam.reset();
            m_renderers.clear();
            m_prepareFailed.clear();
        }
        invalidate();
    });
    connect(context->document(), &ProjectDocument::documentReset, this, [this] {
        ++m_epoch;
        m_aam.reset();
        m_aamPath.clear();
        m_renderers.clear();
        m_faces.reset();
        m_facesSequence.clear();
        m_prepareFailed.clear();
        const bool wasSpeech = std::exchange(m_showingSpeech, false);
        layoutPanels();
        if (wasSpeech)
            m_context->setShownSpeech(nullptr, {});
    });
    connect(context->document(), &ProjectDocument::sequenceChanged, this, [this, invalidate](int row) {
        if (row == m_context->currentSequence())
            invalidate();
    });
}

FrameView *PreviewPanel::panel(int index) const
{
    return index >= 0 && index < int(m_panels.size()) ? m_panels[std::size_t(index)].view : nullptr;
}

QString PreviewPanel::panelTitle(int index) const
{
    return index >= 0 && index < int(m_panels.size()) ? m_panels[std::size_t(index)].title->text() : QString();
}

QString PreviewPanel::caption() const
{
    return m_caption->text();
}

void PreviewPanel::setFrame(const QImage &image, const QString &caption)
{
    *m_recorded = image;
    m_sequenceCaption = caption; // shown again by Back to Sequence
    if (m_showingSpeech)
        return;
    m_caption->setText(caption);
    showCurrent();
}

void PreviewPanel::setPlaceholderText(const QString &text)
{
    m_placeholder = text;
    if (!m_panels.empty())
        m_panels.front().view->setPlaceholderText(text);
}

void PreviewPanel::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    prepare();
}

// --- the recorded sequence's faces ---

void PreviewPanel::prepare()
{
    if (!m_context || !isVisible() || m_showingSpeech)
        return;
    const int row = m_context->currentSequence();
    const auto media = m_context->media();
    if (row < 0 || !media)
        return;
    const ProjectDocument *doc = m_context->document();
    const Sequence &s = doc->sequence(row);
    const QString id = QString::fromStdString(s.id);
    if (m_aam && m_renderers.contains(id)) {
        if (m_facesSequence != id)
            rebuild();
        return;
    }
    if (m_prepareTask || m_prepareFailed == id)
        return;
    const std::string aamPath = projectAamPath(doc->project());
    if (aamPath.empty()) {
        rebuild(); // says why there is nothing to show
        return;
    }
    // The Faces workflow may have the AAM loaded already.
    std::shared_ptr<const AamModel> aam = m_aam ? m_aam : m_context->modelStore()->aam();
    const std::string mediaPath = media->mediaPath.toStdString();
    const bool audioOnly = media->audioOnly;
    m_prepareTask = m_context->taskRunner()->start(
        tr("Prepare the preview of %1").arg(id),
        [this, aam, aamPath, mediaPath, audioOnly, id, epoch = m_epoch](Feedback &feedback) -> TaskRunner::Commit {
            feedback.setStatus("loading the appearance model");
            auto model = aam ? aam : std::make_shared<const AamModel>(AamModel::load(aamPath));
            std::shared_ptr<FaceRenderer> renderer;
            QImage fixedFrame;
            if (audioOnly) {
                // No head to track: the mean face on grey.
                renderer = std::make_shared<FaceRenderer>(*model);
                fixedFrame = neutralFrame(*renderer);
            } else {
                FaceDetector detector(FaceDetectorPaths::boxesOnly());
                feedback.setStatus("tracking the head pose");
                renderer = std::make_shared<FaceRenderer>(*model, mediaPath, feedback, &detector);
            }
            return [this, model, renderer, fixedFrame, id, epoch, aamPath] {
                if (epoch != m_epoch)
                    return; // another document or AAM since
                m_aam = model;
                m_aamPath = aamPath;
                m_renderers.insert(id, {model, renderer, fixedFrame});
                m_facesSequence.clear();
                prepare();
            };
        });
    connect(m_prepareTask, &Task::finished, this, [this, task = m_prepareTask.data(), id](Task::State state) {
        if (m_prepareTask == task)
            m_prepareTask = nullptr;
        if (state != Task::State::Finished)
            m_prepareFailed = id; // not again until the sequence is loaded again
        prepare(); // the sequence shown now may have changed meanwhile
        // The commit rebuilt the panels while this task still counted as running: say what is
        // missing now ("train a model"), not "tracking the head pose".
        layoutPanels();
        if (state == Task::State::Failed && id == m_prepareFailed && m_panels.size() > 1)
            m_panels.back().view->setPlaceholderText(tr("The head could not be tracked: %1").arg(task->errorMessage()));
    });
    layoutPanels();
}

void PreviewPanel::rebuild()
{
    m_faces.reset();
    m_facesSequence.clear();
    const int row = m_context ? m_context->currentSequence() : -1;
    if (row >= 0 && m_aam) {
        const Sequence &s = m_context->document()->sequence(row);
        const QString id = QString::fromStdString(s.id);
        if (const Renderer r = m_renderers.value(id); r.renderer) {
            auto faces = std::make_shared<GeneratedFaces>(r.aam, r.renderer, s.clock());
            if (!r.fixedFrame.isNull())
                faces->setFixedFrame(r.fixedFrame, 0);
            // Lips closed on /p b m/ as exported videos close them (StudioContext).
            for (StudioContext::GeneratedTrajectory &g : m_context->generatedTrajectories(row, m_aam.get()))
                faces->addTrack({g.kind, ModelKinds::name(g.kind), ModelKinds::colour(g.kind), std::move(g.features),
                                 std::move(g.posture)});
            m_faces = std::move(faces);
            m_facesSequence = id;
        }
    }
    layoutPanels();
    showCurrent();
    if (m_faces && !m_faces->tracks().empty())
        emit facesReady();
}

// --- panels ---

void PreviewPanel::layoutPanels()
{
    QStringList titles;
    QList<QColor> colours;
    const GeneratedFaces *shown = faces();
    if (!m_showingSpeech) {
        titles << tr("Recorded video (landmarks: tracked)");
        colours << palette().color(QPalette::WindowText);
    }
    if (shown && !shown->tracks().empty()) {
        for (const GeneratedFaces::Track &t : shown->tracks()) {
            titles << tr("Generated: %1").arg(t.name);
            colours << t.color;
        }
    } else {
        titles << tr("Generated");
        colours << palette().color(QPalette::WindowText);
    }
    if (int(m_panels.size()) != titles.size()) {
        for (Panel &p : m_panels)
            delete p.box;
        m_panels.clear();
        for (int i = 0; i < titles.size(); ++i) {
            auto *box = new QWidget(m_grid);
            auto *v = new QVBoxLayout(box);
            v->setContentsMargins(0, 0, 0, 0);
            v->setSpacing(2);
            auto *title = new QLabel(box);
            title->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred); // columns stay equal
            QFont bold = title->font();
            bold.setBold(true);
            title->setFont(bold);
            auto *view = new FrameView(box);
            view->setObjectName(QStringLiteral("previewPanel%1").arg(i));
            view->setEditable(false);
            view->setMinimumSize(160, 120);
            v->addWidget(title);
            v->addWidget(view, 1);
            m_panels.push_back({box, title, view});
        }
        // Side by side up to three, then a grid.
        const int n = int(m_panels.size());
        const int columns = n <= 3 ? n : int(std::ceil(std::sqrt(double(n))));
        for (int i = 0; i < n; ++i)
            m_gridLayout->addWidget(m_panels[std::size_t(i)].box, i / columns, i % columns);
        for (int c = 0; c < 4; ++c)
            m_gridLayout->setColumnStretch(c, c < columns ? 1 : 0);
    }
    for (int i = 0; i < titles.size(); ++i) {
        QLabel *title = m_panels[std::size_t(i)].title;
        title->setText(titles[i]);
        title->setToolTip(titles[i]); // the whole name when the column is narrow
        QPalette pal = title->palette();
        pal.setColor(QPalette::WindowText, colours[i]);
        title->setPalette(pal);
        // Each pane's landmarks in its title's colour: tracked and each model's generated points
        // are told apart by colour, and the pane titles are their legend.
        m_panels[std::size_t(i)].view->setPointColour(colours[i]);
    }
    // What the generated panel says while there is nothing to draw.
    if (!shown || shown->tracks().empty()) {
        QString why;
        const int row = m_context ? m_context->currentSequence() : -1;
        if (!m_context || row < 0)
            why = m_placeholder;
        else if (projectAamPath(m_context->document()->project()).empty())
            why = tr("The project has no appearance model (Faces ▸ Build AAM).");
        else if (m_prepareTask)
            why = tr("Tracking the head pose…");
        else if (m_context->document()->sequence(row).phones.isEmpty())
            why = tr("This sequence has no phones (align it in the Timeline).");
        else
            why = tr("Train a dynamic model in the Models panel to see the faces it generates.");
        m_panels.back().view->setImage({});
        m_panels.back().view->setPlaceholderText(why);
    }
    if (!m_showingSpeech) {
        const auto media = m_context ? m_context->media() : nullptr;
        m_panels.front().view->setPlaceholderText(media && media->audioOnly ? tr("Sound only: no video to show")
                                                                            : m_placeholder);
    }
    m_back->setVisible(m_showingSpeech);
}

void PreviewPanel::showCurrent()
{
    const GeneratedFaces *shown = faces();
    const bool overlay = m_landmarks->isChecked();
    const CompositeOptions composite = m_context ? m_context->compositeOptions() : CompositeOptions();
    if (m_showingSpeech) {
        for (int i = 0; i < int(m_panels.size()) && shown && i < int(shown->tracks().size()); ++i) {
            FrameView *view = m_panels[std::size_t(i)].view;
            view->setImage(shown->render(i, m_speechFrame, composite));
            view->setLandmarks(overlay ? std::optional<LandmarkSet>(shown->landmarks(i, m_speechFrame, composite)) : std::nullopt);
        }
        return;
    }
    if (m_panels.empty())
        return;
    const int frame = m_context ? m_context->currentFrame() : 0;
    const auto media = m_context ? m_context->media() : nullptr;
    if (!media || media->sequenceId != m_facesSequence)
        shown = nullptr; // generated for the sequence shown before (a new one is loading)
    FrameView *recorded = m_panels.front().view;
    recorded->setImage(*m_recorded);
    std::optional<LandmarkSet> tracked;
    if (overlay && shown && !m_recorded->isNull())
        tracked = shown->trackedLandmarks(frame);
    recorded->setLandmarks(tracked);
    // A sequence of sound alone has no recorded frame; its faces have a frame of their own.
    if (!shown || (m_recorded->isNull() && !media->audioOnly))
        return;
    for (int k = 0; k < int(shown->tracks().size()) && k + 1 < int(m_panels.size()); ++k) {
        FrameView *view = m_panels[std::size_t(k + 1)].view;
        view->setImage(shown->render(k, frame, composite, *m_recorded));
        view->setLandmarks(overlay ? std::optional<LandmarkSet>(shown->landmarks(k, frame, composite)) : std::nullopt);
    }
}

void PreviewPanel::updateControls()
{
    const QSignalBlocker block(m_scrub);
    if (m_showingSpeech) {
        const int n = m_speech ? m_speech->frameCount() : 0;
        m_scrub->setRange(0, std::max(0, n - 1));
        m_scrub->setValue(m_speechFrame);
        m_caption->setText(tr("%1 — frame %2 of %3").arg(speechTitle()).arg(m_speechFrame + 1).arg(n));
        return;
    }
    const auto media = m_context ? m_context->media() : nullptr;
    m_scrub->setRange(0, media ? std::max(0, media->frameCount() - 1) : 0);
    m_scrub->setValue(m_context ? m_context->currentFrame() : 0);
}

// --- transport ---

void PreviewPanel::setCurrent(int frame)
{
    if (!m_context)
        return;
    if (m_showingSpeech) {
        const int n = m_speech ? m_speech->frameCount() : 0;
        m_speechFrame = std::clamp(frame, 0, std::max(0, n - 1));
        updateControls();
        showCurrent();
    } else {
        m_context->setCurrentFrame(frame);
    }
}

void PreviewPanel::step(int frames)
{
    if (!m_context)
        return;
    m_context->playback()->pause();
    setCurrent((m_showingSpeech ? m_speechFrame : m_context->currentFrame()) + frames);
}

void PreviewPanel::togglePlay()
{
    if (!m_context)
        return;
    PlaybackController *player = m_context->playback();
    if (!m_showingSpeech) {
        m_context->togglePlayback();
        return;
    }
    if (player->isPlaying()) {
        player->pause();
        return;
    }
    if (player->mediaPath() != speechPath())
        player->setSequence(speechPath(), m_speech->frames());
    player->setAudioEnabled(!ErrorReporter::isBatchMode());
    player->play(m_speechFrame);
}

void PreviewPanel::onLoopToggled(bool on)
{
    if (!m_context)
        return;
    PlaybackController *player = m_context->playback();
    player->setLooping(on);
    if (!on)
        return;
    player->setAudioEnabled(!ErrorReporter::isBatchMode());
    if (m_showingSpeech) {
        if (!m_speech)
            return;
        if (player->mediaPath() != speechPath())
            player->setSequence(speechPath(), m_speech->frames());
        player->playRange(0.0, player->duration());
        return;
    }
    const auto media = m_context->media();
    if (!media)
        return;
    if (player->mediaPath() != media->mediaPath)
        player->setSequence(media->mediaPath, media->clock);
    double a = 0, b = 0;
    if (!m_context->selection(&a, &b)) {
        a = 0.0;
        b = player->duration();
    }
    player->playRange(a, b);
}

// --- new speech ---

void PreviewPanel::openSpeechDialog()
{
    if (!m_context)
        return;
    QStringList kinds;
    for (const QString &kind : ModelKinds::ids())
        if (m_context->modelStore()->dynamicModel(kind))
            kinds << kind;
    const auto media = m_context->media();
    SpeechDialog dialog(kinds, media ? media->frameRate : 25.0, this);
    dialog.setObjectName(QStringLiteral("speechDialog"));
    if (media)
        dialog.setMediaPath(media->mediaPath);
    emit speechDialogOpened(&dialog);
    if (dialog.exec() != QDialog::Accepted)
        return;
    startSpeech(dialog.mediaPath(), dialog.transcript(), dialog.frameRate(), dialog.kind());
}

Task *PreviewPanel::startSpeech(const QString &mediaPath, const QString &transcript, double frameRate,
                                const QString &kind)
{
    if (!m_context)
        return nullptr;
    const std::string aamPath = projectAamPath(m_context->document()->project());
    if (!m_aam && aamPath.empty()) {
        ErrorReporter::report(this, tr("Faces for new speech need the project's appearance model."), QString(),
                              tr("Build one with Faces ▸ Build AAM."));
        return nullptr;
    }
    const auto model = m_context->modelStore()->dynamicModel(kind);
    if (!model) {
        ErrorReporter::report(this, tr("No faces could be generated for this speech."), mediaPath,
                              tr("Train a dynamic model in the Models panel first."));
        return nullptr;
    }
    SpeechToFaceRequest request;
    request.mediaPath = mediaPath.toStdString();
    request.aamPath = aamPath;
    request.aam = m_aam ? m_aam : m_context->modelStore()->aam();
    request.model = model;
    request.frameRate = frameRate;
    request.pronunciations = m_context->document()->project().pronunciations;
    request.closeBilabials = m_context->closesLips();
    // The background: the current sequence's video re-timed to the speech (its head motion and
    // blinks, cut where the pose allows; exports re-time it the same way), else the mean face
    // on grey.
    const auto media = m_context->media();
    QVector<QImage> background;
    Renderer sequence;
    if (media && !media->frames.isEmpty() && !media->audioOnly && m_context->currentSequence() >= 0) {
        sequence = m_renderers.value(QString::fromStdString(m_context->document()->sequence(m_context->currentSequence()).id));
        if (sequence.renderer) {
            background = media->frames;
            request.backgroundPath = media->mediaPath.toStdString();
        }
    }
    // The aligner the timeline aligns with (ModelStore), loaded once for both.
    request.aligner = m_context->modelStore()->alignerChoice();
    request.aligner.transcriptFit = true; // another voice than its speaker's is aligned again (alignAnyVoice)
    const std::shared_ptr<AlignerCache> aligners = m_context->modelStore()->aligners();
    const QString title = QFileInfo(mediaPath).fileName();
    const std::string words = transcript.toStdString();
    Task *task = m_context->taskRunner()->start(
        tr("Generate faces for %1").arg(title),
        [this, request, words, background, sequence, mediaPath, title, kind, aligners](Feedback &feedback) mutable
        -> TaskRunner::Commit {
            request.aligners = aligners;
            request.words = parsePlainTranscript(words).words; // the typed words, as typed
            Feedback sub(feedback, 0.0, 0.95);
            auto result = std::make_shared<const SpeechToFaceResult>(lipsync::generateFromSpeech(request, sub));
            std::shared_ptr<GeneratedFaces> faces;
            if (sequence.renderer) {
                faces = std::make_shared<GeneratedFaces>(sequence.aam, sequence.renderer, result->frames);
                faces->setRetimedBackground(sequence.renderer->retimingFor(result->frameCount()).frames, background);
            } else {
                auto neutral = std::make_shared<FaceRenderer>(*result->aam);
                faces = std::make_shared<GeneratedFaces>(result->aam, neutral, result->frames);
                faces->setFixedFrame(neutralFrame(*neutral), 0);
            }
            faces->addTrack({kind, ModelKinds::name(kind), ModelKinds::colour(kind), result->features, result->posture});
            feedback.setProgress(1.0);
            return [this, faces, result, title] { showSpeech(faces, result, title); };
        });
    connect(task, &Task::finished, this, [this, task, mediaPath](Task::State state) {
        if (state == Task::State::Failed)
            ErrorReporter::report(this, tr("No faces could be generated for this speech."), mediaPath,
                                  task->errorMessage());
    });
    return task;
}

void PreviewPanel::showSpeech(std::shared_ptr<GeneratedFaces> faces, std::shared_ptr<const SpeechToFaceResult> result,
                              const QString &title)
{
    if (m_context)
        m_context->playback()->pause();
    m_speech = std::move(faces);
    m_speechFrame = 0;
    m_showingSpeech = true;
    if (result->voiceRealigned)
        m_context->showStatus(tr("The words did not fit this voice with the timeline's aligner: aligned with CMU "
                                 "Sphinx's generic model adapted to the recording"),
                              15000);
    // The context holds the result (what exports and the timeline show); the panel its faces.
    m_context->setShownSpeech(std::move(result), title);
    layoutPanels();
    updateControls();
    showCurrent();
    emit facesReady();
}

std::shared_ptr<const SpeechToFaceResult> PreviewPanel::speechResult() const
{
    return m_showingSpeech && m_context ? m_context->shownSpeech() : nullptr;
}

QString PreviewPanel::speechTitle() const
{
    return m_showingSpeech && m_context ? m_context->shownSpeechTitle() : QString();
}

QString PreviewPanel::speechPath() const
{
    const auto result = speechResult();
    return result ? QString::fromStdString(result->mediaPath) : QString();
}

void PreviewPanel::seekSpeech(double seconds)
{
    if (m_showingSpeech && m_speech)
        setCurrent(std::max(0, m_speech->frames().frameAt(seconds)));
}

void PreviewPanel::showSequence()
{
    if (!m_showingSpeech)
        return;
    if (m_context)
        m_context->playback()->pause();
    m_showingSpeech = false;
    m_caption->setText(m_sequenceCaption);
    layoutPanels();
    updateControls();
    showCurrent();
    prepare();
    m_speech.reset();
    m_context->setShownSpeech(nullptr, {});
}

} // namespace lipsync::studio
