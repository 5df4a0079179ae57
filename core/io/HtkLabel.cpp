#include "io/HtkLabel.h"

#include <charconv>

#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace lipsync {

namespace {

bool isInteger(const std::string &s)
{
    if (s.empty())
        return false;
    for (size_t i = (s[0] == '-' ? 1 : 0); i < s.size(); ++i)
        if (!std::isdigit(static_cast<unsigned char>(s[i])))
            return false;
    return s != "-";
}

// A time in seconds ("0.05", "1.2e-1"): the .lab form of wavesurfer and Audacity exports.
bool isSeconds(const std::string &s)
{
    if (s.find_first_of(".eE") == std::string::npos)
        return false;
    char *end = nullptr;
    std::strtod(s.c_str(), &end);
    return end == s.c_str() + s.size();
}

// One label line into `tier`; `timed` is -1 until the first line decides: 0 untimed, 1 times in
// 100 ns units, 2 times in seconds (a time with a decimal point on the first timed line).
void parseLine(const std::string &line, const std::string &path, int lineNumber, Tier &tier, int &timed)
{
    std::istringstream fields(line);
    std::vector<std::string> f;
    std::string word;
    while (fields >> word)
        f.push_back(word);
    if (f.empty() || f[0][0] == '#') // blank or comment
        return;
    const std::string where = "line " + std::to_string(lineNumber);
    auto isTime = [](const std::string &s) { return isInteger(s) || isSeconds(s); };
    const bool hasTimes = f.size() >= 3 && isTime(f[0]) && isTime(f[1]);
    const bool inSeconds = hasTimes && (isSeconds(f[0]) || isSeconds(f[1]));
    if (timed < 0)
        timed = !hasTimes ? 0 : inSeconds ? 2 : 1;
    if ((timed != 0) != hasTimes)
        throw Error(timed ? "expected 'start end label' (times in 100 ns units, or in seconds)"
                          : "timed label after untimed ones",
                    path, where);
    if (!hasTimes) {
        if (f.size() != 1)
            throw Error("expected 'start end label' or a single label", path, where);
        tier.intervals.push_back(Interval{0, 0, f[0], false});
        return;
    }
    if (timed == 1 && inSeconds)
        throw Error("time in seconds in a file whose times are in 100 ns units", path, where);
    // from_chars, not stoll: a time too large for 64 bits is bad input (an Error naming the line),
    // not std::out_of_range (fuzz regression htklabel-time-out-of-range); likewise a time in
    // seconds that overflows.
    double times[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
        const std::string &text = f[size_t(k)];
        if (timed == 2) {
            times[k] = std::strtod(text.c_str(), nullptr);
            if (!std::isfinite(times[k]))
                throw Error("time '" + text + "' is out of range", path, where);
        } else {
            long long units = 0;
            const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), units);
            if (ec != std::errc() || ptr != text.data() + text.size())
                throw Error("time '" + text + "' is out of range", path, where);
            times[k] = double(units) / kHtkUnitsPerSecond;
        }
    }
    const double start = times[0], end = times[1];
    if (start < 0 || end < start)
        throw Error("interval end is before its start", path, where);
    Interval interval{start, end, f[2], false};
    if (!tier.intervals.empty() && interval.start < tier.intervals.back().end - 1e-9)
        throw Error("interval overlaps the previous one", path, where);
    // Fields after the label (scores, auxiliary labels) are ignored.
    tier.intervals.push_back(interval);
}

} // namespace

Tier parseHtkLabel(const std::string &text, const std::string &path, bool *isTimed)
{
    Tier tier{"labels", {}};
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    int timed = -1;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        if (line.rfind("///", 0) == 0)
            break; // further label levels
        parseLine(line, path, lineNumber, tier, timed);
    }
    if (tier.intervals.empty())
        throw Error("no labels", path);
    if (isTimed)
        *isTimed = timed > 0;
    return tier;
}

Tier readHtkLabel(const std::string &path, bool *isTimed)
{
    return parseHtkLabel(readWholeFile(path), path, isTimed);
}

std::string formatHtkLabel(const Tier &tier)
{
    std::ostringstream out;
    for (const Interval &i : tier.intervals)
        out << std::llround(i.start * kHtkUnitsPerSecond) << ' ' << std::llround(i.end * kHtkUnitsPerSecond)
            << ' ' << (i.label.empty() ? std::string(PhoneSet::kSilenceLabel) : i.label) << '\n';
    return out.str();
}

void writeHtkLabel(const std::string &path, const Tier &tier)
{
    writeFileAtomically(path, formatHtkLabel(tier));
}

std::map<std::string, Tier> parseHtkMlf(const std::string &text, const std::string &path)
{
    std::map<std::string, Tier> entries;
    std::istringstream in(text);
    std::string line;
    int lineNumber = 0;
    bool header = false;
    Tier *current = nullptr;
    int timed = -1;
    int entryLine = 0;
    while (std::getline(in, line)) {
        ++lineNumber;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        const std::string where = "line " + std::to_string(lineNumber);
        if (!header) {
            if (line.find_first_not_of(" \t") == std::string::npos)
                continue;
            if (line.rfind("#!MLF!#", 0) != 0)
                throw Error("not an HTK master label file (expected #!MLF!#)", path, where);
            header = true;
            continue;
        }
        if (!current) {
            if (line.find_first_not_of(" \t") == std::string::npos)
                continue;
            if (line.size() < 2 || line.front() != '"' || line.find('"', 1) == std::string::npos)
                throw Error("expected a quoted file pattern", path, where);
            const std::string name = line.substr(1, line.find('"', 1) - 1);
            if (entries.count(name))
                throw Error("duplicate entry \"" + name + "\"", path, where);
            current = &entries[name];
            current->name = "labels";
            timed = -1;
            entryLine = lineNumber;
            continue;
        }
        if (line == ".") {
            if (current->intervals.empty())
                throw Error("entry has no labels", path, "line " + std::to_string(entryLine));
            current = nullptr;
            continue;
        }
        parseLine(line, path, lineNumber, *current, timed);
    }
    if (!header)
        throw Error("empty file, not an HTK master label file", path);
    if (current)
        throw Error("last entry is not terminated by '.'", path, "line " + std::to_string(entryLine));
    return entries;
}

std::map<std::string, Tier> readHtkMlf(const std::string &path)
{
    return parseHtkMlf(readWholeFile(path), path);
}

void writeHtkMlf(const std::string &path, const std::map<std::string, Tier> &entries)
{
    std::string out = "#!MLF!#\n";
    for (const auto &[name, tier] : entries)
        out += "\"" + name + "\"\n" + formatHtkLabel(tier) + ".\n";
    writeFileAtomically(path, out);
}

} // namespace lipsync
