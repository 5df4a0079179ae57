#pragma once
// The sound of one recording for every step of a job that needs it: an aligner at its own rate,
// the output at the recording's own. Once own() has decoded the recording at its own rate, every
// other rate is resampled from that by libswresample (SoundResampler) instead of decoding the file
// again; before, at() decodes the file at the rate asked (AudioDecoder::decode, exactly). Only the
// recording's own rate is kept; a copy at another rate belongs to the caller. Thread-safe.
#include "io/AudioDecoder.h"

#include <memory>
#include <mutex>
#include <string>

namespace lipsync {

class RecordingSound
{
public:
    explicit RecordingSound(std::string mediaPath) : m_path(std::move(mediaPath)) {}

    const std::string &path() const { return m_path; }
    // The recording at its own rate, decoded once and kept. Errors as AudioDecoder::decode.
    std::shared_ptr<const AudioBuffer> own() const;
    // The sound on the media timeline at `sampleRate` (0: the recording's own). Errors as
    // AudioDecoder::decode, naming the file.
    std::shared_ptr<const AudioBuffer> at(int sampleRate) const;

private:
    std::string m_path;
    mutable std::mutex m_mutex;
    mutable std::shared_ptr<const AudioBuffer> m_own;
};

} // namespace lipsync
