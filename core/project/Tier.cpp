#include "project/Tier.h"

#include <algorithm>

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

} // namespace lipsync
