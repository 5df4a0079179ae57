#include "dynamics/PhoneLabels.h"

#include "util/PhoneSet.h"
#include "io/AtomicFile.h"
#include "util/Error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

namespace lipsync {

namespace {

struct Token
{
    bool isString = false;
    std::string text;
    double number = 0.0;
};

bool parseNumber(std::string_view s, double &value)
{
    if (s.empty())
        return false;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    return ec == std::errc() && ptr == s.data() + s.size();
}

// Praat's text formats are a stream of numbers and quoted strings; everything else ("xmin =",
// "item [1]:", "<exists>") is decoration. Reading only those tokens handles long and short form.
std::vector<Token> tokenize(const std::string &text, const std::string &path)
{
    std::vector<Token> tokens;
    size_t i = 0;
    if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
        i = 3;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '"') {
            std::string s;
            ++i;
            while (true) {
                if (i >= text.size())
                    throw Error("unterminated string", path);
                if (text[i] == '"') {
                    if (i + 1 < text.size() && text[i + 1] == '"') {
                        s += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                s += text[i++];
            }
            tokens.push_back({true, s, 0.0});
        } else if (c == '!') { // comment to end of line
            while (i < text.size() && text[i] != '\n')
                ++i;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else {
            const size_t start = i;
            while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i])) && text[i] != '"')
                ++i;
            double value;
            if (parseNumber(std::string_view(text).substr(start, i - start), value))
                tokens.push_back({false, {}, value});
        }
    }
    return tokens;
}

} // namespace

Tier parseTextGridPhones(const std::string &text, const std::string &path)
{
    const std::vector<Token> tokens = tokenize(text, path);
    size_t i = 0;
    auto need = [&](bool string, const char *what) -> const Token & {
        if (i >= tokens.size() || tokens[i].isString != string)
            throw Error(std::string("malformed TextGrid: expected ") + what, path);
        return tokens[i++];
    };
    if (need(true, "\"ooTextFile\"").text != "ooTextFile" || need(true, "\"TextGrid\"").text != "TextGrid")
        throw Error("not a TextGrid text file", path);
    need(false, "xmin");
    need(false, "xmax");
    const int tierCount = int(need(false, "tier count").number);
    std::vector<Tier> tiers;
    for (int tier = 0; tier < tierCount; ++tier) {
        const std::string cls = need(true, "tier class").text;
        Tier t;
        t.name = need(true, "tier name").text;
        need(false, "tier xmin");
        need(false, "tier xmax");
        const int count = int(need(false, "interval count").number);
        for (int k = 0; k < count; ++k) {
            Interval interval;
            interval.start = need(false, "interval xmin").number;
            if (cls == "IntervalTier")
                interval.end = need(false, "interval xmax").number;
            else
                interval.end = interval.start; // TextTier point
            interval.label = need(true, "interval text").text;
            t.intervals.push_back(interval);
        }
        if (cls == "IntervalTier")
            tiers.push_back(std::move(t));
    }
    for (const Tier &t : tiers) {
        std::string lower = t.name;
        std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
        if (lower == "phones" || lower == "phone" || lower == "phonemes")
            return t;
    }
    if (tiers.size() == 1)
        return tiers.front();
    throw Error("no interval tier named \"phones\"", path);
}

Tier parseLabPhones(const std::string &text, const std::string &path)
{
    Tier tier{"phones", {}};
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        const size_t first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] == '#')
            continue;
        std::istringstream fields(line);
        std::string start, end, label;
        fields >> start >> end >> label;
        Interval interval;
        if (!parseNumber(start, interval.start) || !parseNumber(end, interval.end) || label.empty()
            || !(interval.end >= interval.start))
            throw Error("expected \"start end phone\" with times in seconds", path,
                        "line " + std::to_string(lineNumber));
        interval.label = label;
        tier.intervals.push_back(interval);
    }
    if (tier.intervals.empty())
        throw Error("no phone segments", path);
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
    std::vector<int> intervalLabels;
    for (const Interval &interval : phones.intervals) {
        const int index = PhoneSet::index(interval.label);
        if (index < 0) {
            std::ostringstream where;
            where << "phone '" << interval.label << "' at " << interval.start
                  << " s is not in the 41-phone set (ARPAbet, sil, br)";
            throw Error(where.str(), path, phones.name);
        }
        intervalLabels.push_back(index);
    }
    if (frameCount <= 0)
        frameCount = std::max(1, int(std::ceil(phones.endTime() * fps - 1e-9)));
    auto labelAt = [&](double time) {
        for (size_t k = 0; k < phones.intervals.size(); ++k)
            if (time >= phones.intervals[k].start && time < phones.intervals[k].end)
                return intervalLabels[k];
        return int(PhoneSet::kSilence);
    };
    constexpr double hop = 0.01, halfWindow = 0.0125; // HTK defaults, §0 [choice]
    std::vector<int> labels(static_cast<size_t>(frameCount));
    for (int i = 0; i < frameCount; ++i) {
        const double begin = i / fps, end = (i + 1) / fps, centre = (i + 0.5) / fps;
        // Audio frames j with centre c_j = 0.01 j + 0.0125 in [begin, end).
        long j = std::max(0L, long(std::ceil((begin - halfWindow) / hop - 1e-9)));
        std::map<int, int> votes;
        std::vector<std::pair<double, int>> members; // (distance to centre, label)
        for (;; ++j) {
            const double c = hop * double(j) + halfWindow;
            if (c >= end)
                break;
            if (c < begin)
                continue;
            const int label = labelAt(c);
            ++votes[label];
            members.emplace_back(std::abs(c - centre), label);
        }
        if (votes.empty()) {
            labels[size_t(i)] = labelAt(centre);
            continue;
        }
        int best = 0;
        for (const auto &[label, count] : votes)
            best = std::max(best, count);
        double nearest = INFINITY;
        for (const auto &[distance, label] : members)
            if (votes[label] == best && distance < nearest) {
                nearest = distance;
                labels[size_t(i)] = label;
            }
    }
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
