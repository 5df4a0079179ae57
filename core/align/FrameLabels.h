#pragma once
// Phone label of every video frame by voting (docs/models.md §0): 100 Hz audio frame j has centre
// c_j = j * shift + window / 2 (0.01 j + 0.0125 s by default) and belongs to video frame i when
// c_j lies in [i / fps, (i + 1) / fps). Each audio frame takes the phone whose interval holds
// c_j; the video frame takes the phone held by most of its audio frames.
// Tie rule [choice, after docs/models.md §0]: among the phones tied for most audio frames, the one
// whose audio frame centre is nearest the video frame's centre (i + 1/2) / fps; if two such
// centres are equally near, the earlier one. A video frame containing no audio-frame centre (a
// frame rate above 100 Hz, or past the last audio frame) takes the phone at its own centre.
// Times not covered by the tier are silence ("sil").
#include "audio/Mfcc.h"
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

std::vector<std::string> voteFrameLabels(const Tier &phones, double frameRate, int frameCount,
                                         const MfccOptions &audioFrames = {});
// The labels of video frames [firstFrame, firstFrame + frameCount) alone (streaming: the frames
// whose audio frames are labelled so far, from a tier of those audio frames).
std::vector<std::string> voteFrameLabels(const Tier &phones, double frameRate, int firstFrame, int frameCount,
                                         const MfccOptions &audioFrames);

} // namespace lipsync
