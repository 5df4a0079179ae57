#pragma once
// Audio PCM from any media file (.mpg/.mp4/.wav...) through libavformat/libavcodec, resampled
// with libswresample to mono float at the requested rate.
#include <functional>
#include <string>
#include <utility>
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

    // The sound of each of `ranges` (seconds on the media timeline, [start, end), starts not
    // decreasing) as decode() places it, handed to `take(index, piece)` in order as soon as the
    // decoding reaches its end: one pass over the file, holding no more than the sound from the
    // next range's start on (a long recording cut into clips at its own rate in bounded memory).
    // A range past the end of the sound gets what there is of it (possibly nothing). Errors as
    // decode(); and for ranges out of order.
    static void decodeRanges(const std::string &path, int sampleRate,
                             const std::vector<std::pair<double, double>> &ranges,
                             const std::function<void(size_t, AudioBuffer)> &take);
};

} // namespace lipsync
