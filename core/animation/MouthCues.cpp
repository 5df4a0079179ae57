#include "animation/MouthCues.h"

#include "animation/MouthMapping.h"
#include "animation/MouthTrack.h"
#include "io/AtomicFile.h"
#include "util/Error.h"
#include "util/NumberText.h"

#include <QByteArray>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QString>
#include <QXmlStreamReader>
#include <QXmlStreamWriter>

#include <cmath>
#include <sstream>

namespace lipsync {

namespace {

// Rhubarb's times: centiseconds, written "%.2f".
double centiseconds(double seconds)
{
    return std::round(seconds * 100.0) / 100.0;
}

std::string formatTime(double seconds)
{
    return formatFixed(centiseconds(seconds), 2);
}

std::string jsonString(const std::string &s)
{
    const QByteArray quoted = QJsonDocument(QJsonArray{QString::fromStdString(s)}).toJson(QJsonDocument::Compact);
    return quoted.mid(1, quoted.size() - 2).toStdString();
}

int datFrame(double seconds, const DatOptions &dat)
{
    return 1 + int(dat.frameRate * centiseconds(seconds) + 1e-9); // a frame's own start is that frame
}

std::string formatCueTsv(const MouthCueTrack &track)
{
    std::string out;
    for (const MouthCue &c : track.cues)
        out += formatTime(c.start) + '\t' + mouthShapeLetter(c.shape) + '\n';
    out += formatTime(track.duration) + "\tX\n";
    return out;
}

std::string formatCueJson(const MouthCueTrack &track)
{
    std::string out = "{\n  \"metadata\": {\n    \"soundFile\": " + jsonString(track.soundFile)
                      + ",\n    \"duration\": " + formatTime(track.duration) + "\n  },\n  \"mouthCues\": [\n";
    for (size_t i = 0; i < track.cues.size(); ++i) {
        const MouthCue &c = track.cues[i];
        out += "    { \"start\": " + formatTime(c.start) + ", \"end\": " + formatTime(c.end) + ", \"value\": \""
               + mouthShapeLetter(c.shape) + "\" }" + (i + 1 < track.cues.size() ? ",\n" : "\n");
    }
    return out + "  ]\n}\n";
}

std::string formatCueXml(const MouthCueTrack &track)
{
    QByteArray bytes;
    QXmlStreamWriter xml(&bytes);
    xml.setAutoFormatting(true);
    xml.setAutoFormattingIndent(2);
    xml.writeStartDocument();
    xml.writeStartElement("rhubarbResult");
    xml.writeStartElement("metadata");
    xml.writeTextElement("soundFile", QString::fromStdString(track.soundFile));
    xml.writeTextElement("duration", QString::fromStdString(formatTime(track.duration)));
    xml.writeEndElement();
    xml.writeStartElement("mouthCues");
    for (const MouthCue &c : track.cues) {
        xml.writeStartElement("mouthCue");
        xml.writeAttribute("start", QString::fromStdString(formatTime(c.start)));
        xml.writeAttribute("end", QString::fromStdString(formatTime(c.end)));
        xml.writeCharacters(QString(QLatin1Char(mouthShapeLetter(c.shape))));
        xml.writeEndElement();
    }
    xml.writeEndDocument();
    return bytes.toStdString();
}

std::string shapeName(MouthShape s, const DatOptions &dat)
{
    return dat.prestonBlair ? prestonBlairName(s) : std::string(1, mouthShapeLetter(s));
}

std::string formatCueDat(const MouthCueTrack &track, const DatOptions &dat)
{
    std::string out = "MohoSwitch1\n";
    int last = 0;
    for (const MouthCue &c : track.cues) {
        const int frame = datFrame(c.start, dat);
        if (frame == last)
            continue; // shorter than a frame at this rate, as Rhubarb drops it
        out += std::to_string(frame) + ' ' + shapeName(c.shape, dat) + '\n';
        last = frame;
    }
    int end = datFrame(track.duration, dat);
    if (end == last)
        ++end;
    return out + std::to_string(end) + ' ' + shapeName(MouthShape::X, dat) + '\n';
}

void checkDatOptions(const DatOptions &dat)
{
    if (!(dat.frameRate >= 24.0 && dat.frameRate <= 100.0))
        throw Error("the .dat frame rate must be from 24 to 100 fps (Rhubarb's range), not "
                    + std::to_string(dat.frameRate));
}

// A letter, or a Preston Blair name; `prestonBlairFirst` for .dat files written with those names,
// where "E" is Rhubarb's C.
MouthShape shapeOf(const std::string &name, const std::string &path, const std::string &where,
                   bool prestonBlairFirst = false)
{
    if (prestonBlairFirst)
        if (const auto s = parsePrestonBlairName(name))
            return *s;
    if (const auto s = parseMouthShape(name))
        return *s;
    if (const auto s = parsePrestonBlairName(name))
        return *s;
    throw Error("'" + name + "' is not a mouth shape (A to H or X, or a Preston Blair name)", path, where);
}

double timeOf(const std::string &text, const std::string &path, const std::string &where)
{
    const std::optional<double> t = parseFiniteNumber(text);
    if (!t || *t < 0)
        throw Error("'" + text + "' is not a time in seconds", path, where);
    return *t;
}

// Cues from (start, shape) pairs and an end: each lasts until the next starts.
MouthCueTrack fromStarts(std::vector<std::pair<double, MouthShape>> starts, double end, std::string soundFile)
{
    MouthCueTrack track;
    track.soundFile = std::move(soundFile);
    track.duration = end;
    for (size_t i = 0; i < starts.size(); ++i)
        track.cues.push_back({starts[i].first, i + 1 < starts.size() ? starts[i + 1].first : end, starts[i].second});
    return track;
}

MouthCueTrack parseCueLines(const std::string &text, const std::string &path, bool dat, const DatOptions &options)
{
    std::istringstream in(text);
    std::string line;
    int number = 0;
    std::vector<std::pair<double, MouthShape>> starts;
    while (std::getline(in, line)) {
        ++number;
        if (!line.empty() && line.back() == '\r')
            line.pop_back();
        const std::string where = "line " + std::to_string(number);
        if (dat && number == 1) {
            if (line != "MohoSwitch1")
                throw Error("a Moho switch file starts with MohoSwitch1", path, where);
            continue;
        }
        if (line.empty())
            continue;
        const size_t cut = line.find(dat ? ' ' : '\t');
        if (cut == std::string::npos)
            throw Error(dat ? "expected 'frame shape'" : "expected 'time<TAB>shape'", path, where);
        double t = 0;
        if (dat) {
            const double frame = timeOf(line.substr(0, cut), path, where);
            if (frame < 1 || frame != std::floor(frame))
                throw Error("frames are counted from 1", path, where);
            t = (frame - 1) / options.frameRate;
        } else {
            t = timeOf(line.substr(0, cut), path, where);
        }
        if (!starts.empty() && t < starts.back().first)
            throw Error("the times go backwards", path, where);
        starts.emplace_back(t, shapeOf(line.substr(cut + 1), path, where, dat && options.prestonBlair));
    }
    if (starts.empty())
        throw Error("no mouth cues", path);
    const double end = starts.back().first; // the last line closes the mouth at the end
    starts.pop_back();
    return fromStarts(std::move(starts), end, {});
}

MouthCueTrack parseCueJson(const std::string &text, const std::string &path)
{
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(QByteArray::fromStdString(text), &error);
    if (!doc.isObject())
        throw Error("not a JSON object: " + error.errorString().toStdString(), path);
    const QJsonObject root = doc.object();
    MouthCueTrack track;
    track.soundFile = root["metadata"]["soundFile"].toString().toStdString();
    track.duration = root["metadata"]["duration"].toDouble(NAN);
    if (!root["mouthCues"].isArray() || !std::isfinite(track.duration))
        throw Error("expected metadata.duration and a mouthCues array", path);
    const QJsonArray cues = root["mouthCues"].toArray();
    for (int i = 0; i < cues.size(); ++i) {
        const std::string where = "mouthCues[" + std::to_string(i) + "]";
        const QJsonObject c = cues[i].toObject();
        if (!c["start"].isDouble() || !c["end"].isDouble() || !c["value"].isString())
            throw Error("expected start, end and value", path, where);
        track.cues.push_back({c["start"].toDouble(), c["end"].toDouble(),
                              shapeOf(c["value"].toString().toStdString(), path, where)});
    }
    return track;
}

MouthCueTrack parseCueXml(const std::string &text, const std::string &path)
{
    QXmlStreamReader xml(QByteArray::fromStdString(text));
    MouthCueTrack track;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        const QStringView name = xml.name();
        const std::string where = "line " + std::to_string(xml.lineNumber());
        if (name == QLatin1String("soundFile")) {
            track.soundFile = xml.readElementText().toStdString();
        } else if (name == QLatin1String("duration")) {
            track.duration = timeOf(xml.readElementText().toStdString(), path, where);
        } else if (name == QLatin1String("mouthCue")) {
            const double start = timeOf(xml.attributes().value("start").toString().toStdString(), path, where);
            const double end = timeOf(xml.attributes().value("end").toString().toStdString(), path, where);
            track.cues.push_back({start, end, shapeOf(xml.readElementText().toStdString(), path, where)});
        }
    }
    if (xml.hasError())
        throw Error("not well-formed XML: " + xml.errorString().toStdString(), path,
                    "line " + std::to_string(xml.lineNumber()));
    return track;
}

} // namespace

