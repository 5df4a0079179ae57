#include "animation/AnimationControls.h"

#include "animation/MouthMapping.h"
#include "animation/MouthTrack.h"
#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/NumberText.h"

#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace lipsync {

namespace {

constexpr int kControlPointValues = 46;
constexpr const char *kControlsFormat = "lipsync-controls";

// MouthMeasures::values() order.
enum Measure { Opening, Width, LeftCorner, RightCorner, Rounding, Jaw, UpperLeft, UpperRight, LowerLeft, LowerRight };

std::string controlNumber(double v)
{
    return formatSignificant(v, 6);
}

std::string formatControlsCsv(const AnimationControls &c)
{
    std::string out = "# soundFile: " + c.soundFile + "\n# frameRate: " + controlNumber(c.frameRate) + "\nframe,time";
    for (const std::string &n : c.names)
        out += ',' + n;
    for (int p = 0; p < kControlPointValues / 2; ++p)
        out += ",x" + std::to_string(p) + ",y" + std::to_string(p);
    out += '\n';
    for (int f = 0; f < c.frameCount(); ++f) {
        out += std::to_string(f) + ',' + controlNumber(c.times[size_t(f)]);
        for (Eigen::Index k = 0; k < c.values.cols(); ++k)
            out += ',' + controlNumber(c.values(f, k));
        for (Eigen::Index k = 0; k < c.points.cols(); ++k)
            out += ',' + controlNumber(c.points(f, k));
        out += '\n';
    }
    return out;
}

QJsonArray controlRow(const Eigen::MatrixXd &m, int r)
{
    QJsonArray a;
    for (Eigen::Index k = 0; k < m.cols(); ++k)
        a.append(parseFiniteNumber(controlNumber(m(r, k))).value_or(0.0)); // as the CSV writes it
    return a;
}

std::string formatControlsJson(const AnimationControls &c)
{
    QJsonArray names, frames;
    for (const std::string &n : c.names)
        names.append(QString::fromStdString(n));
    for (int f = 0; f < c.frameCount(); ++f)
        frames.append(QJsonObject{{"time", c.times[size_t(f)]}, {"values", controlRow(c.values, f)}, {"points", controlRow(c.points, f)}});
    const QJsonObject root{{"format", kControlsFormat},         {"version", 1},
                           {"soundFile", QString::fromStdString(c.soundFile)},
                           {"frameRate", c.frameRate},  {"frameCount", c.frameCount()},
                           {"controls", names},         {"frames", frames}};
    return QJsonDocument(root).toJson(QJsonDocument::Compact).toStdString() + "\n";
}

double parseControlNumber(const std::string &text, const std::string &path, const std::string &where)
{
    const std::optional<double> v = parseFiniteNumber(text);
    if (!v)
        throw Error("'" + text + "' is not a finite number", path, where);
    return *v;
}

std::vector<std::string> splitCells(const std::string &line)
{
    std::vector<std::string> cells;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ','))
        cells.push_back(cell);
    return cells;
}

AnimationControls parseControlsCsv(const std::string &text, const std::string &path)
{
    AnimationControls c;
    std::istringstream in(text);
    std::string line;
    int number = 0;
    std::vector<std::vector<double>> rows;
    size_t columns = 0;
    while (std::getline(in, line)) {
        ++number;
        const std::string where = "line " + std::to_string(number);
        if (line.rfind("# soundFile: ", 0) == 0) {
            c.soundFile = line.substr(13);
        } else if (line.rfind("# frameRate: ", 0) == 0) {
            c.frameRate = parseControlNumber(line.substr(13), path, where);
        } else if (line.rfind("frame,time", 0) == 0) {
            const std::vector<std::string> header = splitCells(line);
            columns = header.size();
            if (columns < 2 + kControlPointValues)
                throw Error("the header names too few columns", path, where);
            c.names.assign(header.begin() + 2, header.end() - kControlPointValues);
        } else if (!line.empty()) {
            const std::vector<std::string> cells = splitCells(line);
            if (columns == 0 || cells.size() != columns)
                throw Error("expected " + std::to_string(columns) + " values", path, where);
            std::vector<double> values;
            for (const std::string &cell : cells)
                values.push_back(parseControlNumber(cell, path, where));
            rows.push_back(std::move(values));
        }
    }
    if (columns == 0)
        throw Error("no header line (frame,time,…)", path);
    c.values.resize(Eigen::Index(rows.size()), Eigen::Index(c.names.size()));
    c.points.resize(Eigen::Index(rows.size()), kControlPointValues);
    for (size_t r = 0; r < rows.size(); ++r) {
        c.times.push_back(rows[r][1]);
        for (size_t k = 0; k < c.names.size(); ++k)
            c.values(Eigen::Index(r), Eigen::Index(k)) = rows[r][2 + k];
        for (int k = 0; k < kControlPointValues; ++k)
            c.points(Eigen::Index(r), k) = rows[r][2 + c.names.size() + size_t(k)];
    }
    return c;
}

