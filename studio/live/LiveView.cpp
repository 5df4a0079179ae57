#include "live/LiveView.h"

#include "annotate/FrameView.h"
#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "context/WritableProject.h"
#include "document/ProjectDocument.h"
#include "live/CameraFeed.h"
#include "live/LiveController.h"
#include "live/PhoneStrip.h"
#include "tasks/Task.h"

#include <QAudioDevice>
#include <QCameraDevice>
#include <QComboBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHideEvent>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStyle>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <utility>

namespace lipsync::studio {

LiveView::LiveView(StudioContext *context, std::function<bool()> saveProject, QWidget *parent)
    : QWidget(parent), m_context(context), m_saveProject(std::move(saveProject)),
      m_controller(new LiveController(context, this)), m_devices(new QMediaDevices(this)),
      m_microphones(new QComboBox(this)), m_models(new QComboBox(this)), m_cameras(new QComboBox(this)),
      m_start(new QPushButton(tr("Start"), this)),
      m_stop(new QPushButton(tr("Stop"), this)), m_save(new QPushButton(tr("Save as Sequence"), this)),
      m_export(new QPushButton(tr("Export Video…"), this)), m_face(new FrameView(this)), m_strip(new PhoneStrip(this)),
      m_latency(new QLabel(this)), m_progress(new QLabel(this)), m_message(new QLabel(this))
{
    setObjectName(QStringLiteral("liveView"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(8, 4, 8, 6);
    layout->setSpacing(4);

    auto *header = new QHBoxLayout;
    header->setSpacing(8);
    auto *micLabel = new QLabel(tr("Microphone:"), this);
    micLabel->setBuddy(m_microphones);
    auto *modelLabel = new QLabel(tr("Model:"), this);
    modelLabel->setBuddy(m_models);
    m_microphones->setObjectName(QStringLiteral("liveMicrophone"));
    m_microphones->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_microphones->setMinimumContentsLength(8);
    m_microphones->setToolTip(tr("The microphone the face listens to"));
    m_cameras->setObjectName(QStringLiteral("liveCamera"));
    m_cameras->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    m_cameras->setMinimumContentsLength(8);
    m_cameras->setToolTip(tr("Draw the face over a camera's picture of you, wherever your face is in it, or into "
                             "the still of the person (No camera)"));
    m_models->setObjectName(QStringLiteral("liveModel"));
    m_models->setToolTip(tr("The trained dynamic model that moves the face"));
    m_start->setObjectName(QStringLiteral("liveStart"));
    m_start->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    m_start->setToolTip(tr("Listen to the microphone and move the face as you speak"));
    m_stop->setObjectName(QStringLiteral("liveStop"));
    m_stop->setIcon(style()->standardIcon(QStyle::SP_MediaStop));
    m_stop->setToolTip(tr("Stop listening; the session is kept for Save and Export"));
    m_save->setObjectName(QStringLiteral("liveSave"));
    m_save->setToolTip(tr("Add the last session to the project as a sequence: its sound, generated faces and "
                          "recognised phones"));
    m_export->setObjectName(QStringLiteral("liveExport"));
    m_export->setToolTip(tr("Write the last session's faces with its sound as an MP4 video"));
    // Two rows, what to listen to and what to draw, then the buttons: in one row they would
    // claim the width the window's side panels need at 1280x800.
    header->addWidget(micLabel);
    header->addWidget(m_microphones, 2);
    header->addWidget(modelLabel);
    header->addWidget(m_models, 1);
    layout->addLayout(header);
    auto *controls = new QHBoxLayout;
    controls->setSpacing(8);
    controls->addWidget(m_cameras, 1);
    controls->addWidget(m_start);
    controls->addWidget(m_stop);
    controls->addStretch(1);
    layout->addLayout(controls);

    m_face->setObjectName(QStringLiteral("liveFace"));
    m_face->setEditable(false);
    m_face->setMinimumSize(160, 96); // the timeline below keeps its height
    layout->addWidget(m_face, 1);
    // Which recogniser hears the phones, in the face's corner: the rows around it have no room at
    // the smallest window.
    m_recogniser = new QLabel(m_face);
    m_recogniser->setObjectName(QStringLiteral("liveRecogniser"));
    m_recogniser->setStyleSheet(QStringLiteral("background: rgba(0, 0, 0, 140); color: white; padding: 1px 5px;"));
    m_recogniser->move(6, 6);
    m_recogniser->setToolTip(tr("What recognises the phones: CMU Sphinx's US-English model when the timeline aligns "
                                "with CMU Sphinx (its Model menu), else the HMMs of the studio's aligner model, "
                                "trained on one speaker"));
    m_strip->setObjectName(QStringLiteral("livePhones"));
    m_strip->setToolTip(tr("The phones recognised in the last seconds, the newest on the right"));
    layout->addWidget(m_strip);

    auto *footer = new QHBoxLayout;
    footer->setSpacing(16);
    m_latency->setObjectName(QStringLiteral("liveLatency"));
    m_latency->setToolTip(tr("Time from the sound to the frame that shows it, over the last %1 seconds")
                              .arg(LiveController::kLatencyWindowSeconds));
    m_progress->setObjectName(QStringLiteral("liveProgress"));
    m_message->setObjectName(QStringLiteral("liveMessage"));
    m_message->setWordWrap(true);
    m_message->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_message->setTextInteractionFlags(Qt::TextSelectableByMouse);
    // The read-outs on a row of their own, above the buttons: side by side they would claim the
    // width the window's side panels need at 1280x800.
    footer->addWidget(m_latency);
    footer->addWidget(m_progress);
    footer->addStretch(1);
    layout->addLayout(footer);
    auto *keep = new QHBoxLayout;
    keep->addStretch(1);
    keep->addWidget(m_save);
    keep->addWidget(m_export);
    layout->addLayout(keep);
    layout->addWidget(m_message);

    connectControls();
    showFrames();
    updateControls();
}

LiveView::~LiveView() = default;

// The buttons and lists to the session, the devices coming and going, the controller's news and
// the project's models.
void LiveView::connectControls()
{
    connect(m_start, &QPushButton::clicked, this, &LiveView::start);
    connect(m_stop, &QPushButton::clicked, this, &LiveView::stop);
    connect(m_save, &QPushButton::clicked, this, &LiveView::saveAsSequence);
    connect(m_export, &QPushButton::clicked, this, &LiveView::exportVideo);
    connect(m_models, &QComboBox::currentIndexChanged, this, &LiveView::updateControls);
    connect(m_microphones, &QComboBox::currentIndexChanged, this, &LiveView::updateControls);
    // A narrow list shows the start of a long device name: the whole of it on hover.
    for (QComboBox *list : {m_microphones, m_models, m_cameras}) {
        const QString purpose = list->toolTip();
        connect(list, &QComboBox::currentTextChanged, list, [list, purpose](const QString &text) {
            list->setToolTip(text.isEmpty() ? purpose : QStringLiteral("%1\n%2").arg(text, purpose));
        });
    }
    connect(m_devices, &QMediaDevices::audioInputsChanged, this, [this] {
        fillMicrophones();
        updateControls();
    });
    connect(m_devices, &QMediaDevices::videoInputsChanged, this, &LiveView::fillCameras);
    connect(m_cameras, &QComboBox::activated, this, &LiveView::useChosenCamera);
    connect(m_controller->camera(), &CameraFeed::failed, this, [this](const QString &why) {
        m_lastProblem = why;
        m_cameras->setCurrentIndex(0);
        useChosenCamera();
    });
    connect(m_controller, &LiveController::stateChanged, this, &LiveView::updateControls);
    connect(m_controller, &LiveController::recordingChanged, this, &LiveView::updateControls);
    connect(m_controller, &LiveController::framesShownChanged, this, &LiveView::showFrames);
    connect(m_controller, &LiveController::failed, this, [this](const QString &why) {
        m_lastProblem = why;
        updateControls();
    });
    connect(m_controller, &LiveController::exportStarted, this, &LiveView::updateControls);
    connect(m_controller, &LiveController::exportEnded, this, &LiveView::updateControls);
    // The next session's recogniser, and whether it is installed.
    connect(m_context->modelStore(), &ModelStore::alignerChoiceChanged, this, &LiveView::updateControls);
    connect(m_models, &QComboBox::activated, this, [this] { m_modelChosen = true; });
    ProjectDocument *document = m_context->document();
    for (auto signal : {&ProjectDocument::documentReset, &ProjectDocument::modelsChanged})
        connect(document, signal, this, [this] {
            fillModels();
            updateControls();
        });
    connect(document, &ProjectDocument::documentReset, this, [this] {
        m_lastProblem.clear();
        m_face->setImage({});
        m_strip->clear();
    });
}

QString LiveView::chosenKind() const
{
    return m_models->currentData().toString();
}

void LiveView::fillMicrophones()
{
    const QByteArray current = m_microphones->currentData().toByteArray();
    const QSignalBlocker block(m_microphones);
    m_microphones->clear();
    const QList<QAudioDevice> inputs = QMediaDevices::audioInputs();
    const QByteArray preferred = current.isEmpty() ? QMediaDevices::defaultAudioInput().id() : current;
    for (const QAudioDevice &device : inputs) {
        m_microphones->addItem(device.description(), device.id());
        if (device.id() == preferred)
            m_microphones->setCurrentIndex(m_microphones->count() - 1);
    }
    if (inputs.isEmpty())
        m_microphones->addItem(tr("No microphone found"));
    // A recording instead of the voice: chosen when Start is pressed.
    m_microphones->insertSeparator(m_microphones->count());
    m_microphones->addItem(tr("A recording…"), QByteArray(kFileInput));
    m_microphones->setItemData(m_microphones->count() - 1,
                               tr("An audio or video file, played aloud, drives the face as if spoken now"),
                               Qt::ToolTipRole);
    if (current == kFileInput)
        m_microphones->setCurrentIndex(m_microphones->count() - 1);
}

void LiveView::fillCameras()
{
    const QByteArray current = m_cameras->currentData().toByteArray();
    const QSignalBlocker block(m_cameras);
    m_cameras->clear();
    m_cameras->addItem(tr("No camera"));
    m_cameras->setItemData(0, tr("The face is drawn into a still of the person"), Qt::ToolTipRole);
    for (const QCameraDevice &device : QMediaDevices::videoInputs()) {
        m_cameras->addItem(device.description(), device.id());
        if (device.id() == current)
            m_cameras->setCurrentIndex(m_cameras->count() - 1);
    }
    // The camera in use went away.
    if (!current.isEmpty() && m_cameras->currentData().toByteArray() != current)
        useChosenCamera();
}

void LiveView::useChosenCamera()
{
    CameraFeed *camera = m_controller->camera();
    const QByteArray id = m_cameras->currentData().toByteArray();
    camera->close();
    if (id.isEmpty() || !isVisible())
        return;
    for (const QCameraDevice &device : QMediaDevices::videoInputs())
        if (device.id() == id) {
            QString why;
            if (!camera->open(device, &why)) {
                m_lastProblem = why;
                const QSignalBlocker block(m_cameras);
                m_cameras->setCurrentIndex(0);
                updateControls();
            }
            return;
        }
}

void LiveView::fillModels()
{
    const QString current = chosenKind();
    const QSignalBlocker block(m_models);
    m_models->clear();
    const QStringList kinds = m_controller->trainedKinds();
    for (const QString &kind : kinds) {
        m_models->addItem(ModelKinds::name(kind), kind);
        m_models->setItemData(m_models->count() - 1, ModelKinds::description(kind), Qt::ToolTipRole);
    }
    // The one the user chose, else the studio's default order (ModelKinds: Brand first), as the
    // Models panel and exports choose.
    int index = m_modelChosen ? m_models->findData(current) : -1;
    for (const QString &kind : ModelKinds::ids())
        if (index < 0)
            index = m_models->findData(kind);
    m_models->setCurrentIndex(std::max(0, index));
    if (kinds.isEmpty())
        m_models->addItem(tr("No trained model"));
}

void LiveView::showEvent(QShowEvent *event)
{
    QWidget::showEvent(event);
    // The devices and models are looked at when the view is seen (the AAM loads then, not at startup).
    fillMicrophones();
    fillModels();
    fillCameras();
    useChosenCamera();
    updateControls();
}

void LiveView::hideEvent(QHideEvent *event)
{
    // Another tab or a closed panel, not a minimised window: the microphone stops with the view.
    if (!event->spontaneous()) {
        m_controller->stop();
        m_controller->camera()->close();
    }
    QWidget::hideEvent(event);
}

void LiveView::updateControls()
{
    using State = LiveController::State;
    const State state = m_controller->state();
    const bool idle = state == State::Idle;
    const bool exporting = m_controller->isExporting();
    QString problem = isVisible() ? m_controller->problem(chosenKind()) : QString();
    const bool hasMicrophone = !m_microphones->currentData().toByteArray().isEmpty();
    if (problem.isEmpty() && !hasMicrophone)
        problem = tr("No microphone was found. Connect one (the list above follows the devices as they come and go), "
                     "or choose A recording… there.");
    m_start->setEnabled(idle && !exporting && problem.isEmpty() && isVisible());
    m_stop->setEnabled(state == State::Preparing || state == State::Running);
    m_microphones->setEnabled(idle); // a recording is always there to choose
    m_models->setEnabled(idle && !m_controller->trainedKinds().isEmpty());
    m_cameras->setEnabled(m_cameras->count() > 1);
    const bool recorded = idle && m_controller->hasRecording();
    m_save->setEnabled(recorded && !exporting);
    m_export->setEnabled(recorded && !exporting);
    m_recogniser->setText(m_controller->recognisesWithSphinx() ? tr("Phones: CMU Sphinx US English (any speaker)")
                                                               : tr("Phones: the aligner model's HMMs"));
    m_recogniser->adjustSize();

    QString message;
    switch (state) {
    case State::Preparing:
        message = tr("Preparing: loading the phone recogniser and finding the face in the current sequence…");
        break;
    case State::Running:
        message = m_controller->input() == LiveController::Input::File
                      ? tr("Playing %1: the face follows its sound.").arg(m_playing)
                      : tr("Listening. Speak, and the face follows.");
        break;
    case State::Finishing:
        message = tr("Finishing the last frames…");
        break;
    case State::Idle:
        if (!m_lastProblem.isEmpty())
            message = m_lastProblem;
        else if (exporting)
            message = tr("Writing the video…");
        else if (recorded)
            message = tr("The last session (%1 s) is kept: save it as a sequence, export it as a video, or start "
                         "again.")
                          .arg(QLocale().toString(m_controller->recordedSeconds(), 'f', 1));
        // A start refused for this problem left it as the last problem: say it once.
        if (!problem.isEmpty() && problem != m_lastProblem)
            message = message.isEmpty() ? problem : message + QLatin1Char(' ') + problem;
        else if (message.isEmpty())
            message = tr("Press Start and speak: the face moves with your voice.");
        break;
    }
    if (m_controller->waitsForPhones(chosenKind()))
        message += (message.isEmpty() ? QString() : QStringLiteral(" "))
                   + tr("This model's file predates Live's guess of phones in context, so its face waits for each "
                        "phone to end, in pauses for seconds. Train it again for a face that follows at once.");
    if (m_controller->recordingTruncated())
        message += QLatin1Char(' ')
                   + tr("Only the first %1 minutes are kept for saving; the face went on moving after that.")
                         .arg(int(LiveController::kMaxRecordedSeconds / 60));
    // Without a face to show, the message takes its place; beneath, it would only repeat it.
    m_face->setPlaceholderText(message);
    m_message->setText(m_face->image().isNull() ? QString() : message);
    m_message->setVisible(!m_message->text().isEmpty());
}

void LiveView::showFrames()
{
    const LiveController *c = m_controller;
    if (!c->lastImage().isNull() && m_face->image().isNull()) {
        m_face->setImage(c->lastImage());
        updateControls(); // the message moves from the face to beneath it
    } else if (!c->lastImage().isNull()) {
        m_face->setImage(c->lastImage());
    }
    m_strip->setPhones(c->recentPhones(), c->soundSeconds());
    double mean = 0.0, worst = 0.0;
    if (c->latency(&mean, &worst)) {
        m_latency->setText(tr("Latency: %1 ms mean, %2 ms max")
                               .arg(std::lround(1000 * mean))
                               .arg(std::lround(1000 * worst)));
        m_latency->setToolTip(tr("Time from the sound to the frame that shows it, over the last %1 seconds; %2 ms of "
                                 "it the phone recogniser and the model wait for the sound that follows")
                                  .arg(LiveController::kLatencyWindowSeconds)
                                  .arg(std::lround(1000 * c->algorithmicLatency())));
    } else {
        m_latency->setText(tr("Latency: –"));
    }
    m_progress->setText(c->framesShown() > 0 ? tr("%1 s, frame %2 at %3 fps")
                                                   .arg(QLocale().toString(c->soundSeconds(), 'f', 1))
                                                   .arg(c->framesShown())
                                                   .arg(QLocale().toString(c->frameRate(), 'g', 4))
                                             : QString());
}

void LiveView::start()
{
    const QByteArray id = m_microphones->currentData().toByteArray();
    if (id == kFileInput) {
        const QString path = QFileDialog::getOpenFileName(
            this, tr("Live from a Recording"), m_context->document()->exportFolder(),
            tr("Audio and video (*.wav *.flac *.mp3 *.ogg *.m4a *.mpg *.mp4 *.mov *.avi *.mkv *.webm);;All files (*)"));
        if (!path.isEmpty())
            startWithFile(path, !ErrorReporter::isBatchMode());
        return;
    }
    m_lastProblem.clear();
    QAudioDevice device;
    for (const QAudioDevice &d : QMediaDevices::audioInputs())
        if (d.id() == id)
            device = d;
    QString why;
    m_face->setImage({});
    m_strip->clear();
    if (!m_controller->start(chosenKind(), LiveController::Input::Microphone, device, &why))
        m_lastProblem = why;
    updateControls();
}

bool LiveView::startWithFile(const QString &path, bool audible)
{
    m_lastProblem.clear();
    QString why;
    m_face->setImage({});
    m_strip->clear();
    m_playing = QFileInfo(path).fileName();
    const bool started = m_controller->startFromFile(chosenKind(), path, &why, audible);
    if (!started)
        m_lastProblem = why;
    updateControls();
    return started;
}

bool LiveView::startWithFedSound()
{
    m_lastProblem.clear();
    QString why;
    m_face->setImage({});
    m_strip->clear();
    const bool started = m_controller->start(chosenKind(), LiveController::Input::Fed, {}, &why);
    if (!started)
        m_lastProblem = why;
    updateControls();
    return started;
}

void LiveView::stop()
{
    m_controller->stop();
}

void LiveView::say(const QString &message)
{
    m_lastProblem = message;
    updateControls();
}

void LiveView::saveAsSequence()
{
    ProjectDocument *document = m_context->document();
    if (!ensureWritableProject(this, *document, m_saveProject, tr("Save as Sequence"),
                               tr("The session's sound is written into the project's folder, and the bundled "
                                  "demo is read-only. Save the project in a folder of your own first?")))
        return;
    QString why;
    const QString id = m_controller->saveAsSequence(&why);
    if (id.isEmpty()) {
        say(why);
        return;
    }
    m_context->showStatus(tr("The live session is sequence %1, at the end of the list.").arg(id), 8000);
    emit sequenceSaved(id);
}

void LiveView::exportVideo()
{
    const QString folder = m_context->document()->exportFolder();
    const QString path = QFileDialog::getSaveFileName(this, tr("Export Live Session"),
                                                      QDir(folder).filePath(QStringLiteral("live-session.mp4")),
                                                      tr("MP4 video (*.mp4)"));
    if (path.isEmpty())
        return;
    QString why;
    if (!m_controller->exportVideo(path, &why))
        say(why);
    updateControls();
}

} // namespace lipsync::studio
