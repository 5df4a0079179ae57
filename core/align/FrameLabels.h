#pragma once
// Phone label of every video frame by voting (docs/models.md §0): 100 Hz audio frame j has centre
// c_j = j * shift + window / 2 (0.01 j + 0.0125 s by default) and belongs to video frame i when
// c_j lies in the time the frame is on screen, [t_i, t_{i+1}) on the media timeline (FrameClock:
// the stream's timestamps, so offsets and variable frame rates are honoured; i / fps only for a
// clip whose frames are evenly spaced from 0). Each audio frame takes the phone whose interval
// holds c_j; the video frame takes the phone held by most of its audio frames.
// Tie rule [choice, after docs/models.md §0]: among the phones tied for most audio frames, the one
// whose audio frame centre is nearest the video frame's centre (t_i + t_{i+1}) / 2; if two such
// centres are equally near, the earlier one. A video frame containing no audio-frame centre (a
// frame rate above 100 Hz, or past the last audio frame) takes the phone at its own centre.
// Times not covered by the tier are silence ("sil").
#include "annotation/FrameClock.h"
#include "annotation/Tier.h"
#include "audio/Mfcc.h"

#include <string>
#include <vector>

namespace lipsync {

std::vector<std::string> voteFrameLabels(const Tier &phones, const FrameClock &frames,
                                         const MfccOptions &audioFrames = {});
// The labels of video frames [firstFrame, firstFrame + frameCount) alone (streaming: the frames
// whose audio frames are labelled so far, from a tier of those audio frames). Frames past the
// clock's end follow at its rate.
std::vector<std::string> voteFrameLabels(const Tier &phones, const FrameClock &frames, int firstFrame,
                                         int frameCount, const MfccOptions &audioFrames);

} // namespace lipsync