void readControlRow(const QJsonValue &value, Eigen::MatrixXd &m, int r, const std::string &path, const std::string &where)
{
    const QJsonArray a = value.toArray();
    if (!value.isArray() || a.size() != m.cols())
        throw Error("expected " + std::to_string(m.cols()) + " numbers", path, where);
    for (int k = 0; k < a.size(); ++k) {
        if (!a[k].isDouble())
            throw Error("expected numbers", path, where);
        m(r, k) = a[k].toDouble();
    }
}

AnimationControls parseControlsJson(const std::string &text, const std::string &path)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &error);
    const QJsonObject root = doc.object();
    if (!doc.isObject() || root["format"].toString() != QLatin1String(kControlsFormat))
        throw Error("not a lipsync-controls file", path, "format");
    if (root["version"].toInt() != 1)
        throw Error("version " + std::to_string(root["version"].toInt()) + " is not one this build reads", path,
                    "version");
    AnimationControls c;
    c.soundFile = root["soundFile"].toString().toStdString();
    c.frameRate = root["frameRate"].toDouble();
    for (const QJsonValue &n : root["controls"].toArray())
        c.names.push_back(n.toString().toStdString());
    const QJsonArray frames = root["frames"].toArray();
    c.values.resize(frames.size(), Eigen::Index(c.names.size()));
    c.points.resize(frames.size(), kControlPointValues);
    for (int f = 0; f < frames.size(); ++f) {
        const std::string where = "frames[" + std::to_string(f) + "]";
        const QJsonObject frame = frames[f].toObject();
        if (!frame["time"].isDouble())
            throw Error("expected a time", path, where + ".time");
        c.times.push_back(frame["time"].toDouble());
        readControlRow(frame["values"], c.values, f, path, where + ".values");
        readControlRow(frame["points"], c.points, f, path, where + ".points");
    }
    return c;
}

bool isControlsCsv(const std::string &path)
{
    const QString suffix = QFileInfo(QString::fromStdString(path)).suffix().toLower();
    if (suffix != QLatin1String("csv") && suffix != QLatin1String("json"))
        throw Error("animation controls are written as .json or .csv, not ." + suffix.toStdString(), path);
    return suffix == QLatin1String("csv");
}

} // namespace

const std::vector<std::string> &animationControlNames()
{
    static const std::vector<std::string> names{
        "jawOpen",          "mouthClose",        "mouthFunnel",        "mouthPucker",
        "mouthStretchLeft", "mouthStretchRight", "mouthUpperUpLeft",   "mouthUpperUpRight",
        "mouthLowerDownLeft", "mouthLowerDownRight", "mouthOpen"};
    return names;
}

int AnimationControls::column(const std::string &name) const
{
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : int(it - names.begin());
}

AnimationControls animationControls(const MouthTrack &track, const MouthMapping &mapping)
{
    AnimationControls c;
    c.soundFile = QFileInfo(QString::fromStdString(track.soundFile)).absoluteFilePath().toStdString();
    c.frameRate = track.frames.rate();
    c.times = track.frames.times();
    c.names = animationControlNames();
    c.values.resize(track.frameCount(), Eigen::Index(c.names.size()));
    c.points = track.points;
    for (int f = 0; f < track.frameCount(); ++f) {
        const auto m = track.measures[size_t(f)].values();
        auto n = [&](Measure k) { return mapping.normalised(k, m[size_t(k)]); };
        const double jaw = n(Jaw), open = n(Opening), narrow = 1.0 - n(Width);
        // Image left is the subject's right.
        c.values.row(f) << jaw, std::max(0.0, jaw - open), narrow * open, narrow * (1.0 - open), n(RightCorner),
            n(LeftCorner), n(UpperRight), n(UpperLeft), n(LowerRight), n(LowerLeft), open;
    }
    return c;
}

void writeAnimationControls(const AnimationControls &controls, const std::string &path)
{
    writeFileAtomically(path, isControlsCsv(path) ? formatControlsCsv(controls) : formatControlsJson(controls));
}

AnimationControls readAnimationControls(const std::string &path)
{
    const bool csv = isControlsCsv(path);
    const std::string text = readWholeFile(path);
    return csv ? parseControlsCsv(text, path) : parseControlsJson(text, path);
}

} // namespace lipsync
