#include "annotation/LandmarkSet.h"

#include <algorithm>

namespace lipsync {

namespace {
// The manifest spells states in lower case; the order matches the enum.
constexpr const char *kStateNames[] = {"undefined", "placed", "automatic", "fixed"};
} // namespace

const char *pointStateName(PointState state)
{
    return kStateNames[int(state)];
}

bool pointStateFromName(const std::string &name, PointState &state)
{
    for (int i = 0; i < 4; ++i) {
        if (name == kStateNames[i]) {
            state = PointState(i);
            return true;
        }
    }
    return false;
}

int LandmarkSet::definedCount() const
{
    return int(std::count_if(points.begin(), points.end(),
                             [](const LandmarkPoint &p) { return p.isDefined(); }));
}

} // namespace lipsync
