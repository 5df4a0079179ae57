#pragma once
// Background frames for new speech in a person's own video, as Synthesizing Obama (Suwajanakorn
// et al. 2017) re-times its target video: the recording is played forward in long runs (its head
// motion and blinks as they were), and where the speech outlasts a run it cuts back to an earlier
// frame whose head pose continues the motion — a jump no larger than the recording's own 99th
// percentile frame-to-frame pose step, placed at the calmest moment near the end of the run.
// The mouth is redrawn in every frame (LowerFaceWarp), so only the head's motion can show a cut.
//
// Pose distance between two frames: the face centre's move in face widths, plus the change of
// log scale and of in-plane angle (radians) — a step of 0.01 is a 1 % move, a 1 % zoom or 0.6°.
// When no cut is small enough (a short or restless recording), the run plays back in reverse
// from its end (no step at all at the turn, only the motion reversing).
#include "aam/Procrustes.h"

#include <vector>

namespace lipsync {

struct BackgroundRetimingOptions
{
    int shortestRun = 50;   // frames a run plays at least before a cut (2 s at 25 fps)
    int searchWindow = 50;  // the cut is placed within this many frames of the run's end
};

struct BackgroundRetiming
{
    std::vector<int> frames;   // background frame of each output frame
    std::vector<int> cuts;     // output frames where a cut lands (the first frame after it)
    std::vector<double> cutSteps; // the pose step of each cut
    int reversals = 0;         // turns played in reverse where no cut was small enough
    double naturalStep99 = 0;  // the recording's 99th-percentile frame-to-frame pose step
    double largestStep = 0;    // the largest step between consecutive output frames
};

// Pose step between the faces at poses `a` and `b` (model -> image similarities of unit-size,
// centred model shapes: the translation is where the face's centre is, the scale its size).
double poseStep(const Similarity &a, const Similarity &b);

// `frames` output frames from a background whose face poses are `poses` (one per background frame).
BackgroundRetiming retimeBackground(const std::vector<Similarity> &poses, int frames,
                                    const BackgroundRetimingOptions &options = {});

} // namespace lipsync
