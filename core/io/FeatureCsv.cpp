#include "io/FeatureCsv.h"

#include "io/AtomicFile.h"
#include "util/Error.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

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
    size_t pos = 0;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string::npos)
            end = text.size();
        const std::string_view line(text.data() + pos, end - pos);
        pos = end + 1;
        ++lineNumber;
        if (line.find_first_not_of(" \t\r") == std::string_view::npos)
            continue;
        const auto fields = splitFields(line);
        const std::string where = "line " + std::to_string(lineNumber);
        double first = 0;
        if (!parseDouble(fields[0], first)) {
            if (rows.empty() && frames.empty() && lineNumber == 1)
                continue; // header
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
    table.values.resize(Eigen::Index(rows.size()), Eigen::Index(columns - 1));
    for (size_t r = 0; r < rows.size(); ++r)
        for (size_t c = 0; c + 1 < columns; ++c)
            table.values(Eigen::Index(r), Eigen::Index(c)) = rows[r][c];
    return table;
}

void writeFeatureCsv(const std::string &path, const Eigen::MatrixXd &values,
                     const std::vector<int> &frames)
{
    if (!frames.empty() && frames.size() != size_t(values.rows()))
        throw Error("frame list and feature rows differ in length", path);
    std::ostringstream out;
    out.precision(17);
    out << "frame";
    for (Eigen::Index c = 0; c < values.cols(); ++c)
        out << ",p" << c;
    out << '\n';
    for (Eigen::Index r = 0; r < values.rows(); ++r) {
        out << (frames.empty() ? int(r) : frames[size_t(r)]);
        for (Eigen::Index c = 0; c < values.cols(); ++c)
            out << ',' << values(r, c);
        out << '\n';
    }
    writeFileAtomically(path, out.str());
}

} // namespace lipsync
