#include "live/SampleConverter.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace lipsync::studio {

SampleConverter::SampleConverter(const QAudioFormat &input, int outputRate)
    : m_input(input), m_outputRate(outputRate),
      m_step(input.sampleRate() > 0 && outputRate > 0 ? double(input.sampleRate()) / outputRate : 1.0)
{
    // The first output sample falls on the first input sample.
    m_position = 1.0;
}

float SampleConverter::monoSample(const char *frame) const
{
    const int channels = std::max(1, m_input.channelCount());
    const int width = m_input.bytesPerSample();
    float sum = 0.0f;
    for (int c = 0; c < channels; ++c) {
        const char *p = frame + c * width;
        float v = 0.0f;
        switch (m_input.sampleFormat()) {
        case QAudioFormat::UInt8:
            v = (float(static_cast<unsigned char>(*p)) - 128.0f) / 128.0f;
            break;
        case QAudioFormat::Int16: {
            qint16 s;
            std::memcpy(&s, p, 2);
            v = float(s) / 32768.0f;
            break;
        }
        case QAudioFormat::Int32: {
            qint32 s;
            std::memcpy(&s, p, 4);
            v = float(double(s) / 2147483648.0);
            break;
        }
        case QAudioFormat::Float:
            std::memcpy(&v, p, 4);
            break;
        default:
            break;
        }
        sum += v;
    }
    return sum / float(channels);
}

std::vector<float> SampleConverter::convert(const char *bytes, qsizetype count)
{
    const int frameBytes = m_input.bytesPerFrame();
    std::vector<float> out;
    if (frameBytes <= 0)
        return out;
    std::vector<char> joined;
    if (!m_partial.empty()) {
        joined = std::exchange(m_partial, {});
        joined.insert(joined.end(), bytes, bytes + count);
        bytes = joined.data();
        count = qsizetype(joined.size());
    }
    const qsizetype frames = count / frameBytes;
    m_partial.assign(bytes + frames * frameBytes, bytes + count);
    if (frames == 0)
        return out;
    out.reserve(std::size_t(double(frames) / m_step) + 2);
    // Input sample k of this block sits at position k + 1 (0 is the block before's last one);
    // each output sample interpolates between the two input samples around its position.
    float before = m_previous;
    qsizetype loaded = 0; // input samples of this block read so far
    float after = 0.0f;
    while (m_position <= double(frames)) {
        const qsizetype right = qsizetype(std::ceil(m_position)); // 1..frames
        while (loaded < right) {
            before = loaded == 0 ? m_previous : after;
            after = monoSample(bytes + loaded * frameBytes);
            ++loaded;
        }
        const double t = m_position - double(right - 1);
        out.push_back(float((1.0 - t) * before + t * after));
        m_position += m_step;
    }
    m_previous = monoSample(bytes + (frames - 1) * frameBytes);
    m_position -= double(frames);
    return out;
}

} // namespace lipsync::studio
