#include "preview/PlaybackController.h"

#include <QAudioOutput>
#include <QDateTime>
#include <QMediaPlayer>
#include <QTimer>
#include <QUrl>

#include <cmath>

namespace lipsync::studio {

PlaybackController::PlaybackController(QObject *parent) : QObject(parent), m_timer(new QTimer(this))
{
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &PlaybackController::tick);
}

void PlaybackController::setSequence(const QString &mediaPath, int frameCount, double frameRate)
{
    pause();
    m_mediaPath = mediaPath;
    m_frameCount = frameCount;
    m_frameRate = frameRate > 0 ? frameRate : 25.0;
    if (m_player)
        m_player->setSource(QUrl::fromLocalFile(mediaPath));
}

void PlaybackController::play(int fromFrame)
{
    if (m_frameCount <= 0)
        return;
    m_frame = fromFrame >= m_frameCount - 1 ? 0 : fromFrame; // at the end, play from the start
    m_startFrame = m_frame;
    m_startMs = QDateTime::currentMSecsSinceEpoch();
    if (m_audioEnabled) {
        if (!m_player) {
            m_player = new QMediaPlayer(this);
            m_output = new QAudioOutput(this);
            m_player->setAudioOutput(m_output);
            m_player->setSource(QUrl::fromLocalFile(m_mediaPath));
        }
        m_player->setPosition(qint64(std::llround(m_frame / m_frameRate * 1000.0)));
        m_player->play();
    }
    m_playing = true;
    // Tick faster than the frame rate and pick the frame from the wall clock, so timer jitter
    // never accumulates into drift.
    m_timer->start(std::max(5, int(500.0 / m_frameRate)));
    emit frameReached(m_frame);
    emit playingChanged(true);
}

void PlaybackController::pause()
{
    if (!m_playing)
        return;
    m_timer->stop();
    if (m_player)
        m_player->pause();
    m_playing = false;
    emit playingChanged(false);
}

void PlaybackController::tick()
{
    const double elapsed = (QDateTime::currentMSecsSinceEpoch() - m_startMs) / 1000.0;
    const int frame = m_startFrame + int(elapsed * m_frameRate);
    if (frame >= m_frameCount) {
        emit frameReached(m_frameCount - 1);
        pause();
        return;
    }
    if (frame != m_frame) {
        m_frame = frame;
        emit frameReached(frame);
    }
}

} // namespace lipsync::studio
