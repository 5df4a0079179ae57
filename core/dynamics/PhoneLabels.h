#pragma once
// Frame labels from phone alignments (docs/models.md §0), read with the io readers and voted with
// the align module's rule (align/FrameLabels). Accepted inputs:
//  - Praat TextGrid (io/TextGrid): the interval tier named "phones" (or "phone", "phonemes"; any
//    case; a file with a single interval tier uses that one).
//  - .lab (io/HtkLabel): one "start end phone" line per segment, times in seconds or in HTK's
//    100 ns units (blank lines and lines starting with '#' ignored).
//  - for generation also a per-frame list: one phone name per line (any other extension).
// Phone names are mapped by PhoneSet::index (stress digits dropped, sil/sp/spn/"" = silence).
// Every failure throws lipsync::Error naming the file and the line or tier.
#include "annotation/FrameClock.h"
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

Tier readPhoneTier(const std::string &path);
Tier parseTextGridPhones(const std::string &text, const std::string &pathForErrors = {});
Tier parseLabPhones(const std::string &text, const std::string &pathForErrors = {});

// voteFrameLabels (align/FrameLabels.h, docs/models.md §0) as PhoneSet indices, one per frame of
// `frames`; throws naming the file for a phone outside the 41-phone set.
std::vector<int> frameLabelsFromTier(const Tier &phones, const FrameClock &frames,
                                     const std::string &pathForErrors = {});
// The same for frames known only by their rate (a feature table's "# fps="), evenly spaced from
// time 0. frameCount <= 0: ceil(end * fps).
std::vector<int> frameLabelsFromTier(const Tier &phones, double fps, int frameCount = 0,
                                     const std::string &pathForErrors = {});

// TextGrid / .lab -> voting at fps; otherwise a per-frame list of phone names.
std::vector<int> readFrameLabels(const std::string &path, double fps, int frameCount = 0);

} // namespace lipsync
