#include "io/TextGrid.h"

#include "io/AtomicFile.h"
#include "util/Error.h"

#include <QString>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace lipsync {

namespace {

// Praat's text reader ignores everything that is not a number, a quoted string or a
// <flag>; the long form's labels ("xmin =", "intervals [3]:") are skipped the same way.
struct Token
{
    enum Kind { Number, String, Flag } kind;
    std::string text;
    double value = 0;
    int line = 0;
};

std::string toUtf8(const std::string &bytes)
{
    auto u = [&](size_t i) { return static_cast<unsigned char>(bytes[i]); };
    if (bytes.size() >= 2 && ((u(0) == 0xFE && u(1) == 0xFF) || (u(0) == 0xFF && u(1) == 0xFE))) {
        const bool big = u(0) == 0xFE;
        std::u16string text;
        for (size_t i = 2; i + 1 < bytes.size(); i += 2)
            text += char16_t(big ? (u(i) << 8 | u(i + 1)) : (u(i + 1) << 8 | u(i)));
        return QString::fromStdU16String(text).toStdString();
    }
    if (bytes.size() >= 3 && u(0) == 0xEF && u(1) == 0xBB && u(2) == 0xBF)
        return bytes.substr(3);
    return bytes;
}

std::vector<Token> tokenize(const std::string &text, const std::string &path)
{
    std::vector<Token> tokens;
    int line = 1;
    size_t i = 0;
    const size_t n = text.size();
    while (i < n) {
        const char c = text[i];
        if (c == '\n') {
            ++line;
            ++i;
        } else if (c == '"') {
            // Quoted string; "" inside is one quote. Strings may span lines.
            const int startLine = line;
            std::string value;
            ++i;
            for (;;) {
                if (i >= n)
                    throw Error("unterminated string", path, "line " + std::to_string(startLine));
                if (text[i] == '"') {
                    if (i + 1 < n && text[i + 1] == '"') {
                        value += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                if (text[i] == '\n')
                    ++line;
                value += text[i++];
            }
            tokens.push_back({Token::String, value, 0, startLine});
        } else if (c == '!') {
            while (i < n && text[i] != '\n')
                ++i; // comment
        } else if (c == '[') {
            while (i < n && text[i] != ']' && text[i] != '\n')
                ++i; // "item [1]:" indices
        } else if (c == '<') {
            const size_t close = text.find('>', i);
            if (close == std::string::npos)
                throw Error("unterminated <flag>", path, "line " + std::to_string(line));
            tokens.push_back({Token::Flag, text.substr(i + 1, close - i - 1), 0, line});
            i = close + 1;
        } else if (std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.') {
            size_t j = i;
            while (j < n && !std::isspace(static_cast<unsigned char>(text[j])))
                ++j;
            const std::string word = text.substr(i, j - i);
            double value = 0;
            const char *begin = word.c_str() + (word[0] == '+' ? 1 : 0);
            auto [end, ec] = std::from_chars(begin, word.c_str() + word.size(), value);
            if (ec != std::errc() || end != word.c_str() + word.size())
                throw Error("bad number '" + word + "'", path, "line " + std::to_string(line));
            tokens.push_back({Token::Number, word, value, line});
            i = j;
        } else if (std::isalpha(static_cast<unsigned char>(c))) {
            while (i < n && (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_' || text[i] == '?'))
                ++i; // a label such as xmin, intervals, tiers?
        } else {
            ++i;
        }
    }
    return tokens;
}

class Reader
{
public:
    Reader(std::vector<Token> tokens, std::string path) : m_tokens(std::move(tokens)), m_path(std::move(path)) {}

    const Token &next(const char *what)
    {
        if (m_pos >= m_tokens.size())
            throw Error(std::string("unexpected end of file, expected ") + what, m_path,
                        "line " + std::to_string(m_tokens.empty() ? 1 : m_tokens.back().line));
        return m_tokens[m_pos++];
    }
    double number(const char *what)
    {
        const Token &t = next(what);
        if (t.kind != Token::Number)
            throw Error(std::string("expected ") + what, m_path, "line " + std::to_string(t.line));
        if (!std::isfinite(t.value))
            throw Error(std::string("non-finite ") + what, m_path, "line " + std::to_string(t.line));
        return t.value;
    }
    std::string string(const char *what)
    {
        const Token &t = next(what);
        if (t.kind != Token::String)
            throw Error(std::string("expected ") + what + " (a quoted string)", m_path, "line " + std::to_string(t.line));
        return t.text;
    }
    int count(const char *what)
    {
        const int line = m_pos < m_tokens.size() ? m_tokens[m_pos].line : 0;
        const double v = number(what);
        if (v < 0 || v != std::floor(v) || v > 1e8)
            throw Error(std::string("bad ") + what, m_path, "line " + std::to_string(line));
        return int(v);
    }
    bool atFlag()
    {
        return m_pos < m_tokens.size() && m_tokens[m_pos].kind == Token::Flag;
    }
    int line() const { return m_pos < m_tokens.size() ? m_tokens[m_pos].line : (m_tokens.empty() ? 1 : m_tokens.back().line); }
    const std::string &path() const { return m_path; }
    bool atEnd() const { return m_pos >= m_tokens.size(); }

private:
    std::vector<Token> m_tokens;
    size_t m_pos = 0;
    std::string m_path;
};

std::string quote(const std::string &s)
{
    std::string out = "\"";
    for (char c : s) {
        if (c == '"')
            out += '"';
        out += c;
    }
    return out + '"';
}

std::string num(double v)
{
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    // Shortest representation that round-trips.
    for (int precision = 6; precision < 17; ++precision) {
        char shorter[40];
        std::snprintf(shorter, sizeof shorter, "%.*g", precision, v);
        if (std::strtod(shorter, nullptr) == v)
            return shorter;
    }
    return buffer;
}

} // namespace

const Tier *TextGrid::tier(const std::string &name) const &
{
    auto lower = [](std::string s) {
        for (char &c : s)
            c = char(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    for (const TextGridTier &t : tiers)
        if (!t.isPointTier && lower(t.tier.name) == lower(name))
            return &t.tier;
    return nullptr;
}

TextGrid parseTextGrid(const std::string &bytes, const std::string &path)
{
    Reader r(tokenize(toUtf8(bytes), path), path);
    if (r.atEnd())
        throw Error("empty file, not a TextGrid", path);
    const std::string fileType = r.string("File type");
    const std::string objectClass = r.string("Object class");
    if (fileType != "ooTextFile" || objectClass != "TextGrid")
        throw Error("not a Praat TextGrid text file (File type = \"ooTextFile\", Object class = \"TextGrid\")",
                    path, "line 1");
    TextGrid grid;
    grid.xmin = r.number("xmin");
    grid.xmax = r.number("xmax");
    int tierCount = 0;
    if (r.atFlag()) {
        const Token &flag = r.next("<exists>");
        if (flag.text == "exists")
            tierCount = r.count("tier count");
    }
    for (int k = 0; k < tierCount; ++k) {
        const int tierLine = r.line();
        TextGridTier t;
        const std::string kind = r.string("tier class");
        t.tier.name = r.string("tier name");
        r.number("tier xmin");
        r.number("tier xmax");
        const int n = r.count("interval count");
        if (kind == "IntervalTier") {
            for (int i = 0; i < n; ++i) {
                const int line = r.line();
                Interval in;
                in.start = r.number("interval xmin");
                in.end = r.number("interval xmax");
                in.label = r.string("interval text");
                if (in.end < in.start)
                    throw Error("interval ends before it starts", path, "line " + std::to_string(line));
                if (!t.tier.intervals.empty() && in.start < t.tier.intervals.back().end - 1e-9)
                    throw Error("interval overlaps the previous one", path, "line " + std::to_string(line));
                t.tier.intervals.push_back(in);
            }
        } else if (kind == "TextTier") {
            t.isPointTier = true;
            for (int i = 0; i < n; ++i) {
                Interval in;
                in.start = in.end = r.number("point time");
                in.label = r.string("point mark");
                t.tier.intervals.push_back(in);
            }
        } else {
            throw Error("unknown tier class '" + kind + "'", path, "line " + std::to_string(tierLine));
        }
        grid.tiers.push_back(std::move(t));
    }
    return grid;
}

TextGrid readTextGrid(const std::string &path)
{
    return parseTextGrid(readWholeFile(path), path);
}

TextGrid makeTextGrid(const std::vector<Tier> &tiers, double duration)
{
    TextGrid grid;
    grid.xmax = duration;
    for (const Tier &t : tiers) {
        grid.tiers.push_back(TextGridTier{t, false});
        grid.xmax = std::max(grid.xmax, t.endTime());
    }
    return grid;
}

std::string formatTextGrid(const TextGrid &grid, TextGridForm form)
{
    double xmin = grid.xmin, xmax = grid.xmax;
    for (const TextGridTier &t : grid.tiers)
        if (!t.tier.intervals.empty()) {
            xmin = std::min(xmin, t.tier.intervals.front().start);
            xmax = std::max(xmax, t.tier.intervals.back().end);
        }
    const bool longForm = form == TextGridForm::Long;
    std::string out = "File type = \"ooTextFile\"\nObject class = \"TextGrid\"\n\n";
    auto field = [&](const std::string &indent, const std::string &name, const std::string &value) {
        out += longForm ? indent + name + " = " + value + " \n" : value + "\n";
    };
    field("", "xmin", num(xmin));
    field("", "xmax", num(xmax));
    out += longForm ? "tiers? <exists> \n" : "<exists>\n";
    field("", "size", std::to_string(grid.tiers.size()));
    if (longForm)
        out += "item []: \n";
    for (size_t k = 0; k < grid.tiers.size(); ++k) {
        const TextGridTier &t = grid.tiers[k];
        // Interval tiers must tile [xmin, xmax]: fill gaps with empty intervals.
        std::vector<Interval> items;
        if (t.isPointTier) {
            items = t.tier.intervals;
        } else {
            double cursor = xmin;
            for (const Interval &i : t.tier.intervals) {
                if (i.start < cursor - 1e-9)
                    throw Error("tier '" + t.tier.name + "' has overlapping intervals at " + num(i.start) + " s");
                if (i.start > cursor + 1e-9)
                    items.push_back(Interval{cursor, i.start, "", false});
                items.push_back(i);
                items.back().start = std::max(i.start, cursor);
                cursor = i.end;
            }
            if (cursor < xmax - 1e-9 || items.empty())
                items.push_back(Interval{cursor, xmax, "", false});
        }
        if (longForm)
            out += "    item [" + std::to_string(k + 1) + "]:\n";
        field("        ", "class", quote(t.isPointTier ? "TextTier" : "IntervalTier"));
        field("        ", "name", quote(t.tier.name));
        field("        ", "xmin", num(xmin));
        field("        ", "xmax", num(xmax));
        field("        ", t.isPointTier ? "points: size" : "intervals: size", std::to_string(items.size()));
        for (size_t i = 0; i < items.size(); ++i) {
            if (longForm)
                out += std::string("        ") + (t.isPointTier ? "points [" : "intervals [") + std::to_string(i + 1) + "]:\n";
            if (t.isPointTier) {
                field("            ", "number", num(items[i].start));
                field("            ", "mark", quote(items[i].label));
            } else {
                field("            ", "xmin", num(items[i].start));
                field("            ", "xmax", num(items[i].end));
                field("            ", "text", quote(items[i].label));
            }
        }
    }
    return out;
}

void writeTextGrid(const std::string &path, const TextGrid &grid, TextGridForm form)
{
    std::string text;
    try {
        text = formatTextGrid(grid, form);
    } catch (const Error &e) {
        throw Error(e.reason(), path);
    }
    writeFileAtomically(path, text);
}

} // namespace lipsync
