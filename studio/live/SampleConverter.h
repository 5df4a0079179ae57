#pragma once
// Microphone bytes to what the live session takes: mono float samples at one rate. Any
// QAudioFormat a device offers (unsigned 8-bit, 16- and 32-bit integer or float, any number of
// interleaved channels, any rate) is read as float; its channels are averaged and its rate changed
// by libswresample (core/io/SoundResampler), across blocks without a seam. Only for a device that
// cannot deliver mono at the session's rate itself (MicrophoneInput asks for that first).
#include "io/SoundResampler.h"

#include <QAudioFormat>

#include <memory>
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
    float sample(const char *p) const;

    QAudioFormat m_input;
    std::vector<char> m_partial; // bytes of a frame split between blocks
    std::unique_ptr<SoundResampler> m_resampler; // null when the input is mono at the output rate
};

} // namespace lipsync::studio
