#include "context/PlaybackController.h"

#include "io/AudioDecoder.h"
#include "util/Error.h"

#include <QAudioDevice>
#include <QAudioFormat>
#include <QAudioSink>
#include <QBuffer>
#include <QMediaDevices>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace lipsync::studio {

PlaybackController::PlaybackController(QObject *parent) : QObject(parent), m_timer(new QTimer(this))
{
    // Ticks well above any video frame rate; each tick reads the clock, so timer jitter never
    // accumulates into drift.
    m_timer->setTimerType(Qt::PreciseTimer);
    m_timer->setInterval(10);
    connect(m_timer, &QTimer::timeout, this, &PlaybackController::tick);
}

PlaybackController::~PlaybackController()
{
    stopAudio();
}

void PlaybackController::setSequence(const QString &mediaPath, const FrameClock &frames, double duration)
{
    pause();
    m_mediaPath = mediaPath;
    m_frames = frames;
    m_duration = duration >= 0 ? duration : frames.endTime();
    m_position = 0.0;
    m_frame = -1;
}

int PlaybackController::frameAt(double seconds) const
{
    // The frame on screen at that moment, as a click on the timeline picks it (MainWindow).
    return std::max(0, m_frames.frameAt(seconds));
}

void PlaybackController::play(int fromFrame)
{
    const int frameCount = m_frames.count();
    if (frameCount <= 0 && m_duration <= 0)
        return;
    if (frameCount > 0 && fromFrame >= frameCount - 1)
        fromFrame = 0; // at the end: from the start
    fromFrame = std::max(0, fromFrame);
    startRange(frameCount > 0 ? m_frames.time(fromFrame) : 0.0, m_duration, fromFrame);
}

void PlaybackController::playRange(double from, double to)
{
    startRange(from, to, -1);
}

void PlaybackController::startRange(double from, double to, int fromFrame)
{
    const bool wasPlaying = m_playing;
    m_timer->stop();
    stopAudio();
    m_playing = false;
    from = std::clamp(from, 0.0, std::max(0.0, m_duration));
    to = std::clamp(to, from, std::max(0.0, m_duration));
    if (to - from < 0.005 || (m_mediaPath.isEmpty() && m_frames.count() <= 0)) {
        if (wasPlaying)
            emit playingChanged(false);
        return;
    }
    m_from = from;
    m_to = to;
    m_position = from;
    m_frame = -1;
    startClock();
    m_playing = true;
    m_timer->start();
    if (!wasPlaying)
        emit playingChanged(true);
    m_frame = fromFrame >= 0 ? fromFrame : frameAt(from);
    emit frameReached(m_frame);
    emit positionChanged(from);
}

void PlaybackController::startClock()
{
    m_origin = m_from;
    if (!m_audioEnabled || m_mediaPath.isEmpty()) {
        m_wallClock.start(); // no sound asked for, or none to play
        return;
    }
    if (const QString why = startAudio(); !why.isEmpty()) {
        m_wallClock.start();
        emit playingSilently(why);
    }
}

