#pragma once
// Audio PCM from any media file (.mpg/.mp4/.wav...) through libavformat/libavcodec, resampled
// with libswresample to mono float at the requested rate.
#include <string>
#include <vector>

namespace lipsync {

struct AudioBuffer
{
    int sampleRate = 0;
    std::vector<float> samples; // mono, [-1, 1]
    // Presentation time of samples[0] in seconds from the start of the file (the time base of
    // VideoReader::timestamp); 0 for GRID clips.
    double startTime = 0.0;

    double duration() const { return sampleRate > 0 ? double(samples.size()) / sampleRate : 0.0; }
};

class AudioDecoder
{
public:
    // Decodes the first audio stream of `path`, mixed down to mono and resampled to `sampleRate`
    // (0 keeps the stream's own rate). Throws lipsync::Error naming the file for missing,
    // corrupt or truncated files and for files without audio ("no audio stream").
    // Channels are averaged (so the mix stays in [-1, 1]); resampling is libswresample's.
    static AudioBuffer decode(const std::string &path, int sampleRate = 16000);
};

} // namespace lipsync
