#include "timeline/TimelinePlayer.h"

#include <QAudioOutput>
#include <QMediaPlayer>
#include <QTimer>
#include <QUrl>

#include <cmath>

namespace lipsync::studio {

TimelinePlayer::TimelinePlayer(QObject *parent) : QObject(parent), m_timer(new QTimer(this))
{
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(15);
    connect(m_timer, &QTimer::timeout, this, &TimelinePlayer::tick);
}

void TimelinePlayer::setMedia(const QString &mediaPath)
{
    stop();
    if (mediaPath == m_mediaPath)
        return;
    m_mediaPath = mediaPath;
    if (m_player)
        m_player->setSource(QUrl::fromLocalFile(mediaPath));
}

void TimelinePlayer::play(double from, double to)
{
    stop();
    if (to - from < 0.005 || m_mediaPath.isEmpty())
        return;
    m_from = from;
    m_to = to;
    m_position = from;
    if (m_audioEnabled) {
        if (!m_player) {
            m_player = new QMediaPlayer(this);
            m_output = new QAudioOutput(this);
            m_player->setAudioOutput(m_output);
            m_player->setSource(QUrl::fromLocalFile(m_mediaPath));
        }
        m_player->setPosition(qint64(std::llround(from * 1000.0)));
        m_player->play();
    }
    m_playing = true;
    m_clock.start();
    m_timer->start();
    emit playingChanged(true);
    emit positionChanged(from);
}

void TimelinePlayer::stop()
{
    if (!m_playing)
        return;
    m_timer->stop();
    if (m_player)
        m_player->pause();
    m_playing = false;
    emit playingChanged(false);
}

void TimelinePlayer::tick()
{
    m_position = std::min(m_to, m_from + m_clock.nsecsElapsed() * 1e-9);
    emit positionChanged(m_position);
    if (m_position >= m_to)
        stop();
}

} // namespace lipsync::studio