QString PlaybackController::startAudio()
{
    const QAudioDevice device = QMediaDevices::defaultAudioOutput();
    if (device.isNull())
        return tr("no audio output device was found");
    QAudioFormat format = device.preferredFormat();
    if (format.sampleRate() <= 0)
        format.setSampleRate(48000);
    format.setChannelCount(std::clamp(format.channelCount(), 1, 2));
    format.setSampleFormat(QAudioFormat::Float);
    if (!device.isFormatSupported(format))
        format.setSampleFormat(QAudioFormat::Int16);
    if (!device.isFormatSupported(format))
        return tr("the audio device %1 takes neither float nor 16-bit samples").arg(device.description());
    if (m_audioPath != m_mediaPath || (m_audio && m_audio->sampleRate != format.sampleRate())) {
        // A GRID clip decodes in milliseconds; a minute of new speech in about a tenth of a second.
        m_audioPath = m_mediaPath;
        m_audio.reset();
        m_audioFailed = false;
        try {
            m_audio = std::make_shared<const AudioBuffer>(
                AudioDecoder::decode(m_mediaPath.toStdString(), format.sampleRate()));
        } catch (const Error &) {
            m_audioFailed = true; // no sound (the waveform view says why): play silent
        }
    }
    if (!m_audio || m_audioFailed || m_audio->samples.empty())
        return tr("the clip's sound could not be decoded");

    // The stretch's samples, as the device wants them. Sample 0 sounds at AudioBuffer::startTime.
    const int rate = m_audio->sampleRate;
    const auto n = qsizetype(m_audio->samples.size());
    const qsizetype first = std::clamp(qsizetype(std::llround((m_origin - m_audio->startTime) * rate)), qsizetype(0), n);
    const qsizetype last = std::clamp(qsizetype(std::llround((m_to - m_audio->startTime) * rate)), first, n);
    const int channels = format.channelCount();
    const bool isFloat = format.sampleFormat() == QAudioFormat::Float;
    const int bytesPerSample = isFloat ? 4 : 2;
    QByteArray bytes((last - first) * channels * bytesPerSample, Qt::Uninitialized);
    char *out = bytes.data();
    for (qsizetype i = first; i < last; ++i) {
        const float v = m_audio->samples[std::size_t(i)];
        for (int c = 0; c < channels; ++c) {
            if (isFloat) {
                std::memcpy(out, &v, 4);
            } else {
                const auto s = qint16(std::lround(std::clamp(v, -1.f, 1.f) * 32767.f));
                std::memcpy(out, &s, 2);
            }
            out += bytesPerSample;
        }
    }
    // Silence before the audio starts (a stretch beginning before startTime) delays the sound
    // by as much, so the clock below still maps device time to media time.
    const double lead = std::max(0.0, m_audio->startTime - m_origin);
    if (lead > 0)
        bytes.prepend(QByteArray(qsizetype(std::llround(lead * rate)) * channels * bytesPerSample, '\0'));

    m_pcm = new QBuffer(this);
    m_pcm->setData(bytes);
    m_pcm->open(QIODevice::ReadOnly);
    m_bytesPerSecond = double(rate) * channels * bytesPerSample;
    m_sink = new QAudioSink(device, format, this);
    m_sink->start(m_pcm);
    if (m_sink->error() != QAudio::NoError) {
        stopAudio();
        return tr("the audio device %1 could not be opened").arg(device.description());
    }
    return {};
}

void PlaybackController::stopAudio()
{
    if (m_sink) {
        m_sink->stop();
        delete m_sink;
        m_sink = nullptr;
    }
    delete m_pcm;
    m_pcm = nullptr;
}

double PlaybackController::clockPosition() const
{
    if (m_sink) {
        // Played = handed to the device minus what still waits in its buffer.
        const double buffered = (m_sink->bufferSize() - m_sink->bytesFree()) / m_bytesPerSecond;
        const double played = std::max(0.0, m_sink->processedUSecs() * 1e-6 - std::max(0.0, buffered));
        return m_origin + played;
    }
    return m_origin + m_wallClock.nsecsElapsed() * 1e-9;
}

void PlaybackController::tick()
{
    if (m_sink && m_sink->error() != QAudio::NoError && m_sink->error() != QAudio::UnderrunError) {
        // The device went away: carry on silent from here.
        const double at = m_position;
        stopAudio();
        m_wallClock.start();
        m_origin = at;
        emit playingSilently(tr("the audio device stopped"));
    }
    double t = clockPosition();
    // The device drains its buffer at the end: the sink goes idle with everything played.
    if (m_sink && m_sink->state() == QAudio::IdleState && m_pcm->atEnd())
        t = m_to;
    if (t >= m_to) {
        if (m_loop) {
            stopAudio();
            startClock();
            t = m_from;
        } else {
            t = m_to;
        }
    }
    m_position = t;
    const int frame = frameAt(t);
    if (frame != m_frame) {
        m_frame = frame;
        emit frameReached(frame);
    }
    emit positionChanged(t);
    if (t >= m_to && !m_loop)
        pause();
}

void PlaybackController::pause()
{
    if (!m_playing)
        return;
    m_timer->stop();
    stopAudio();
    m_playing = false;
    emit playingChanged(false);
}

} // namespace lipsync::studio
