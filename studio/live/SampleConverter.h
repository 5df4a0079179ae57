#pragma once
// Microphone bytes to what the live session takes: mono float samples at one rate. Any
// QAudioFormat a device offers (unsigned 8-bit, 16- and 32-bit integer or float, any number of
// interleaved channels, any rate) is read, its channels averaged, and its rate changed by linear
// interpolation, carried across blocks so that the blocks join without a seam. Linear
// interpolation is enough here: the recogniser reads MFCCs up to 8 kHz and a microphone's
// preferred rate (44.1 or 48 kHz) is far above it.
#include <QAudioFormat>

#include <vector>

namespace lipsync::studio {

class SampleConverter
{
public:
    SampleConverter(const QAudioFormat &input, int outputRate);

    // The samples of `bytes` (whole frames of the input format; a trailing partial frame is kept
    // for the next block) at the output rate.
    std::vector<float> convert(const char *bytes, qsizetype count);

private:
    float monoSample(const char *frame) const;

    QAudioFormat m_input;
    int m_outputRate;
    double m_step;           // input samples per output sample
    double m_position = 0.0; // of the next output sample, in input samples after m_previous
    float m_previous = 0.0f; // the last input sample of the block before
    std::vector<char> m_partial; // bytes of a frame split between blocks
};

} // namespace lipsync::studio
