#pragma once
// Praat TextGrid files (https://www.fon.hum.uva.nl/praat/manual/TextGrid_file_formats.html):
// the long ("ooTextFile" with "xmin = ..." lines) and short (values only) text forms, read in
// UTF-8 or UTF-16 (with a byte-order mark) and written in UTF-8. Interval tiers map to Tier;
// point tiers (TextTier) are kept with start == end per point.
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

struct TextGridTier
{
    Tier tier;
    bool isPointTier = false;
    bool operator==(const TextGridTier &) const = default;
};

struct TextGrid
{
    double xmin = 0.0;
    double xmax = 0.0;
    std::vector<TextGridTier> tiers;

    // The interval tier named `name` (case-insensitive), or nullptr.
    const Tier *tier(const std::string &name) const &;
    // The pointer points into the grid: asking a temporary grid would dangle (as in
    // `for (x : readTextGrid(f).tier("words")->intervals)`), so that does not compile.
    const Tier *tier(const std::string &name) const && = delete;
    bool operator==(const TextGrid &) const = default;
};

enum class TextGridForm { Long, Short };

// Throws lipsync::Error naming the file and line.
TextGrid readTextGrid(const std::string &path);
TextGrid parseTextGrid(const std::string &bytes, const std::string &pathForErrors = {});
// Interval tiers are written gap-free: gaps become empty intervals, and xmin/xmax of the grid
// cover every tier. Throws lipsync::Error naming the file (overlapping intervals, I/O).
std::string formatTextGrid(const TextGrid &grid, TextGridForm form = TextGridForm::Long);
void writeTextGrid(const std::string &path, const TextGrid &grid, TextGridForm form = TextGridForm::Long);
// A grid holding interval tiers (e.g. "words" and "phones") over [0, duration].
TextGrid makeTextGrid(const std::vector<Tier> &tiers, double duration = 0.0);

} // namespace lipsync
