#include "live/LiveController.h"

#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "live/CameraFeed.h"
#include "live/FileInput.h"
#include "live/MicrophoneInput.h"

#include "aam/AamModel.h"
#include "aam/FaceDetector.h"
#include "align/AcousticModel.h"
#include "align/PhoneBigram.h"
#include "align/ShippedAlignerModel.h"
#include "align/SphinxAligner.h"
#include "align/SphinxPhoneRecognizer.h"
#include "dynamics/DynamicModel.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/WavWriter.h"
#include "render/FaceRenderer.h"
#include "render/VideoExporter.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QThread>

#include <algorithm>
#include <cmath>
#include <utility>

namespace lipsync::studio {

LiveController::LiveController(StudioContext *context, QObject *parent)
    : QObject(parent), m_context(context), m_microphone(new MicrophoneInput(this)), m_file(new FileInput(this)),
      m_camera(std::make_shared<CameraFeed>())
{
    qRegisterMetaType<LiveFrames>();
    connect(m_microphone, &MicrophoneInput::captured, this, &LiveController::take);
    connect(m_file, &FileInput::captured, this, &LiveController::take);
    connect(m_file, &FileInput::ended, this, &LiveController::stop); // the recording has been said
    // Another project: its session and recording were the old one's (the old AAM's features).
    connect(context->document(), &ProjectDocument::documentReset, this, &LiveController::reset);
}

LiveController::~LiveController()
{
    m_microphone->stop();
    m_file->stop();
    ++m_epoch;
    if (m_prepareTask)
        m_prepareTask->cancel();
    endThread(true);
}

bool LiveController::sphinxChosen(std::string *modelDir) const
{
    const AlignerChoice &choice = m_context->modelStore()->alignerChoice();
    if (modelDir)
        *modelDir = choice.sphinxModelDir();
    return choice.isSphinx();
}

bool LiveController::recognisesWithSphinx() const
{
    return isActive() ? m_sessionSphinx : sphinxChosen();
}

QString LiveController::alignerModelPath() const
{
    // Our HMMs recognise with the timeline's aligner model when it is one of ours, else with the
    // shipped one.
    const AlignerChoice &choice = m_context->modelStore()->alignerChoice();
    const std::string path = choice.model.empty() || choice.isSphinx() ? shippedAlignerModelPath() : choice.model;
    return !path.empty() && QFileInfo::exists(QString::fromStdString(path)) ? QString::fromStdString(path) : QString();
}

QStringList LiveController::trainedKinds() const
{
    QStringList kinds;
    if (!m_context->document()->isOpen())
        return kinds;
    for (const QString &kind : ModelKinds::ids())
        if (const auto model = m_context->modelStore()->dynamicModel(kind); model && model->isTrained())
            kinds << kind;
    return kinds;
}

bool LiveController::waitsForPhones(const QString &kind) const
{
    const std::shared_ptr<const DynamicModel> model = m_context->modelStore()->dynamicModel(kind);
    return model && model->isTrained() && model->promptStreamer()->latency() < 0;
}

QString LiveController::problem(const QString &kind) const
{
    const ProjectDocument *document = m_context->document();
    if (!document->isOpen())
        return tr("Open a project to go live: the face is drawn with its appearance model and animated by its "
                  "trained dynamic model.");
    ModelStore *store = m_context->modelStore();
    if (!document->project().aam())
        return tr("The project has no appearance model. Build one (Faces ▸ Build AAM), then train a dynamic model "
                  "in the Models panel.");
    QString why;
    const std::shared_ptr<const AamModel> aam = store->aam(&why);
    if (!aam)
        return tr("The project's appearance model could not be loaded: %1").arg(why);
    if (trainedKinds().isEmpty())
        return tr("No dynamic model is trained yet. Train one in the Models panel (DPDS follows live speech best), "
                  "then start again.");
    const std::shared_ptr<const DynamicModel> model = store->dynamicModel(kind);
    if (!model || !model->isTrained())
        return tr("Choose a trained model.");
    if (model->dimension() != aam->combinedModes())
        return tr("The %1 model was trained with another appearance model: train it again in the Models panel.")
            .arg(ModelKinds::name(kind));
    if (std::string sphinxDir; sphinxChosen(&sphinxDir))
        return SphinxAligner::available(sphinxDir)
                   ? QString()
                   : tr("CMU Sphinx's US-English models, which recognise the phones when the timeline aligns with "
                        "CMU Sphinx, were not found. Install the Debian package pocketsphinx-en-us, or choose the "
                        "built-in model in the timeline's Model menu.");
    if (alignerModelPath().isEmpty())
        return tr("The studio's aligner model, which recognises the phones, was not found. Reinstall the studio or "
                  "point LIPSYNC_ALIGNER_MODEL at an aligner model.");
    if (shippedPhoneBigramPath().empty())
        return tr("The phone bigram for live recognition (aligner/grid-s1.bigram) was not found. Reinstall the "
                  "studio.");
    return {};
}

void LiveController::setState(State state)
{
    if (m_state == state)
        return;
    m_state = state;
    emit stateChanged(state);
}

namespace {

// A recording's sound, mono at the session's rate; refused before decoding when it has none or is
// longer than a session keeps (bounded memory).
std::shared_ptr<const std::vector<float>> decodeForSession(const std::string &path, int sampleRate)
{
    const MediaInfo info = MediaInfo::probe(path);
    if (!info.hasAudio)
        throw Error("the file has no sound", path);
    if (info.audioDuration > FileInput::kMaxSeconds)
        throw Error("the sound lasts " + std::to_string(int(info.audioDuration / 60)) + " minutes; Live takes at most "
                        + std::to_string(int(FileInput::kMaxSeconds / 60)),
                    path);
    return std::make_shared<const std::vector<float>>(AudioDecoder::decode(path, sampleRate).samples);
}

} // namespace

bool LiveController::start(const QString &kind, Input input, const QAudioDevice &device, QString *why)
{
    auto refuse = [why](const QString &reason) {
        if (why)
            *why = reason;
        return false;
    };
    if (m_state != State::Idle)
        return refuse(tr("A live session is running already."));
    if (isExporting())
        return refuse(tr("Wait until the video export has ended."));
    if (const QString p = problem(kind); !p.isEmpty())
        return refuse(p);
    if (input == Input::Microphone && device.isNull())
        return refuse(tr("Choose a microphone."));
    ModelStore *store = m_context->modelStore();
    const std::shared_ptr<const AamModel> aam = store->aam();
    const std::shared_ptr<const DynamicModel> model = store->dynamicModel(kind);
    m_input = input;
    m_device = device;
    const int epoch = ++m_epoch;
    clearShown();

    // The face goes into a still of the person: the first frame of the sequence shown, when it
    // has a video; else the AAM's mean face on grey.
    const std::shared_ptr<const SequenceMedia> media = m_context->media();
    const QString background = media && !media->audioOnly ? media->mediaPath : QString();
    std::shared_ptr<FaceRenderer> renderer =
        m_renderer && m_rendererAam == aam && m_rendererMedia == background ? m_renderer : nullptr;
    // The phones: CMU Sphinx's recogniser when the timeline aligns with it, else our HMMs.
    std::string sphinxDir;
    const bool sphinx = sphinxChosen(&sphinxDir);
    m_sessionSphinx = sphinx;
    const std::string acousticPath = sphinx ? std::string() : alignerModelPath().toStdString();
    std::shared_ptr<const AcousticModel> acoustic = m_acousticPath == acousticPath ? m_acoustic : nullptr;
    std::shared_ptr<const PhoneBigram> bigram = m_bigram;
    const std::string bigramPath = shippedPhoneBigramPath();
    const std::string soundFile = input == Input::File ? m_inputPath.toStdString() : std::string();
    m_fileSound.reset();

    setState(State::Preparing);
    QPointer<LiveController> self(this);
    m_prepareTask = m_context->taskRunner()->start(
        tr("Prepare the live view"),
        [self, epoch, aam, model, renderer, sphinx, sphinxDir, acoustic, bigram, acousticPath, bigramPath,
         background, soundFile](Feedback &feedback) -> TaskRunner::Commit {
            LiveSetup setup;
            setup.aam = aam;
            setup.model = model;
            if (sphinx) {
                // A recogniser of its own for each session: it holds the session's search.
                feedback.setStatus("loading CMU Sphinx's phone models");
                SphinxPhoneOptions options;
                options.modelDir = sphinxDir;
                setup.sphinx = std::make_shared<std::unique_ptr<PhoneStream>>(
                    std::make_unique<SphinxPhoneRecognizer>(options));
                setup.sampleRate = (*setup.sphinx)->frameOptions().sampleRate;
            } else {
                feedback.setStatus("loading the aligner model");
                setup.acoustic =
                    acoustic ? acoustic : std::make_shared<const AcousticModel>(AcousticModel::load(acousticPath));
                setup.bigram = bigram ? bigram : std::make_shared<const PhoneBigram>(PhoneBigram::load(bigramPath));
                setup.sampleRate = setup.acoustic->featureOptions().sampleRate;
            }
            setup.renderer = renderer;
            bool tracked = !background.isEmpty();
            if (!setup.renderer && tracked) {
                feedback.setStatus("tracking the head pose");
                FaceDetector detector(FaceDetectorPaths::boxesOnly());
                try {
                    // The Live view draws into the clip's first frame: only that one is tracked.
                    setup.renderer = std::make_shared<FaceRenderer>(*aam, background.toStdString(), feedback,
                                                                    &detector, 1);
                } catch (const Error &) {
                    tracked = false; // no face found in the clip: the mean face on grey instead
                }
            }
            if (!setup.renderer)
                setup.renderer = std::make_shared<FaceRenderer>(*aam);
            setup.options.stillBackground = true;
            std::shared_ptr<const std::vector<float>> sound;
            if (!soundFile.empty()) {
                feedback.setStatus("decoding the recording's sound");
                sound = decodeForSession(soundFile, setup.sampleRate);
            }
            return [self, epoch, setup, acousticPath, background, tracked, sound] {
                if (!self || self->m_epoch != epoch || self->m_state != State::Preparing)
                    return;
                if (setup.acoustic) {
                    self->m_acoustic = setup.acoustic;
                    self->m_acousticPath = acousticPath;
                    self->m_bigram = setup.bigram;
                }
                self->m_fileSound = sound;
                self->m_renderer = setup.renderer;
                self->m_rendererAam = setup.aam;
                // A clip whose face could not be tracked is not tried again for this AAM.
                self->m_rendererMedia = background;
                if (!background.isEmpty() && !tracked)
                    self->m_context->showStatus(
                        tr("No face was found in %1: the live face is drawn on grey.").arg(QFileInfo(background).fileName()),
                        8000);
                self->launch(setup);
            };
        });
    connect(m_prepareTask, &Task::finished, this, [this, epoch, task = m_prepareTask.data()](Task::State state) {
        if (state == Task::State::Finished || epoch != m_epoch || m_state != State::Preparing)
            return;
        setState(State::Idle);
        if (state == Task::State::Failed)
            emit failed(tr("The live view could not be prepared: %1").arg(task->errorMessage()));
    });
    return true;
}

void LiveController::launch(LiveSetup setup)
{
    setup.renderer->setCompositeOptions(m_context->compositeOptions());
    setup.camera = m_camera;
    setup.options.closeBilabials = m_context->closesLips();
    m_sampleRate = setup.sampleRate;
    m_recording = Recording{};
    m_recording.sampleRate = m_sampleRate;
    m_recording.aam = setup.aam;
    m_recording.renderer = setup.renderer;
    m_recording.still = setup.options.stillBackground;
    emit recordingChanged();

    const int epoch = m_epoch;
    m_thread = new QThread(this);
    m_thread->setObjectName(QStringLiteral("live session"));
    m_worker = new LiveWorker(std::move(setup));
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    // Signals of an abandoned session may still be queued: dropped by the epoch.
    connect(m_worker, &LiveWorker::started, this, [this, epoch](double frameRate, double latency) {
        if (epoch != m_epoch)
            return;
        m_frameRate = frameRate;
        m_algorithmicLatency = latency;
        m_recording.frameRate = frameRate;
    });
    connect(m_worker, &LiveWorker::framesReady, this, [this, epoch](const LiveFrames &frames) {
        if (epoch == m_epoch)
            onFrames(frames);
    });
    connect(m_worker, &LiveWorker::failed, this, [this, epoch](const QString &why) {
        if (epoch == m_epoch)
            onWorkerFailed(why);
    });
    m_thread->start();
    QMetaObject::invokeMethod(m_worker, &LiveWorker::begin, Qt::QueuedConnection);

    if (m_input == Input::Microphone) {
        if (const QString why = m_microphone->start(m_device, m_sampleRate); !why.isEmpty()) {
            ++m_epoch;
            endThread(true);
            m_recording = Recording{};
            setState(State::Idle);
            emit recordingChanged();
            emit failed(tr("The microphone could not be opened: %1.").arg(why));
            return;
        }
    }
    setState(State::Running);
    if (m_input == Input::File && m_fileSound)
        m_file->start(std::exchange(m_fileSound, {}), m_sampleRate, m_inputPath, m_audible);
    if (!m_pending.empty())
        take(std::exchange(m_pending, {}), LiveWorker::Clock::now());
}

bool LiveController::startFromFile(const QString &kind, const QString &path, QString *why, bool audible)
{
    if (m_state == State::Idle) {
        m_inputPath = path;
        m_audible = audible;
    }
    return start(kind, Input::File, {}, why);
}

void LiveController::feed(const std::vector<float> &samples)
{
    if (m_input != Input::Fed)
        return;
    if (m_state == State::Preparing)
        m_pending.insert(m_pending.end(), samples.begin(), samples.end());
    else
        take(samples, LiveWorker::Clock::now());
}

void LiveController::take(const std::vector<float> &samples, LiveWorker::Clock::time_point captured)
{
    if (m_state != State::Running || !m_worker || samples.empty())
        return;
    // Kept up to the limit; the face goes on moving beyond it.
    const auto limit = std::size_t(kMaxRecordedSeconds * m_sampleRate);
    const std::size_t room = limit - std::min(limit, m_recording.sound.size());
    const std::size_t kept = std::min(room, samples.size());
    m_recording.sound.insert(m_recording.sound.end(), samples.begin(), samples.begin() + std::ptrdiff_t(kept));
    if (kept < samples.size() && !m_recording.truncated) {
        m_recording.truncated = true;
        emit recordingChanged();
    }
    LiveWorker *worker = m_worker;
    QMetaObject::invokeMethod(
        worker, [worker, samples, captured] { worker->push(samples, captured); }, Qt::QueuedConnection);
}

void LiveController::onFrames(const LiveFrames &frames)
{
    const auto keptFrames = std::size_t(std::lround(kMaxRecordedSeconds * m_recording.frameRate));
    const auto window = std::size_t(std::max(1L, std::lround(kLatencyWindowSeconds * m_frameRate)));
    for (std::size_t i = 0; i < frames.features.size(); ++i) {
        ++m_framesShown;
        if (!frames.images[i].isNull())
            m_lastImage = frames.images[i];
        if (m_recording.features.size() < keptFrames) {
            m_recording.features.push_back(frames.features[i]);
            m_recording.labels.push_back(frames.labels[i]);
        }
        if (std::isfinite(frames.latencies[i])) {
            m_latencies.push_back(frames.latencies[i]);
            while (m_latencies.size() > window)
                m_latencies.pop_front();
        }
    }
    m_soundSeconds = frames.soundSeconds;
    if (frames.last) {
        m_recording.phones = frames.phones;
        // The recent ones for the strip, as the batches before carried them.
        auto &recent = m_recentPhones.intervals;
        recent.clear();
        for (const Interval &p : frames.phones.intervals)
            if (p.end > m_soundSeconds - LiveWorker::kRecentPhoneSeconds)
                recent.push_back(p);
    } else {
        m_recentPhones = frames.phones;
    }
    emit framesShownChanged();
    if (frames.last) {
        m_recording.complete = true;
        endThread(false);
        setState(State::Idle);
        emit recordingChanged();
    }
}

void LiveController::onWorkerFailed(const QString &why)
{
    m_microphone->stop();
    m_file->stop();
    ++m_epoch;
    endThread(true);
    m_recording = Recording{};
    setState(State::Idle);
    emit recordingChanged();
    emit failed(tr("The live session stopped: %1").arg(why));
}

void LiveController::stop()
{
    switch (m_state) {
    case State::Idle:
    case State::Finishing:
        return;
    case State::Preparing:
        ++m_epoch;
        if (m_prepareTask)
            m_prepareTask->cancel();
        m_pending.clear();
        setState(State::Idle);
        return;
    case State::Running:
        m_microphone->stop();
        m_file->stop();
        setState(State::Finishing);
        QMetaObject::invokeMethod(m_worker, &LiveWorker::finish, Qt::QueuedConnection);
        return;
    }
}

void LiveController::endThread(bool abandon)
{
    if (!m_thread)
        return;
    if (abandon && m_worker)
        m_worker->abandon();
    // The worker is deleted on its thread as the thread ends (QThread::finished -> deleteLater).
    m_thread->quit();
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_worker = nullptr;
}

void LiveController::clearShown()
{
    m_pending.clear();
    m_framesShown = 0;
    m_soundSeconds = 0.0;
    m_lastImage = QImage();
    m_recentPhones.intervals.clear();
    m_latencies.clear();
}

void LiveController::reset()
{
    m_microphone->stop();
    m_file->stop();
    ++m_epoch;
    if (m_prepareTask)
        m_prepareTask->cancel();
    endThread(true);
    clearShown();
    m_renderer.reset();
    m_rendererAam.reset();
    m_rendererMedia.clear();
    m_recording = Recording{};
    setState(State::Idle);
    emit framesShownChanged();
    emit recordingChanged();
}

bool LiveController::latency(double *meanSeconds, double *maxSeconds) const
{
    if (m_latencies.empty())
        return false;
    double sum = 0.0, worst = 0.0;
    for (double l : m_latencies) {
        sum += l;
        worst = std::max(worst, l);
    }
    *meanSeconds = sum / double(m_latencies.size());
    *maxSeconds = worst;
    return true;
}

bool LiveController::hasRecording() const
{
    return m_recording.complete && !m_recording.features.empty();
}

double LiveController::recordedSeconds() const
{
    return m_recording.sampleRate > 0 ? double(m_recording.sound.size()) / m_recording.sampleRate : 0.0;
}

QString LiveController::saveAsSequence(QString *why)
{
    auto refuse = [why](const QString &reason) {
        if (why)
            *why = reason;
        return QString();
    };
    ProjectDocument *document = m_context->document();
    if (!hasRecording())
        return refuse(tr("Nothing is recorded yet: start a session and stop it first."));
    if (!document->isOpen())
        return refuse(tr("No project is open."));
    if (document->isReadOnly())
        return refuse(tr("The bundled demo is read-only: save the project in a folder of your own first."));
    if (m_context->modelStore()->aam() != m_recording.aam)
        return refuse(tr("The project's appearance model changed since the recording: its features no longer fit."));

    // A new id, and a file name no earlier save left on disk.
    const Project &project = document->project();
    const QDir folder(QString::fromStdString(project.folder()));
    QString id;
    for (int n = 1; id.isEmpty(); ++n) {
        const QString candidate = QStringLiteral("live_%1").arg(n, 4, 10, QLatin1Char('0'));
        if (!project.sequence(candidate.toStdString())
            && !QFileInfo::exists(folder.filePath(QStringLiteral("live/%1.wav").arg(candidate))))
            id = candidate;
    }
    const QString file = QStringLiteral("live/%1.wav").arg(id);
    const QString path = folder.filePath(file);
    try {
        if (!folder.mkpath(QStringLiteral("live")))
            throw Error("the folder could not be created", folder.filePath(QStringLiteral("live")).toStdString());
        writeWav(path.toStdString(), m_recording.sound, 0, m_recording.sound.size(), m_recording.sampleRate);
    } catch (const Error &e) {
        return refuse(tr("The sound could not be written: %1").arg(QString::fromUtf8(e.what())));
    }

    const double seconds = recordedSeconds();
    const int frames = std::min(int(m_recording.features.size()),
                                std::max(1, int(std::lround(seconds * m_recording.frameRate))));
    Sequence s;
    s.id = id.toStdString();
    s.mediaFile = file.toStdString();
    s.frameRate = m_recording.frameRate;
    s.frameCount = frames;
    s.features.resize(frames, m_recording.features.front().size());
    for (int i = 0; i < frames; ++i)
        s.features.row(i) = m_recording.features[std::size_t(i)].transpose();
    // The phones of the sound kept (all of it unless the session outlasted the limit).
    for (Interval p : m_recording.phones.intervals) {
        if (p.start >= seconds)
            break;
        p.end = std::min(p.end, seconds);
        s.phones.intervals.push_back(std::move(p));
    }
    if (!document->requestAddSequences({std::move(s)}, tr("Save Live Session as %1").arg(id))) {
        QFile::remove(path);
        return refuse(tr("The project refused the new sequence (the status bar says why)."));
    }
    return id;
}

Task *LiveController::exportVideo(const QString &path, QString *why)
{
    auto refuse = [why](const QString &reason) -> Task * {
        if (why)
            *why = reason;
        return nullptr;
    };
    if (!hasRecording())
        return refuse(tr("Nothing is recorded yet: start a session and stop it first."));
    if (isActive())
        return refuse(tr("Stop the session first."));
    if (isExporting())
        return refuse(tr("A video export is running already."));
    // The worker's copies: the recording may be replaced by the next session meanwhile (which
    // waits for the export: the renderer is not shared between threads).
    auto features = std::make_shared<const std::vector<Eigen::VectorXd>>(m_recording.features);
    auto sound = std::make_shared<AudioBuffer>();
    sound->sampleRate = m_recording.sampleRate;
    sound->samples = m_recording.sound;
    const std::shared_ptr<FaceRenderer> renderer = m_recording.renderer;
    const bool still = m_recording.still;
    const double frameRate = m_recording.frameRate;
    QPointer<LiveController> self(this);
    Task *task = m_context->taskRunner()->start(
        tr("Export the live session to %1").arg(QFileInfo(path).fileName()),
        [self, path, features, sound, renderer, still, frameRate](Feedback &feedback) -> TaskRunner::Commit {
            VideoExportOptions options;
            options.setFrameRate(frameRate);
            const int count = int(features->size());
            lipsync::exportVideo(
                path.toStdString(), count,
                [&](int i) { return renderer->render(still ? 0 : i, (*features)[std::size_t(std::min(i, count - 1))]); },
                sound.get(), feedback, options);
            return [self, path] {
                if (self)
                    self->m_context->showStatus(tr("The live session was written to %1.").arg(path), 8000);
            };
        });
    m_exportTask = task;
    connect(task, &Task::finished, this, [this, task, path](Task::State state) {
        if (m_exportTask == task)
            m_exportTask = nullptr;
        if (state == Task::State::Failed)
            emit failed(tr("The video could not be written: %1").arg(task->errorMessage()));
        emit exportEnded(state == Task::State::Finished ? path : QString());
    });
    emit exportStarted();
    return task;
}

} // namespace lipsync::studio