MouthCueTrack mouthCues(const MouthTrack &track, const MouthMapping &mapping)
{
    const int n = track.frameCount();
    std::vector<MouthShape> shapes(static_cast<size_t>(n));
    for (int i = 0; i < n; ++i)
        shapes[size_t(i)] = mapping.classify(track.measures[size_t(i)], track.phones[size_t(i)]);
    // A lone speech frame between two frames of one shape: a flicker no drawn mouth should show.
    for (int i = 1; i + 1 < n; ++i) {
        const MouthShape before = shapes[size_t(i - 1)], here = shapes[size_t(i)];
        if (before == shapes[size_t(i + 1)] && here != before && here != MouthShape::A && here != MouthShape::X
            && before != MouthShape::X)
            shapes[size_t(i)] = before;
    }
    MouthCueTrack out;
    out.soundFile = QFileInfo(QString::fromStdString(track.soundFile)).absoluteFilePath().toStdString();
    out.duration = n > 0 ? track.frames.endTime() : 0.0;
    for (int i = 0; i < n;) {
        int j = i + 1;
        while (j < n && shapes[size_t(j)] == shapes[size_t(i)])
            ++j;
        // Rest from the sound's start to the first frame: the first cue's when it is X.
        const double start = i == 0 && shapes[0] == MouthShape::X ? 0.0 : track.frames.time(i);
        if (i == 0 && start > 0.005)
            out.cues.push_back({0.0, start, MouthShape::X});
        out.cues.push_back({start, track.frames.endTime(j - 1), shapes[size_t(i)]});
        i = j;
    }
    return out;
}

