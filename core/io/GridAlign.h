#pragma once
// GRID corpus word timings (.align): "start end word" per line in units of 1/25000 s (1000 units
// = one 25 fps video frame), CRLF or LF line endings, "sil"/"sp" for silence.
#include "annotation/Tier.h"

#include <string>

namespace lipsync {

constexpr double kGridAlignUnitsPerSecond = 25000.0;

// Throws lipsync::Error naming the file and line.
Tier readGridAlign(const std::string &path);
Tier parseGridAlign(const std::string &text, const std::string &pathForErrors = {});
void writeGridAlign(const std::string &path, const Tier &words);
// The words of a tier without silence labels ("sil", "sp"), space separated.
std::string transcriptFromTier(const Tier &words);

} // namespace lipsync
