#include "io/GridAlign.h"

#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <cmath>
#include <sstream>

namespace lipsync {

Tier parseGridAlign(const std::string &text, const std::string &path)
{
    Tier tier{"words", {}};
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos)
            continue;
        std::istringstream fields(line);
        long long start = 0, end = 0;
        std::string word, extra;
        const std::string where = "line " + std::to_string(lineNumber);
        if (!(fields >> start >> end >> word))
            throw Error("expected 'start end word'", path, where);
        if (fields >> extra)
            throw Error("unexpected text after the word", path, where);
        if (start < 0 || end < start)
            throw Error("interval end is before its start", path, where);
        Interval interval{start / kGridAlignUnitsPerSecond, end / kGridAlignUnitsPerSecond, word, false};
        if (!tier.intervals.empty() && interval.start < tier.intervals.back().end - 1e-9)
            throw Error("interval overlaps the previous one", path, where);
        tier.intervals.push_back(interval);
    }
    if (tier.intervals.empty())
        throw Error("no intervals", path);
    return tier;
}

Tier readGridAlign(const std::string &path)
{
    return parseGridAlign(readWholeFile(path), path);
}

void writeGridAlign(const std::string &path, const Tier &words)
{
    std::ostringstream out;
    for (const Interval &i : words.intervals)
        out << std::llround(i.start * kGridAlignUnitsPerSecond) << ' '
            << std::llround(i.end * kGridAlignUnitsPerSecond) << ' ' << i.label << '\n';
    writeFileAtomically(path, out.str());
}

std::string transcriptFromTier(const Tier &words)
{
    std::string text;
    for (const Interval &i : words.intervals) {
        if (PhoneSet::isSilence(i.label))
            continue;
        if (!text.empty())
            text += ' ';
        text += i.label;
    }
    return text;
}

} // namespace lipsync
