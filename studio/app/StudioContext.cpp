#include "app/StudioContext.h"

#include "app/ModelStore.h"
#include "app/ProjectDocument.h"
#include "app/SequenceMedia.h"
#include "preview/PlaybackController.h"
#include "tasks/TaskRunner.h"

#include <QUndoStack>

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
    m_frame = frame;
    emit currentFrameChanged(frame);
}

} // namespace lipsync::studio

namespace lipsync::studio {

void StudioContext::showStatus(const QString &message, int milliseconds)
{
    emit statusMessage(message, milliseconds);
}

} // namespace lipsync::studio
