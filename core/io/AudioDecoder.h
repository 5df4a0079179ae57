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
    // Presentation time of samples[0] in seconds on the media timeline (the time base of
    // VideoReader::timestamp and of tiers). AudioDecoder::decode places its samples on the
    // timeline from its start, so 0 for every decoded file; a cut of the sound keeps its place.
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
    // The samples lie on the media timeline as a player presents them (AudioTimeline): sample 0
    // at the file's start, silence before a stream that starts late and in timestamp gaps,
    // overlaps dropped; the buffer ends where the sound ends (a shorter sound than picture
    // leaves the rest to the caller).
    static AudioBuffer decode(const std::string &path, int sampleRate = 16000);
};

} // namespace lipsync
