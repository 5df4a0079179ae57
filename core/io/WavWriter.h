#pragma once
// Mono 16-bit PCM WAV files of audio the project holds as float samples (the utterances cut out of
// a long sound-only recording): muxed by libavformat's WAV muxer into memory, then written
// atomically (io/AtomicFile).
#include <string>
#include <vector>

namespace lipsync {

// Writes samples [begin, end) of `samples` (mono, [-1, 1], clipped beyond) at `sampleRate`.
// Throws lipsync::Error naming the file when it cannot be written.
void writeWav(const std::string &path, const std::vector<float> &samples, size_t begin, size_t end, int sampleRate);

} // namespace lipsync
