#include "io/AudioTimeline.h"

#include <cmath>

namespace lipsync {

AudioTimeline::AudioTimeline(double limitSeconds)
    : m_limit(limitSeconds > 0 && std::isfinite(limitSeconds) ? limitSeconds + 1.0
                                                              : std::numeric_limits<double>::infinity())
{
}

AudioTimeline::Placement AudioTimeline::place(double pts, long long samples, int rate)
{
    Placement p;
    const double length = rate > 0 ? double(samples) / rate : 0.0;
    p.start = m_cursor;
    if (std::isfinite(pts)) {
        const double step = pts - m_cursor;
        if (step > kTolerance) {
            if (pts + length > m_limit) {
                ++m_discontinuities; // a broken timestamp: follow on instead of filling
            } else {
                p.start = pts;
                p.silenceBefore = true;
                if (m_started) {
                    ++m_gapCount;
                    m_gapSeconds += step;
                    if (int(m_gaps.size()) < kMaxListed)
                        m_gaps.push_back({m_cursor, step});
                }
            }
        } else if (step < -kTolerance) {
            // Overlap (or audio before the file's start): drop what was already covered.
            p.skip = std::min(samples, (long long)std::llround(-step * rate));
            if (m_started) {
                ++m_overlapCount;
                m_overlapSeconds += double(p.skip) / rate;
                if (int(m_gaps.size()) < kMaxListed)
                    m_gaps.push_back({pts, -double(p.skip) / rate});
            }
        }
    }
    const double kept = rate > 0 ? double(samples - p.skip) / rate : 0.0;
    if (!m_started && samples > p.skip) {
        m_started = true;
        m_first = p.start;
    }
    m_cursor = p.start + kept;
    return p;
}

} // namespace lipsync
