#pragma once
// The 23 AAM landmarks of one frame (eyes, mouth, jaw-line; the paper's §4 model). Each point
// carries a state, as 3D Slicer's markups do: a point not yet placed is a state, never a magic
// coordinate.
#include <array>
#include <string>

namespace lipsync {

enum class PointState {
    Undefined, // not placed in this frame
    Placed,    // clicked by a user
    Automatic, // from a detector or the AAM; may be moved by a refit
    Fixed,     // corrected by a user: refits keep it where it is
};

const char *pointStateName(PointState state);
// Returns false if `name` is not one of the names above.
bool pointStateFromName(const std::string &name, PointState &state);

struct LandmarkPoint
{
    double x = 0.0;
    double y = 0.0;
    PointState state = PointState::Undefined;

    bool isDefined() const { return state != PointState::Undefined; }
    bool operator==(const LandmarkPoint &) const = default;
};

struct LandmarkSet
{
    static constexpr int kPointCount = 23;
    std::array<LandmarkPoint, kPointCount> points{};

    int definedCount() const;
    bool isComplete() const { return definedCount() == kPointCount; }
    bool operator==(const LandmarkSet &) const = default;
};

} // namespace lipsync
