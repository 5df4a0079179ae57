#pragma once
// HTK label files: .lab ("start end label [score...]" per line, times in 100 ns units; lines
// with only a label are untimed) and master label files .mlf ("#!MLF!#", then for each file a
// quoted pattern line, its label lines and a "." line). Only the first label level is read.
// Also read: times in seconds (the .lab of wavesurfer, Audacity, MFA-style tools) when the first
// timed line has a time with a decimal point, and '#' comment lines.
#include "annotation/Tier.h"

#include <map>
#include <string>

namespace lipsync {

constexpr double kHtkUnitsPerSecond = 1e7;

// Throws lipsync::Error naming the file and line. Untimed lines give intervals with
// start == end == 0 (isTimed = false).
Tier parseHtkLabel(const std::string &text, const std::string &pathForErrors = {}, bool *isTimed = nullptr);
Tier readHtkLabel(const std::string &path, bool *isTimed = nullptr);
std::string formatHtkLabel(const Tier &tier);
void writeHtkLabel(const std::string &path, const Tier &tier);

// Master label file: entry name (the quoted pattern without quotes, e.g. "*/bbaf2n.lab") -> tier.
std::map<std::string, Tier> parseHtkMlf(const std::string &text, const std::string &pathForErrors = {});
std::map<std::string, Tier> readHtkMlf(const std::string &path);
void writeHtkMlf(const std::string &path, const std::map<std::string, Tier> &entries);

} // namespace lipsync