CueFormat cueFormatOfPath(const std::string &path)
{
    const QString suffix = QFileInfo(QString::fromStdString(path)).suffix().toLower();
    if (suffix == QLatin1String("tsv"))
        return CueFormat::Tsv;
    if (suffix == QLatin1String("json"))
        return CueFormat::Json;
    if (suffix == QLatin1String("xml"))
        return CueFormat::Xml;
    if (suffix == QLatin1String("dat"))
        return CueFormat::Dat;
    throw Error("mouth cues are written as .tsv, .json, .xml or .dat (Moho), not ." + suffix.toStdString(), path);
}

std::string formatMouthCues(const MouthCueTrack &track, CueFormat format, const DatOptions &dat)
{
    switch (format) {
    case CueFormat::Tsv: return formatCueTsv(track);
    case CueFormat::Json: return formatCueJson(track);
    case CueFormat::Xml: return formatCueXml(track);
    case CueFormat::Dat: checkDatOptions(dat); return formatCueDat(track, dat);
    }
    return {};
}

void writeMouthCues(const MouthCueTrack &track, const std::string &path, const DatOptions &dat)
{
    writeFileAtomically(path, formatMouthCues(track, cueFormatOfPath(path), dat));
}

MouthCueTrack readMouthCues(const std::string &path, const DatOptions &dat)
{
    const CueFormat format = cueFormatOfPath(path);
    const std::string text = readWholeFile(path);
    switch (format) {
    case CueFormat::Tsv: return parseCueLines(text, path, false, dat);
    case CueFormat::Dat: checkDatOptions(dat); return parseCueLines(text, path, true, dat);
    case CueFormat::Json: return parseCueJson(text, path);
    case CueFormat::Xml: return parseCueXml(text, path);
    }
    return {};
}

} // namespace lipsync
