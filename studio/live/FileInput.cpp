#include "live/FileInput.h"

#include <QAudioOutput>
#include <QMediaPlayer>
#include <QTimer>
#include <QUrl>

#include <algorithm>

namespace lipsync::studio {

FileInput::FileInput(QObject *parent) : QObject(parent), m_timer(new QTimer(this))
{
    // Blocks of about 10 ms, a microphone's size.
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(10);
    connect(m_timer, &QTimer::timeout, this, &FileInput::tick);
}

FileInput::~FileInput() = default;

void FileInput::start(std::shared_ptr<const std::vector<float>> sound, int sampleRate, const QString &path,
                      bool audible)
{
    stop();
    m_sound = std::move(sound);
    m_sampleRate = sampleRate;
    m_next = 0;
    if (audible) {
        m_player = new QMediaPlayer(this);
        m_output = new QAudioOutput(this);
        m_player->setAudioOutput(m_output);
        m_player->setSource(QUrl::fromLocalFile(path));
        m_player->play();
    }
    m_clock.start();
    m_timer->start();
}

void FileInput::stop()
{
    m_timer->stop();
    m_sound.reset();
    if (m_player) {
        m_player->stop();
        m_player->deleteLater();
        m_output->deleteLater();
        m_player = nullptr;
        m_output = nullptr;
    }
}

void FileInput::tick()
{
    if (!m_sound)
        return;
    // Everything due by now at the sound's own pace, so late timer ticks do not slow it down.
    const std::size_t due =
        std::min(m_sound->size(), std::size_t(double(m_clock.nsecsElapsed()) * 1e-9 * m_sampleRate));
    if (due > m_next) {
        const std::vector<float> block(m_sound->begin() + std::ptrdiff_t(m_next), m_sound->begin() + std::ptrdiff_t(due));
        m_next = due;
        emit captured(block, std::chrono::steady_clock::now());
    }
    if (m_next >= m_sound->size()) {
        stop();
        emit ended();
    }
}

} // namespace lipsync::studio
