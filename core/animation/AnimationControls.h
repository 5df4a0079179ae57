#pragma once
// Continuous per-frame controls for 3D rigs and blendshapes, normalised 0..1 over this person's
// own range (MouthMapping), named after Apple ARKit's blend shapes where one matches. ARKit's
// left and right are the subject's: mouthStretchLeft is the corner on the image's right.
//   jawOpen               the chin's drop below the eyes
//   mouthClose            lips together while the jaw is open: jawOpen - mouthOpen, at least 0
//   mouthFunnel           a narrow, open mouth: (1 - width) * mouthOpen
//   mouthPucker           a narrow, closed mouth: (1 - width) * (1 - mouthOpen)
//   mouthStretchLeft/Right   each corner's distance from the face's midline
//   mouthUpperUpLeft/Right   each side of the upper lip above the corners' line
//   mouthLowerDownLeft/Right each side of the lower lip below it
//   mouthOpen             the inner-lip gap (no ARKit shape: what a 2D rig's open mouth follows)
// Also the 23 points in the AAM's normalised frame (centred, unit size, eyes level): free of
// head pose, for rigs of their own.
//
// Files (docs/formats.md):
//   JSON  {"format": "lipsync-controls", "version": 1, "soundFile", "frameRate", "frameCount",
//          "controls": [names], "frames": [{"time", "values": [...], "points": [x0, y0, ...]}]}
//   CSV   "# soundFile: …" and "# frameRate: …" lines, then a header
//          frame,time,<controls>,x0,y0,…,x22,y22 and one row per frame.
#include "annotation/FrameClock.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

class MouthMapping;
struct MouthTrack;

struct AnimationControls
{
    std::string soundFile;
    double frameRate = 0;      // the frames' nominal rate
    std::vector<double> times; // each frame's start, seconds on the sound file's timeline
    std::vector<std::string> names;
    Eigen::MatrixXd values;    // frames x names
    Eigen::MatrixXd points;    // frames x 46

    int frameCount() const { return int(times.size()); }
    // The column of control `name`, -1 when absent.
    int column(const std::string &name) const;
};

// The controls' names, in column order.
const std::vector<std::string> &animationControlNames();

AnimationControls animationControls(const MouthTrack &track, const MouthMapping &mapping);

// .json or .csv by the extension, atomically. Throws lipsync::Error naming the path.
void writeAnimationControls(const AnimationControls &controls, const std::string &path);
// Reads either back. Throws lipsync::Error naming the file and the line or field at fault.
AnimationControls readAnimationControls(const std::string &path);

} // namespace lipsync
