#pragma once
// This person's mouth, mapped to what animation tools read, learned from the project's own
// tracked and aligned frames:
//  - the range of every measure (MouthMeasures) over those frames, its 2nd to 98th percentile, so
//    that 0..1 controls span this speaker's own mouth (AnimationControls);
//  - the nine Rhubarb shapes (MouthShape) as points in four cue features — opening, width,
//    rounding, teeth showing, each on that 0..1 scale: each shape's mean over the frames whose
//    phone Rhubarb's documentation gives it (seedShapeOfPhone), and the spread within shapes.
// A frame's cue is then the shape its features are likeliest under, weighed by the phone's own
// shape as a prior; silence and breath are always X and /p b m/ always A (Rhubarb's semantics).
// The user's own shapes (Project::mouthShapes, edited in the studio) replace learned ones.
#include "animation/MouthMeasures.h"
#include "animation/MouthShape.h"

#include <Eigen/Core>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace lipsync {

struct MouthTrack;

class MouthMapping
{
public:
    static constexpr int kCueFeatures = 4; // opening, width, rounding, teeth
    using CueFeatures = Eigen::Matrix<double, kCueFeatures, 1>;

    // Learned from `tracks` (a project's sequences). Throws lipsync::Error when they hold fewer
    // than kMinimumFrames speech frames.
    static MouthMapping learn(const std::vector<MouthTrack> &tracks);
    static constexpr int kMinimumFrames = 50;

    // `value` of measure `index` (MouthMeasures::values() order) on this person's 0..1 scale.
    double normalised(int index, double value) const;
    CueFeatures cueFeatures(const MouthMeasures &m) const;
    // The shape of one frame, its phone a PhoneSet index.
    MouthShape classify(const MouthMeasures &m, int phone) const;

    const CueFeatures &shape(MouthShape s) const { return m_shapes[size_t(s)]; }
    // How many frames taught shape `s` (0: a shape of the user's, or one no phone gave).
    int framesOf(MouthShape s) const { return m_frames[size_t(s)]; }
    bool isUsers(MouthShape s) const { return m_users[size_t(s)]; }
    // The user's shapes (Project::mouthShapes: letter -> 4 values) replace the learned ones.
    void applyUserShapes(const std::map<std::string, std::array<double, 4>> &shapes);

private:
    std::array<double, MouthMeasures::kCount> m_low{}, m_high{};
    std::array<CueFeatures, kMouthShapeCount> m_shapes{};
    std::array<int, kMouthShapeCount> m_frames{};
    std::array<bool, kMouthShapeCount> m_users{};
    CueFeatures m_spread = CueFeatures::Constant(0.2);
};

} // namespace lipsync
