#pragma once
// Where each decoded audio frame sounds on the media timeline (seconds from the file's start,
// the time base of VideoReader::timestamp), as a player presents it: from its timestamp, not
// from the count of samples decoded before it.
//  - the stream's start offset is kept (sound that starts 0.5 s after the picture starts at 0.5);
//  - a timestamp gap (joined clips, dropped packets) is filled with silence;
//  - samples that overlap what is already placed are dropped;
//  - a frame without a timestamp follows the one before it;
//  - a jump past the container's end (a broken timestamp) is not filled: the frame follows on,
//    and the jump is counted as a discontinuity, so no input grows the sound without bound.
// MediaScan (what `info` reports) and AudioDecoder (what is aligned and played) place frames
// with this one class, so the two agree.
#include <cstdint>
#include <limits>
#include <vector>

namespace lipsync {

struct AudioGap
{
    double at = 0.0;     // timeline time where the sound stops
    double length = 0.0; // seconds of silence filled (negative: seconds of overlap dropped)
};

class AudioTimeline
{
public:
    // Timestamp steps within this many seconds of contiguous are taken as contiguous.
    static constexpr double kTolerance = 0.001;

    // `limitSeconds`: the container's duration (gaps that would reach past it are discontinuities).
    explicit AudioTimeline(double limitSeconds = std::numeric_limits<double>::infinity());

    struct Placement
    {
        double start = 0.0;   // timeline time of the first sample kept
        long long skip = 0;   // leading samples of the frame dropped (overlap)
        bool silenceBefore = false; // start lies after the end of what was placed: fill with silence
    };
    // Places a frame of `samples` samples at `rate` whose timestamp is `pts` seconds on the
    // timeline (NaN when the frame has none).
    Placement place(double pts, long long samples, int rate);

    bool started() const { return m_started; }
    double firstTime() const { return m_first; }  // where the sound starts (0 before any frame)
    double endTime() const { return m_cursor; }   // where the last sample placed ends
    const std::vector<AudioGap> &gaps() const { return m_gaps; } // the first kMaxListed
    int gapCount() const { return m_gapCount; }
    double gapSeconds() const { return m_gapSeconds; }
    int overlapCount() const { return m_overlapCount; }
    double overlapSeconds() const { return m_overlapSeconds; }
    int discontinuities() const { return m_discontinuities; }

    static constexpr int kMaxListed = 1000;

private:
    double m_limit;
    bool m_started = false;
    double m_first = 0.0;
    double m_cursor = 0.0;
    std::vector<AudioGap> m_gaps;
    int m_gapCount = 0;
    double m_gapSeconds = 0.0;
    int m_overlapCount = 0;
    double m_overlapSeconds = 0.0;
    int m_discontinuities = 0;
};

} // namespace lipsync
