#include "io/FeatureCsv.h"

#include "io/AtomicFile.h"
#include "util/Error.h"

#include <charconv>
#include <cmath>
#include <limits>

namespace lipsync {

namespace {

std::vector<std::string_view> splitFields(std::string_view line)
{
    std::vector<std::string_view> fields;
    size_t start = 0;
    while (true) {
        const size_t comma = line.find(',', start);
        fields.push_back(line.substr(start, comma == std::string_view::npos ? comma : comma - start));
        if (comma == std::string_view::npos)
            break;
        start = comma + 1;
    }
    for (auto &f : fields) {
        while (!f.empty() && (f.front() == ' ' || f.front() == '\t'))
            f.remove_prefix(1);
        while (!f.empty() && (f.back() == ' ' || f.back() == '\t' || f.back() == '\r'))
            f.remove_suffix(1);
    }
    return fields;
}

bool parseDouble(std::string_view text, double &value)
{
    if (text.empty())
        return false;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    return ec == std::errc() && ptr == text.data() + text.size();
}

constexpr std::string_view kFpsKey = "# fps=";

// The text of a '#' comment line after the '#': "fps=RATE" records the frame rate, anything else
// is free text.
void parseComment(std::string_view comment, double &frameRate, const std::string &path,
                  const std::string &where)
{
    while (!comment.empty() && (comment.front() == ' ' || comment.front() == '\t'))
        comment.remove_prefix(1);
    while (!comment.empty() && (comment.back() == ' ' || comment.back() == '\t' || comment.back() == '\r'))
        comment.remove_suffix(1);
    const std::string_view key = kFpsKey.substr(2);
    if (comment.substr(0, key.size()) != key)
        return;
    const std::string_view text = comment.substr(key.size());
    double rate = 0;
    if (!parseDouble(text, rate) || !(rate > 0 && std::isfinite(rate)))
        throw Error("frame rate '" + std::string(text) + "' is not a positive number", path, where);
    if (frameRate > 0)
        throw Error("a second fps comment", path, where);
    frameRate = rate;
}

} // namespace

FeatureTable readFeatureCsv(const std::string &path)
{
    return parseFeatureCsv(readWholeFile(path), path);
}

FeatureTable parseFeatureCsv(const std::string &text, const std::string &path)
{
    std::vector<std::vector<double>> rows;
    std::vector<int> frames;
    size_t columns = 0;
    int lineNumber = 0;
    bool headerAllowed = true; // the first line that is neither blank nor a comment may be a header
    double frameRate = 0.0;
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos)
            end = text.size();
        const std::string_view line(text.data() + pos, end - pos);
        pos = end + 1;
        ++lineNumber;
        const size_t start = line.find_first_not_of(" \t\r");
        if (start == std::string_view::npos)
            continue;
        const std::string where = "line " + std::to_string(lineNumber);
        if (line[start] == '#') {
            parseComment(line.substr(start + 1), frameRate, path, where);
            continue;
        }
        const auto fields = splitFields(line);
        double first = 0;
        const bool header = headerAllowed;
        headerAllowed = false;
        if (!parseDouble(fields[0], first)) {
            if (header)
                continue;
            throw Error("frame index '" + std::string(fields[0]) + "' is not a number", path, where);
        }
        // A frame index is a whole number in int range: converting anything else to int is undefined
        // behaviour (fuzz regression featurecsv-frame-index-overflow).
        if (!(first >= 0 && first <= double(std::numeric_limits<int>::max()) && first == std::floor(first)))
            throw Error("frame index '" + std::string(fields[0]) + "' is not a whole number from 0 to "
                            + std::to_string(std::numeric_limits<int>::max()), path, where);
        if (fields.size() < 2)
            throw Error("expected a frame index and at least one parameter", path, where);
        if (columns == 0)
            columns = fields.size();
        else if (fields.size() != columns)
            throw Error("has " + std::to_string(fields.size()) + " fields, expected "
                            + std::to_string(columns), path, where);
        std::vector<double> row(fields.size() - 1);
        for (size_t i = 1; i < fields.size(); ++i) {
            if (!parseDouble(fields[i], row[i - 1]))
                throw Error("field " + std::to_string(i + 1) + " '" + std::string(fields[i])
                                + "' is not a number", path, where);
            if (!std::isfinite(row[i - 1]))
                throw Error("field " + std::to_string(i + 1) + " is not finite (NaN or inf)", path,
                            where);
        }
        frames.push_back(int(first));
        rows.push_back(std::move(row));
    }
    if (rows.empty())
        throw Error("no feature rows", path);
    FeatureTable table;
    table.frames = std::move(frames);
    table.frameRate = frameRate;
    table.values.resize(Eigen::Index(rows.size()), Eigen::Index(columns - 1));
    for (size_t r = 0; r < rows.size(); ++r)
        for (size_t c = 0; c + 1 < columns; ++c)
            table.values(Eigen::Index(r), Eigen::Index(c)) = rows[r][c];
    return table;
}

std::string formatFeatureCsv(const Eigen::MatrixXd &values, const std::vector<int> &frames, double frameRate,
                             const std::string &pathForErrors)
{
    if (!frames.empty() && frames.size() != size_t(values.rows()))
        throw Error("frame list and feature rows differ in length", pathForErrors);
    if (frameRate != 0.0 && !(frameRate > 0.0 && std::isfinite(frameRate)))
        throw Error("frame rate " + std::to_string(frameRate) + " is not a positive number", pathForErrors);
    std::string out;
    // A row: the frame index and d values of at most 24 characters each.
    out.reserve(size_t(values.rows()) * (12 + 25 * size_t(values.cols())) + 16 + 8 * size_t(values.cols()));
    char number[32];
    const auto append = [&](auto value) {
        const auto [end, ec] = std::to_chars(number, number + sizeof number, value);
        out.append(number, end);
    };
    if (frameRate > 0.0) {
        out += kFpsKey;
        append(frameRate);
        out += '\n';
    }
    out += "frame";
    for (Eigen::Index c = 0; c < values.cols(); ++c) {
        out += ",p";
        append(c);
    }
    out += '\n';
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
        append(frames.empty() ? int(r) : frames[size_t(r)]);
        for (Eigen::Index c = 0; c < values.cols(); ++c) {
            out += ',';
            append(values(r, c));
        }
        out += '\n';
    }
    return out;
}

void writeFeatureCsv(const std::string &path, const Eigen::MatrixXd &values,
                     const std::vector<int> &frames, double frameRate)
{
    writeFileAtomically(path, formatFeatureCsv(values, frames, frameRate, path));
}

} // namespace lipsync
