#include "annotation/Tier.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lipsync {

int Tier::indexAt(double t) const
{
    // Intervals are sorted and do not overlap (the manifest loader enforces it), so the holder
    // of t is the last interval starting at or before t, if t is before its end ([start, end)).
    auto it = std::upper_bound(intervals.begin(), intervals.end(), t,
                               [](double time, const Interval &i) { return time < i.start; });
    if (it == intervals.begin())
        return -1;
    --it;
    return t < it->end ? int(it - intervals.begin()) : -1;
}

std::optional<TierDefect> Tier::defect() const
{
    for (std::size_t i = 0; i < intervals.size(); ++i) {
        const Interval &iv = intervals[i];
        const int index = int(i);
        if (!std::isfinite(iv.start))
            return TierDefect{index, "start", "must be a finite number"};
        if (!std::isfinite(iv.end))
            return TierDefect{index, "end", "must be a finite number"};
        if (iv.start < 0)
            return TierDefect{index, "start", "must not be negative"};
        if (iv.end < iv.start)
            return TierDefect{index, "end", "is before start"};
        if (i > 0 && iv.start < intervals[i - 1].end) {
            std::ostringstream message;
            message << "overlaps the previous interval (which ends at " << intervals[i - 1].end << ")";
            return TierDefect{index, "start", message.str()};
        }
    }
    return std::nullopt;
}

} // namespace lipsync
