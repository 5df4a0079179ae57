#include "aam/PtsFile.h"

#include "aam/LandmarkScheme.h"
#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/NumberText.h"

#include <cmath>
#include <optional>
#include <cstdio>
#include <sstream>
#include <vector>

namespace lipsync {

namespace {

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front())))
        s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back())))
        s.remove_suffix(1);
    return s;
}

std::string lineField(int line)
{
    return "line " + std::to_string(line);
}

} // namespace

Eigen::VectorXd parsePts(const std::string &text, const std::string &path)
{
    std::istringstream in(text);
    std::string raw;
    int lineNo = 0;
    int declared = -1;
    bool inBraces = false;
    bool closed = false;
    std::vector<double> values;
    while (std::getline(in, raw)) {
        ++lineNo;
        std::string_view line = trimmed(raw);
        if (line.empty())
            continue;
        if (line.starts_with("version:"))
            continue;
        if (line.starts_with("n_points:")) {
            std::string_view count = trimmed(line.substr(9));
            const std::optional<double> n = parseFiniteNumber(count);
            // Bounded before the cast: int(1e300) is undefined behaviour.
            if (!n || *n < 0 || *n != std::floor(*n) || *n > 1e6)
                throw Error("bad n_points '" + std::string(count) + "'", path, lineField(lineNo));
            declared = int(*n);
            continue;
        }
        if (line == "{") {
            inBraces = true;
            continue;
        }
        if (line == "}") {
            if (!inBraces)
                throw Error("'}' without '{'", path, lineField(lineNo));
            closed = true;
            inBraces = false;
            continue;
        }
        if (closed)
            throw Error("text after the closing '}'", path, lineField(lineNo));
        const size_t space = line.find_first_of(" \t,");
        if (space == std::string_view::npos)
            throw Error("expected 'x y', got '" + std::string(line) + "'", path, lineField(lineNo));
        const std::string_view xs = trimmed(line.substr(0, space));
        std::string_view ys = trimmed(line.substr(space + 1));
        if (!ys.empty() && ys.front() == ',')
            ys = trimmed(ys.substr(1));
        const std::optional<double> x = parseFiniteNumber(xs), y = parseFiniteNumber(ys);
        if (!x || !y)
            throw Error("expected two finite numbers 'x y', got '" + std::string(line) + "'", path,
                        lineField(lineNo));
        // 1-based in the file, 0-based in memory.
        values.push_back(*x - 1.0);
        values.push_back(*y - 1.0);
    }
    if (inBraces)
        throw Error("missing closing '}'", path);
    if (values.empty())
        throw Error("no points", path);
    const int n = int(values.size() / 2);
    if (declared >= 0 && declared != n)
        throw Error("n_points says " + std::to_string(declared) + " but the file holds "
                        + std::to_string(n) + " points",
                    path, "n_points");
    return Eigen::Map<Eigen::VectorXd>(values.data(), Eigen::Index(values.size()));
}

Eigen::VectorXd readPtsFile(const std::string &path)
{
    return parsePts(readWholeFile(path), path);
}

Eigen::VectorXd readFaceShape(const std::string &path)
{
    Eigen::VectorXd points = readPtsFile(path);
    const int n = int(points.size() / 2);
    if (n == scheme23::kPointCount)
        return points;
    if (n == scheme23::kIbugPointCount)
        return mapIbug68To23(points);
    throw Error("expected 23 or 68 points, found " + std::to_string(n), path, "n_points");
}

LandmarkSet readLandmarkSet(const std::string &path, PointState state)
{
    return landmarkSetFromShape(readFaceShape(path), state);
}

std::string formatPts(const Eigen::VectorXd &points, bool header)
{
    std::ostringstream s;
    const int n = int(points.size() / 2);
    if (header)
        s << "version: 1\nn_points: " << n << "\n{\n";
    char buffer[64];
    for (int i = 0; i < n; ++i) {
        std::snprintf(buffer, sizeof buffer, "%.6f %.6f\n", points[2 * i] + 1.0,
                      points[2 * i + 1] + 1.0);
        s << buffer;
    }
    if (header)
        s << "}\n";
    return s.str();
}

void writePtsFile(const std::string &path, const Eigen::VectorXd &points, bool header)
{
    if (!points.allFinite())
        throw Error("points are not finite", path);
    writeFileAtomically(path, formatPts(points, header));
}

void writeLandmarkSet(const std::string &path, const LandmarkSet &set, bool header)
{
    for (int i = 0; i < LandmarkSet::kPointCount; ++i)
        if (!set.points[size_t(i)].isDefined())
            throw Error("point " + std::to_string(i) + " ("
                            + landmarkDefinitions()[size_t(i)].name
                            + ") is not placed; a .pts file needs all 23",
                        path);
    writePtsFile(path, shapeFromLandmarkSet(set), header);
}

Eigen::VectorXd shapeFromLandmarkSet(const LandmarkSet &set)
{
    Eigen::VectorXd shape(2 * LandmarkSet::kPointCount);
    for (int i = 0; i < LandmarkSet::kPointCount; ++i) {
        const auto &p = set.points[size_t(i)];
        shape[2 * i] = p.isDefined() ? p.x : 0.0;
        shape[2 * i + 1] = p.isDefined() ? p.y : 0.0;
    }
    return shape;
}

LandmarkSet landmarkSetFromShape(const Eigen::VectorXd &shape, PointState state)
{
    LandmarkSet set;
    const int n = std::min<int>(LandmarkSet::kPointCount, int(shape.size() / 2));
    for (int i = 0; i < n; ++i)
        set.points[size_t(i)] = LandmarkPoint{shape[2 * i], shape[2 * i + 1], state};
    return set;
}

} // namespace lipsync
