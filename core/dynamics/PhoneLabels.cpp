#include "dynamics/PhoneLabels.h"

#include "align/FrameLabels.h"
#include "io/AtomicFile.h"
#include "io/HtkLabel.h"
#include "io/TextGrid.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lipsync {

Tier parseTextGridPhones(const std::string &text, const std::string &path)
{
    const TextGrid grid = parseTextGrid(text, path);
    for (const char *name : {"phones", "phone", "phonemes"})
        if (const Tier *tier = grid.tier(name))
            return *tier;
    const Tier *only = nullptr;
    int intervalTiers = 0;
    for (const TextGridTier &t : grid.tiers)
        if (!t.isPointTier) {
            only = &t.tier;
            ++intervalTiers;
        }
    if (intervalTiers == 1)
        return *only;
    throw Error("no interval tier named \"phones\"", path);
}

Tier parseLabPhones(const std::string &text, const std::string &path)
{
    bool timed = false;
    Tier tier = parseHtkLabel(text, path, &timed);
    if (!timed)
        throw Error("expected \"start end phone\" lines (times in seconds or 100 ns units)", path);
    tier.name = "phones";
    return tier;
}

Tier readPhoneTier(const std::string &path)
{
    const std::string text = readWholeFile(path);
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    if (lower.size() >= 9 && lower.compare(lower.size() - 9, 9, ".textgrid") == 0)
        return parseTextGridPhones(text, path);
    return parseLabPhones(text, path);
}

std::vector<int> frameLabelsFromTier(const Tier &phones, double fps, int frameCount,
                                     const std::string &path)
{
    if (!(fps > 0))
        throw Error("frame rate must be positive", path);
    if (frameCount <= 0)
        frameCount = std::max(1, int(std::ceil(phones.endTime() * fps - 1e-9)));
    return frameLabelsFromTier(phones, FrameClock::uniform(fps, frameCount), path);
}

std::vector<int> frameLabelsFromTier(const Tier &phones, const FrameClock &frames, const std::string &path)
{
    if (!(frames.rate() > 0))
        throw Error("frame rate must be positive", path);
    for (const Interval &interval : phones.intervals)
        if (PhoneSet::index(interval.label) < 0) {
            std::ostringstream where;
            where << "phone '" << interval.label << "' at " << interval.start
                  << " s is not in the 41-phone set (ARPAbet, sil, br)";
            throw Error(where.str(), path, phones.name);
        }
    // The one voting rule (align/FrameLabels, docs/models.md §0).
    const std::vector<std::string> names = voteFrameLabels(phones, frames);
    std::vector<int> labels(names.size());
    for (size_t i = 0; i < names.size(); ++i)
        labels[i] = PhoneSet::index(names[i]);
    return labels;
}

std::vector<int> readFrameLabels(const std::string &path, double fps, int frameCount)
{
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    auto endsWith = [&](const std::string &suffix) {
        return lower.size() >= suffix.size()
               && lower.compare(lower.size() - suffix.size(), suffix.size(), suffix) == 0;
    };
    if (endsWith(".textgrid") || endsWith(".lab"))
        return frameLabelsFromTier(readPhoneTier(path), fps, frameCount, path);
    const std::string text = readWholeFile(path);
    std::istringstream in(text);
    std::string line;
    std::vector<int> labels;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        std::string name;
        std::istringstream(line) >> name;
        if (name.empty() || name[0] == '#')
            continue;
        const int index = PhoneSet::index(name);
        if (index < 0)
            throw Error("'" + name + "' is not a phone of the 41-phone set", path,
                        "line " + std::to_string(lineNumber));
        labels.push_back(index);
    }
    if (labels.empty())
        throw Error("no frame labels", path);
    return labels;
}

} // namespace lipsync
