#pragma once
// When each video frame of a sequence is on screen, on the media timeline: seconds from the
// start of the file, as a player presents it (the time base of tiers, AudioBuffer samples and
// VideoReader::timestamp). Frame i is shown from time(i) until endTime(i) = time(i + 1); the last
// frame lasts one nominal period 1 / rate().
//
// Most recordings have evenly spaced frames, kept as (first time, rate, count): 29.97 fps is the
// exact 30000/1001 when the stream says so. A variable-frame-rate recording (phones, screen
// capture, edited exports with dropped frames) keeps every frame's presentation time. Every
// frame <-> time conversion goes through this class, never index / fps.
#include <memory>
#include <vector>

namespace lipsync {

class FrameClock
{
public:
    FrameClock() = default;
    // `count` frames every 1 / rate seconds from `firstTime`.
    static FrameClock uniform(double rate, int count, double firstTime = 0.0);
    // Frames at `times` (seconds, increasing). `rate` is the stream's nominal rate (the last
    // frame's length; estimated from the times when not positive). Evenly spaced times (within
    // 0.1 ms) give the uniform clock.
    static FrameClock fromTimes(std::vector<double> times, double rate);

    int count() const { return m_count; }
    bool empty() const { return m_count == 0; }
    double rate() const { return m_rate; }
    double period() const { return m_rate > 0 ? 1.0 / m_rate : 0.0; }
    bool isVariable() const { return m_times != nullptr; }

    // Presentation time of frame i; indices outside [0, count) extrapolate at rate().
    double time(int i) const;
    // When frame i leaves the screen: time(i + 1), or time(i) + 1 / rate() for the last.
    double endTime(int i) const;
    double centre(int i) const { return 0.5 * (time(i) + endTime(i)); }
    // The frame on screen at time t: the last frame with time(i) <= t, 0 before the first frame
    // and count() - 1 after the last (-1 for an empty clock).
    int frameAt(double t) const;
    // The frame whose presentation time is nearest t (ties to the earlier).
    int nearestFrame(double t) const;
    // First frame shown and end of the last: [time(0), endTime(count() - 1)).
    double startTime() const { return m_count > 0 ? time(0) : 0.0; }
    double endTime() const { return m_count > 0 ? endTime(m_count - 1) : 0.0; }
    double duration() const { return endTime() - startTime(); }

    // Every frame's presentation time (count() entries).
    std::vector<double> times() const;
    // The frames [first, first + n) as a clock of their own, times unchanged.
    FrameClock slice(int first, int n) const;
    // Every time moved by `seconds`.
    FrameClock shifted(double seconds) const;
    // The start of the first frame at or after t (within 1 µs), or endTime() past the last;
    // the start of the frame on screen at t. A grid to cut at: both are frame boundaries.
    double boundaryAtOrAfter(double t) const;
    double boundaryAtOrBefore(double t) const;
    // The frame that starts at boundary `t` (count() at endTime()).
    int frameAtBoundary(double t) const;

    bool operator==(const FrameClock &other) const;

private:
    int m_count = 0;
    double m_rate = 0.0;
    double m_first = 0.0;                               // uniform: time of frame 0
    std::shared_ptr<const std::vector<double>> m_times; // variable: every frame's time
};

} // namespace lipsync
