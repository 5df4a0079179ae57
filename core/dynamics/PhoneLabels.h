#pragma once
// Frame labels from phone alignments (models.md §0). Accepted inputs:
//  - Praat TextGrid, long or short text form: the interval tier named "phones" (any case; a file
//    with a single interval tier uses that one). UTF-8 or UTF-16 with BOM is not decoded: UTF-8 only.
//  - .lab: one "start end phone" line per segment, times in seconds (blank lines and lines starting
//    with '#' ignored).
//  - for generation also a per-frame list: one phone name per line (any other extension).
// Phone names are mapped by PhoneSet::index (stress digits dropped, sil/sp/spn/"" = silence).
// Every failure throws lipsync::Error naming the file and the line or tier.
#include "project/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

Tier readPhoneTier(const std::string &path);
Tier parseTextGridPhones(const std::string &text, const std::string &pathForErrors = {});
Tier parseLabPhones(const std::string &text, const std::string &pathForErrors = {});

// The voting rule of §0: 100 Hz audio frames with centres 0.01 j + 0.0125 s vote for the video
// frame [i/fps, (i+1)/fps) holding their centre; majority wins, ties go to the tied label of the
// audio frame nearest the video-frame centre; a video frame without audio frames takes the label
// at its centre. Time not covered by the tier is silence. frameCount <= 0: ceil(end * fps).
std::vector<int> frameLabelsFromTier(const Tier &phones, double fps, int frameCount = 0,
                                     const std::string &pathForErrors = {});

// TextGrid / .lab -> voting at fps; otherwise a per-frame list of phone names.
std::vector<int> readFrameLabels(const std::string &path, double fps, int frameCount = 0);

} // namespace lipsync
