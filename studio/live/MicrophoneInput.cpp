#include "live/MicrophoneInput.h"

#include "live/SampleConverter.h"

#include <QAudioSource>
#include <QIODevice>

namespace lipsync::studio {

MicrophoneInput::MicrophoneInput(QObject *parent) : QObject(parent) {}

MicrophoneInput::~MicrophoneInput()
{
    stop();
}

QString MicrophoneInput::start(const QAudioDevice &device, int sampleRate)
{
    stop();
    if (device.isNull())
        return tr("no microphone was chosen");
    QAudioFormat format;
    format.setSampleRate(sampleRate);
    format.setChannelCount(1);
    format.setSampleFormat(QAudioFormat::Float);
    if (!device.isFormatSupported(format))
        format.setSampleFormat(QAudioFormat::Int16);
    if (!device.isFormatSupported(format))
        format = device.preferredFormat(); // converted and resampled here
    if (format.sampleRate() <= 0 || format.channelCount() <= 0 || format.bytesPerFrame() <= 0)
        return tr("the microphone %1 offers no sound format the studio can read").arg(device.description());
    m_converter = std::make_unique<SampleConverter>(format, sampleRate);
    m_source = new QAudioSource(device, format, this);
    // Small device buffers: every millisecond the sound waits there is latency.
    m_source->setBufferSize(format.bytesForDuration(40000));
    m_io = m_source->start();
    if (!m_io || m_source->error() != QAudio::NoError) {
        stop();
        return tr("the microphone %1 could not be opened").arg(device.description());
    }
    connect(m_io, &QIODevice::readyRead, this, &MicrophoneInput::read);
    return {};
}

void MicrophoneInput::stop()
{
    if (m_source) {
        if (m_io)
            disconnect(m_io, nullptr, this, nullptr);
        m_source->stop();
        delete m_source;
    }
    m_source = nullptr;
    m_io = nullptr;
    m_converter.reset();
}

void MicrophoneInput::read()
{
    if (!m_io || !m_converter)
        return;
    const auto now = std::chrono::steady_clock::now();
    const QByteArray bytes = m_io->readAll();
    if (bytes.isEmpty())
        return;
    std::vector<float> samples = m_converter->convert(bytes.constData(), bytes.size());
    if (!samples.empty())
        emit captured(samples, now);
}

} // namespace lipsync::studio
