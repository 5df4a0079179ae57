#include "context/StudioContext.h"

#include "context/CommandRegistry.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/SequenceLoader.h"
#include "context/SequenceMedia.h"
#include "document/ProjectDocument.h"
#include "tasks/TaskRunner.h"

#include "aam/AamModel.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/PhoneLabels.h"
#include "render/BilabialClosure.h"
#include "render/PostureTransfer.h"
#include "util/Error.h"

#include <QUndoStack>

#include <algorithm>

namespace lipsync::studio {

StudioContext::StudioContext(QObject *parent)
    : QObject(parent), m_undo(new QUndoStack(this)), m_runner(new TaskRunner(this)),
      m_document(new ProjectDocument(m_undo, this)), m_models(new ModelStore(m_document, this)),
      m_playback(new PlaybackController(this))
{
    // Playback moves the current frame, unless it plays the Preview's new speech.
    connect(m_playback, &PlaybackController::frameReached, this, [this](int frame) {
        if (m_media && m_playback->mediaPath() == m_media->mediaPath)
            setCurrentFrame(frame);
    });
    // A new document: the old one's media dropped and any load for it canceled.
    connect(m_document, &ProjectDocument::documentReset, this, &StudioContext::clearCurrentSequence);
    // The rows before `first` stay where they were. When the sequence shown (or loading) was among
    // the removed ones, the views let it go (sequenceLoaded without media) and the last remaining
    // sequence takes its place.
    connect(m_document, &ProjectDocument::sequencesRemoved, this, [this](int first) {
        if (m_row < first && m_pendingRow < first)
            return;
        clearCurrentSequence();
        announceSequenceLoaded();
        selectSequence(first - 1);
    });
    // After the context's own handlers, so that commands validate on the context they leave.
    m_commands = new CommandRegistry(this);
}

StudioContext::~StudioContext()
{
    // Workers must be gone before the state their commits would reach.
    m_runner->cancelAll();
    m_runner->waitForAll();
}

void StudioContext::selectSequence(int row)
{
    if (row < 0 || row >= m_document->sequenceCount() || row == m_pendingRow || (row == m_row && m_pendingRow < 0))
        return;
    if (m_loadTask)
        m_loadTask->cancel(); // superseded: its result must not arrive after this one's
    m_playback->pause();
    m_pendingRow = row;
    const Sequence &s = m_document->sequence(row);
    const SequenceSource source{QString::fromStdString(s.id), m_document->mediaPath(row), s.frameRate};
    Task *task = SequenceLoader::start(*m_runner, source, [this, row](std::shared_ptr<const SequenceMedia> media) {
        applyLoadedMedia(row, std::move(media));
    });
    m_loadTask = task;
    connect(task, &Task::finished, this, [this, task, path = source.mediaPath] { onLoadFinished(task, path); });
    emit sequenceRequested(row);
    showStatus(tr("Loading %1…").arg(source.id), 3000);
}

void StudioContext::applyLoadedMedia(int row, std::shared_ptr<const SequenceMedia> media)
{
    m_loadTask = nullptr; // done, not superseded
    m_pendingRow = -1;
    if (row >= m_document->sequenceCount()) { // removed while it loaded
        emit sequenceLoadEnded(false);
        return;
    }
    setCurrentSequence(row, std::move(media));
    m_playback->setSequence(m_media->mediaPath, m_media->clock);
    setCurrentFrame(0);
    announceSequenceLoaded();
    emit sequenceLoadEnded(true);
}

void StudioContext::onLoadFinished(Task *task, const QString &mediaPath)
{
    if (task->state() == Task::State::Finished)
        return; // applyLoadedMedia ran
    if (task->state() == Task::State::Failed)
        emit sequenceLoadFailed(mediaPath, task->errorMessage());
    if (task != m_loadTask)
        return; // superseded by a newer load
    m_pendingRow = -1;
    emit sequenceLoadEnded(false);
}

void StudioContext::setCurrentSequence(int row, std::shared_ptr<const SequenceMedia> media)
{
    if (m_loadTask) // superseded: its result must not arrive after this one
        m_loadTask->cancel();
    m_loadTask = nullptr;
    m_pendingRow = -1;
    m_row = row;
    m_media = std::move(media);
    m_frame = -1;
}

void StudioContext::announceSequenceLoaded()
{
    emit sequenceLoaded(m_media ? m_media->sequenceId : QString());
}

void StudioContext::clearCurrentSequence()
{
    if (m_loadTask)
        m_loadTask->cancel();
    m_pendingRow = -1;
    m_playback->pause();
    m_row = -1;
    m_media.reset();
    m_frame = 0;
}

void StudioContext::setCurrentFrame(int frame)
{
    if (!m_media || m_media->frameCount() == 0)
        return;
    frame = std::clamp(frame, 0, m_media->frameCount() - 1);
    if (frame == m_frame)
        return;
    m_frame = frame;
    emit currentFrameChanged(frame);
}

void StudioContext::seek(double seconds)
{
    if (m_speech)
        emit speechSeekRequested(seconds);
    else if (m_media)
        setCurrentFrame(std::max(0, m_media->clock.frameAt(seconds)));
}

void StudioContext::togglePlayback()
{
    if (m_playback->isPlaying()) {
        m_playback->pause();
    } else if (m_media) {
        if (m_playback->mediaPath() != m_media->mediaPath)
            m_playback->setSequence(m_media->mediaPath, m_media->clock);
        m_playback->play(m_frame);
    }
}

bool StudioContext::selection(double *start, double *end) const
{
    if (m_selectionEnd <= m_selectionStart)
        return false;
    *start = m_selectionStart;
    *end = m_selectionEnd;
    return true;
}

void StudioContext::setSelection(double start, double end)
{
    m_selectionStart = start;
    m_selectionEnd = end;
}

void StudioContext::setShownSpeech(std::shared_ptr<const SpeechToFaceResult> speech, const QString &title)
{
    if (speech == m_speech)
        return;
    m_speech = std::move(speech);
    m_speechTitle = m_speech ? title : QString();
    emit shownSpeechChanged();
}

void StudioContext::setCompositeOptions(const CompositeOptions &options)
{
    if (options == m_composite)
        return;
    m_composite = options;
    emit compositeOptionsChanged();
}

void StudioContext::setClosesLips(bool close)
{
    if (close == m_closesLips)
        return;
    m_closesLips = close;
    emit lipClosureChanged();
}

void StudioContext::showStatus(const QString &message, int milliseconds)
{
    emit statusMessage(message, milliseconds);
}

std::shared_ptr<const PostureTransfer> StudioContext::postureFor(const QString &kind,
                                                                 const std::shared_ptr<const DynamicModel> &model,
                                                                 const AamModel &aam) const
{
    CachedPosture &cached = m_postures[kind];
    // An AAM without an identifier cannot be told from another: built afresh each time.
    if (aam.identifier.empty() || cached.model.lock() != model || cached.aam != aam.identifier)
        cached = {model, aam.identifier, PostureTransfer::forModel(*model, aam)};
    return cached.posture;
}

std::vector<StudioContext::GeneratedTrajectory> StudioContext::generatedTrajectories(int row, const AamModel *aam) const
{
    std::vector<GeneratedTrajectory> out;
    if (row < 0 || row >= m_document->sequenceCount())
        return out;
    const Sequence &s = m_document->sequence(row);
    std::vector<int> labels;
    try {
        labels = frameLabelsFromTier(s.phones, s.clock(), s.id);
    } catch (const Error &) {
        return out; // no usable phones: nothing to generate from
    }
    const Eigen::Index dimension = aam ? aam->combinedModes() : s.features.cols();
    for (const QString &kind : ModelKinds::ids()) {
        const auto model = m_models->dynamicModel(kind);
        if (!model || labels.empty() || model->dimension() != dimension)
            continue;
        try {
            Eigen::MatrixXd generated = model->generate(labels);
            if (aam && m_closesLips)
                generated = BilabialClosure::closeOnPhones(*aam, generated, s.phones, s.clock());
            out.push_back({kind, std::move(generated), aam ? postureFor(kind, model, *aam) : nullptr});
        } catch (const Error &) {
        }
    }
    return out;
}

} // namespace lipsync::studio
