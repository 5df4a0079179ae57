#include "context/StudioContext.h"

#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/PlaybackController.h"
#include "context/SequenceMedia.h"
#include "document/ProjectDocument.h"
#include "tasks/TaskRunner.h"

#include "aam/AamModel.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/PhoneLabels.h"
#include "render/BilabialClosure.h"
#include "util/Error.h"

#include <QUndoStack>

#include <algorithm>

namespace lipsync::studio {

StudioContext::StudioContext(QObject *parent)
    : QObject(parent), m_undo(new QUndoStack(this)), m_runner(new TaskRunner(this)),
      m_document(new ProjectDocument(m_undo, this)), m_models(new ModelStore(m_document, this)),
      m_playback(new PlaybackController(this))
{
}

StudioContext::~StudioContext()
{
    // Workers must be gone before the state their commits would reach.
    m_runner->cancelAll();
    m_runner->waitForAll();
}

void StudioContext::setCurrentSequence(int row, std::shared_ptr<const SequenceMedia> media)
{
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
            out.push_back({kind, std::move(generated)});
        } catch (const Error &) {
        }
    }
    return out;
}

} // namespace lipsync::studio
