#include "live/SampleConverter.h"

#include <cstring>
#include <utility>

namespace lipsync::studio {

SampleConverter::SampleConverter(const QAudioFormat &input, int outputRate) : m_input(input)
{
    if (input.channelCount() != 1 || input.sampleRate() != outputRate)
        m_resampler = std::make_unique<SoundResampler>(input.sampleRate(), input.channelCount(), outputRate);
}

float SampleConverter::sample(const char *p) const
{
    switch (m_input.sampleFormat()) {
    case QAudioFormat::UInt8:
        return (float(static_cast<unsigned char>(*p)) - 128.0f) / 128.0f;
    case QAudioFormat::Int16: {
        qint16 s;
        std::memcpy(&s, p, 2);
        return float(s) / 32768.0f;
    }
    case QAudioFormat::Int32: {
        qint32 s;
        std::memcpy(&s, p, 4);
        return float(double(s) / 2147483648.0);
    }
    case QAudioFormat::Float: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
    }
    default:
        return 0.0f;
    }
}

std::vector<float> SampleConverter::convert(const char *bytes, qsizetype count)
{
    const int frameBytes = m_input.bytesPerFrame();
    if (frameBytes <= 0)
        return {};
    std::vector<char> joined;
    if (!m_partial.empty()) {
        joined = std::exchange(m_partial, {});
        joined.insert(joined.end(), bytes, bytes + count);
        bytes = joined.data();
        count = qsizetype(joined.size());
    }
    const qsizetype frames = count / frameBytes;
    m_partial.assign(bytes + frames * frameBytes, bytes + count);
    // Every sample as float, channels interleaved as they came.
    const int width = m_input.bytesPerSample();
    const qsizetype samples = frames * m_input.channelCount();
    std::vector<float> interleaved(static_cast<std::size_t>(samples));
    for (qsizetype i = 0; i < samples; ++i)
        interleaved[std::size_t(i)] = sample(bytes + i * width);
    if (!m_resampler)
        return interleaved;
    return m_resampler->push(interleaved.data(), std::size_t(frames));
}

} // namespace lipsync::studio
