#include "io/Subtitles.h"

#include "util/Error.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <sstream>

namespace lipsync {

namespace {

std::vector<std::string> splitLines(const std::string &bytes)
{
    std::vector<std::string> lines;
    std::string line;
    std::istringstream in(bytes);
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        lines.push_back(line);
    }
    if (!lines.empty() && lines.front().rfind("\xEF\xBB\xBF", 0) == 0)
        lines.front().erase(0, 3);
    return lines;
}

bool blank(const std::string &line)
{
    return std::all_of(line.begin(), line.end(), [](unsigned char c) { return std::isspace(c); });
}

bool digits(const std::string &s, size_t most)
{
    return !s.empty() && s.size() <= most
           && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

// "[HH:]MM:SS[,.]mmm" -> seconds, or a negative value if it is not one.
double timestamp(std::string s)
{
    const size_t first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
    if (first == std::string::npos)
        return -1.0;
    s = s.substr(first, last - first + 1);
    const size_t fraction = s.find_last_of(",.");
    if (fraction == std::string::npos)
        return -1.0;
    const std::string ms = s.substr(fraction + 1);
    std::vector<std::string> fields;
    std::istringstream clock(s.substr(0, fraction));
    for (std::string field; std::getline(clock, field, ':');)
        fields.push_back(field);
    if (fields.size() < 2 || fields.size() > 3 || !digits(ms, 3) || !digits(fields.back(), 2)
        || !digits(fields[fields.size() - 2], 2) || (fields.size() == 3 && !digits(fields[0], 6)))
        return -1.0;
    const double hours = fields.size() == 3 ? std::stod(fields[0]) : 0.0;
    const double minutes = std::stod(fields[fields.size() - 2]), seconds = std::stod(fields.back());
    if (minutes >= 60 || seconds >= 60)
        return -1.0;
    return hours * 3600.0 + minutes * 60.0 + seconds + std::stod(ms) / std::pow(10.0, double(ms.size()));
}

// A time line "A --> B [settings]": true with the two times, false if the line has no "-->".
bool timeLine(const std::string &line, double &start, double &end, const std::string &path, int lineNumber)
{
    const size_t arrow = line.find("-->");
    if (arrow == std::string::npos)
        return false;
    std::string after = line.substr(arrow + 3);
    const size_t first = after.find_first_not_of(" \t");
    after = first == std::string::npos ? std::string() : after.substr(first);
    const size_t space = after.find_first_of(" \t");
    start = timestamp(line.substr(0, arrow));
    end = timestamp(after.substr(0, space));
    const std::string where = "line " + std::to_string(lineNumber);
    if (start < 0.0 || end < 0.0)
        throw Error("not a cue time line ('" + line + "')", path, where);
    if (end < start)
        throw Error("the cue ends before it starts", path, where);
    return true;
}

std::string replaceAll(std::string s, const std::string &from, const std::string &to)
{
    for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
        s.replace(at, from.size(), to);
    return s;
}

} // namespace

std::string subtitleSpeech(const std::string &cueText)
{
    static const std::string note = "\u266A", notes = "\u266B"; // ♪ ♫
    std::string s;
    for (size_t i = 0; i < cueText.size(); ++i) {
        const char c = cueText[i];
        // Markup and what is not speech, each up to its closing character (on this line).
        const char close = c == '<' ? '>' : c == '{' ? '}' : c == '[' ? ']' : c == '(' ? ')' : '\0';
        if (close != '\0') {
            const size_t end = cueText.find(close, i + 1);
            if (end != std::string::npos) {
                s += ' ';
                i = end;
                continue;
            }
        }
        if (cueText.compare(i, note.size(), note) == 0 || cueText.compare(i, notes.size(), notes) == 0) {
            // Sung: from one note to the next, or the note alone.
            const size_t end = cueText.find(note, i + note.size());
            s += ' ';
            i = (end == std::string::npos ? i : end) + note.size() - 1;
            continue;
        }
        s += c;
    }
    for (const auto &[entity, text] : std::vector<std::pair<std::string, std::string>>{
             {"&nbsp;", " "}, {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&apos;", "'"}, {"&amp;", "&"}})
        s = replaceAll(s, entity, text);
    std::istringstream in(s);
    std::string word, out;
    while (in >> word) {
        if (word == "-" || word == "--" || word == "\u2013" || word == "\u2014")
            continue; // a dialogue dash
        if (word.front() == '-' && word.size() > 1 && out.empty())
            word.erase(0, 1);
        out += (out.empty() ? "" : " ") + word;
    }
    return out;
}

Tier parseSubtitles(const std::string &bytes, SubtitleFormat format, const std::string &path)
{
    const bool vtt = format == SubtitleFormat::WebVtt;
    const std::vector<std::string> lines = splitLines(bytes);
    size_t i = 0;
    if (vtt) {
        if (lines.empty() || lines.front().rfind("WEBVTT", 0) != 0)
            throw Error("a WebVTT file starts with WEBVTT", path, "line 1");
        while (i < lines.size() && !blank(lines[i]))
            ++i; // the header
    }
    Tier tier{"cues", {}};
    while (i < lines.size()) {
        while (i < lines.size() && blank(lines[i]))
            ++i;
        if (i >= lines.size())
            break;
        // One block: up to the next blank line.
        size_t end = i;
        while (end < lines.size() && !blank(lines[end]))
            ++end;
        const std::string &head = lines[i];
        if (vtt && (head.rfind("NOTE", 0) == 0 || head.rfind("STYLE", 0) == 0 || head.rfind("REGION", 0) == 0)) {
            i = end;
            continue;
        }
        // The time line is the first or (after a number or identifier) the second.
        double start = 0.0, stop = 0.0;
        size_t text = i;
        if (timeLine(lines[i], start, stop, path, int(i) + 1))
            text = i + 1;
        else if (i + 1 < end && timeLine(lines[i + 1], start, stop, path, int(i) + 2))
            text = i + 2;
        else
            throw Error("a cue without a time line ('" + head + "')", path, "line " + std::to_string(i + 1));
        std::string words;
        for (size_t k = text; k < end; ++k) {
            const std::string speech = subtitleSpeech(lines[k]);
            if (!speech.empty())
                words += (words.empty() ? "" : " ") + speech;
        }
        if (!words.empty())
            tier.intervals.push_back({start, stop, words, false});
        i = end;
    }
    std::stable_sort(tier.intervals.begin(), tier.intervals.end(),
                     [](const Interval &a, const Interval &b) { return a.start < b.start; });
    return tier;
}

} // namespace lipsync
