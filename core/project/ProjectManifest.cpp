#include "project/ProjectManifest.h"

#include "io/FeatureCsv.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QDir>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonValue>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <set>
#include <sstream>

namespace lipsync {

namespace {

QString toQString(const std::string &s)
{
    return QString::fromStdString(s);
}

std::string absoluteFolder(const std::string &folder)
{
    return QDir::cleanPath(QFileInfo(toQString(folder.empty() ? std::string(".") : folder)).absoluteFilePath())
        .toStdString();
}

// ---- reading ------------------------------------------------------------------------------

std::string member(const std::string &parent, const char *key)
{
    return parent.empty() ? std::string(key) : parent + "." + key;
}

std::string element(const std::string &parent, qsizetype index)
{
    return parent + "[" + std::to_string(index) + "]";
}

std::string describe(const QJsonValue &value)
{
    switch (value.type()) {
    case QJsonValue::Null: return "null";
    case QJsonValue::Bool: return "a boolean";
    case QJsonValue::Double: return QString::number(value.toDouble()).toStdString();
    case QJsonValue::String: return "a string";
    case QJsonValue::Array: return "an array";
    case QJsonValue::Object: return "an object";
    case QJsonValue::Undefined: break;
    }
    return "missing";
}

class Reader
{
public:
    Reader(std::string manifestPath, std::string folder, bool readFeatures)
        : m_path(std::move(manifestPath)), m_folder(std::move(folder)), m_readFeatures(readFeatures)
    {
    }

    Project read(const QJsonObject &root) const
    {
        // Format and version first: a newer manifest may well have fields this build does not
        // know, and "newer version" is the useful message then, not "unknown field".
        const std::string format = string(require(root, "format", ""), "format", false);
        if (format != ProjectManifest::kFormatName)
            fail("format", "is '" + format + "', expected '" + ProjectManifest::kFormatName + "'");
        const QJsonValue versionValue = require(root, "version", "");
        if (!versionValue.isDouble() || versionValue.toDouble() != std::floor(versionValue.toDouble()))
            fail("version", "must be an integer, found " + describe(versionValue));
        const double version = versionValue.toDouble();
        if (version > Project::kFormatVersion)
            fail("version", "project format version " + QString::number(version).toStdString()
                                + " is newer than this build of LipSync Studio reads (up to "
                                + std::to_string(Project::kFormatVersion)
                                + "); open it with a newer version");
        if (version < 1)
            fail("version", "must be at least 1");
        checkKeys(root, "", {"format", "version", "name", "aligner", "sequences", "models", "study", "pronunciations",
                             "mouthShapes"});

        Project project;
        if (root.contains("name"))
            project.name = string(root.value("name"), "name", true);

        const QJsonArray sequences = array(require(root, "sequences", ""), "sequences");
        std::set<std::string> ids;
        for (qsizetype i = 0; i < sequences.size(); ++i) {
            const std::string field = element("sequences", i);
            Sequence sequence = readSequence(object(sequences[i], field), field);
            if (!ids.insert(sequence.id).second)
                fail(member(field, "id"), "'" + sequence.id + "' is used by an earlier sequence");
            project.sequences.push_back(std::move(sequence));
        }

        if (root.contains("models")) {
            const QJsonArray models = array(root.value("models"), "models");
            for (qsizetype i = 0; i < models.size(); ++i)
                project.models.push_back(readModel(object(models[i], element("models", i)),
                                                   element("models", i)));
        }

        if (root.contains("study")) {
            const std::string relative = string(root.value("study"), "study", false);
            if (m_readFeatures) {
                const QString path = QDir::cleanPath(QDir(toQString(m_folder)).absoluteFilePath(toQString(relative)));
                if (!QFileInfo(path).isFile())
                    fail("study", "referenced study file '" + path.toStdString() + "' does not exist");
                // The study file validates itself; its errors name the study file and field.
                project.study = ForcedChoiceStudy::load(path.toStdString());
            }
        }
        if (root.contains("pronunciations"))
            project.pronunciations = readPronunciations(root.value("pronunciations"), "pronunciations");
        if (root.contains("aligner")) {
            project.aligner = string(root.value("aligner"), "aligner", false);
            if (project.aligner != Project::kBuiltinAligner && project.aligner != Project::kGenericAligner)
                fail("aligner", "must be \"builtin\" or \"generic\", found \"" + project.aligner + "\"");
        }
        if (root.contains("mouthShapes"))
            project.mouthShapes = readMouthShapes(root.value("mouthShapes"));
        return project;
    }

private:
    std::map<std::string, Project::MouthShapeFeatures> readMouthShapes(const QJsonValue &value) const
    {
        if (!value.isObject())
            fail("mouthShapes", "must be an object of shape letters, found " + describe(value));
        std::map<std::string, Project::MouthShapeFeatures> shapes;
        const QJsonObject object = value.toObject();
        for (auto it = object.begin(); it != object.end(); ++it) {
            const std::string field = member("mouthShapes", it.key().toUtf8().constData());
            if (it.key().size() != 1 || it.key()[0] < QLatin1Char('A') || it.key()[0] > QLatin1Char('H'))
                fail(field, "must be a mouth shape A to H");
            const QJsonArray values = it.value().toArray();
            if (!it.value().isArray() || values.size() != 4)
                fail(field, "must be 4 numbers (opening, width, rounding, teeth), found " + describe(it.value()));
            Project::MouthShapeFeatures f{};
            for (int i = 0; i < 4; ++i) {
                if (!values[i].isDouble() || !(values[i].toDouble() >= 0 && values[i].toDouble() <= 1))
                    fail(field, "must be numbers from 0 to 1, found " + describe(values[i]));
                f[size_t(i)] = values[i].toDouble();
            }
            shapes[it.key().toStdString()] = f;
        }
        return shapes;
    }

    [[noreturn]] void fail(const std::string &field, const std::string &message) const
    {
        throw Error(message, m_path, field.empty() ? std::string("(top level)") : field);
    }

    void checkKeys(const QJsonObject &object, const std::string &field,
                   std::initializer_list<const char *> known) const
    {
        for (auto it = object.begin(); it != object.end(); ++it) {
            const std::string key = it.key().toStdString();
            if (std::none_of(known.begin(), known.end(), [&](const char *k) { return key == k; }))
                fail(member(field, key.c_str()), "unknown field (misspelt, or from a newer version?)");
        }
    }

    QJsonValue require(const QJsonObject &object, const char *key, const std::string &parent) const
    {
        if (!object.contains(QLatin1String(key)))
            fail(member(parent, key), "missing");
        return object.value(QLatin1String(key));
    }

    QJsonObject object(const QJsonValue &value, const std::string &field) const
    {
        if (!value.isObject())
            fail(field, "must be an object, found " + describe(value));
        return value.toObject();
    }

    QJsonArray array(const QJsonValue &value, const std::string &field) const
    {
        if (!value.isArray())
            fail(field, "must be an array, found " + describe(value));
        return value.toArray();
    }

    std::string string(const QJsonValue &value, const std::string &field, bool allowEmpty) const
    {
        if (!value.isString())
            fail(field, "must be a string, found " + describe(value));
        const std::string text = value.toString().toStdString();
        if (!allowEmpty && text.empty())
            fail(field, "must not be empty");
        return text;
    }

    double number(const QJsonValue &value, const std::string &field) const
    {
        if (!value.isDouble() || !std::isfinite(value.toDouble()))
            fail(field, "must be a finite number, found " + describe(value));
        return value.toDouble();
    }

    int integer(const QJsonValue &value, const std::string &field, int minimum) const
    {
        const double v = value.isDouble() ? value.toDouble() : std::numeric_limits<double>::quiet_NaN();
        if (!std::isfinite(v) || v != std::floor(v) || v < minimum
            || v > std::numeric_limits<int>::max())
            fail(field, "must be an integer >= " + std::to_string(minimum) + ", found "
                            + describe(value));
        return int(v);
    }

    bool boolean(const QJsonValue &value, const std::string &field) const
    {
        if (!value.isBool())
            fail(field, "must be true or false, found " + describe(value));
        return value.toBool();
    }

    // A variable frame rate's presentation times: frameCount increasing seconds >= 0.
    std::vector<double> readFrameTimes(const QJsonValue &value, const std::string &field, int frameCount) const
    {
        if (!value.isArray())
            fail(field, "must be an array of seconds, found " + describe(value));
        const QJsonArray array = value.toArray();
        if (array.size() != frameCount)
            fail(field, "has " + std::to_string(array.size()) + " times, expected frameCount "
                            + std::to_string(frameCount));
        std::vector<double> times;
        times.reserve(size_t(array.size()));
        for (qsizetype i = 0; i < array.size(); ++i) {
            const QJsonValue t = array.at(i);
            if (!t.isDouble() || !std::isfinite(t.toDouble()) || t.toDouble() < 0
                || (!times.empty() && t.toDouble() <= times.back()))
                fail(field + "[" + std::to_string(i) + "]",
                     "must be a time in seconds after the one before, found " + describe(t));
            times.push_back(t.toDouble());
        }
        return times;
    }

    // One posterior in [0, 1] per word of `transcript`.
    std::vector<double> readConfidence(const QJsonValue &value, const std::string &field,
                                       const std::string &transcript) const
    {
        const QJsonArray values = array(value, field);
        const size_t words = Sequence::transcriptWords(transcript).size();
        if (size_t(values.size()) != words)
            fail(field, std::to_string(values.size()) + " values for " + std::to_string(words)
                            + " words of the transcript");
        std::vector<double> out;
        for (qsizetype i = 0; i < values.size(); ++i) {
            const double v = values[i].toDouble(-1.0);
            if (!values[i].isDouble() || !(v >= 0.0 && v <= 1.0))
                fail(element(field, i), "must be a probability (0 to 1), found " + describe(values[i]));
            out.push_back(v);
        }
        return out;
    }

    Sequence readSequence(const QJsonObject &o, const std::string &field) const
    {
        checkKeys(o, field, {"id", "mediaFile", "frameRate", "frameCount", "firstFrameTime", "frameTimes",
                             "transcript", "transcriptProposed", "transcriptFit", "transcriptFitThreshold",
                             "transcriptConfidence", "features", "tiers", "landmarks", "fitErrors"});
        Sequence s;
        s.id = string(require(o, "id", field), member(field, "id"), false);
        // The id names files (features/<id>.csv), so it must stay inside the project folder.
        if (s.id.find_first_of("/\\") != std::string::npos || s.id.front() == '.'
            || std::any_of(s.id.begin(), s.id.end(), [](char c) { return (unsigned char)c < 32; }))
            fail(member(field, "id"), "'" + s.id
                                          + "' must not contain '/', '\\' or control characters "
                                            "nor start with '.'");
        s.mediaFile = string(require(o, "mediaFile", field), member(field, "mediaFile"), false);
        const QJsonValue rate = require(o, "frameRate", field);
        if (!rate.isDouble() || !std::isfinite(rate.toDouble()) || rate.toDouble() <= 0)
            fail(member(field, "frameRate"), "must be a positive number, found " + describe(rate));
        s.frameRate = rate.toDouble();
        s.frameCount = integer(require(o, "frameCount", field), member(field, "frameCount"), 0);
        if (o.contains("firstFrameTime")) {
            const QJsonValue first = o.value("firstFrameTime");
            if (!first.isDouble() || !std::isfinite(first.toDouble()) || first.toDouble() < 0)
                fail(member(field, "firstFrameTime"), "must be a number of seconds >= 0, found " + describe(first));
            s.firstFrameTime = first.toDouble();
        }
        if (o.contains("frameTimes"))
            s.frameTimes = readFrameTimes(o.value("frameTimes"), member(field, "frameTimes"), s.frameCount);
        if (o.contains("transcript"))
            s.transcript = string(o.value("transcript"), member(field, "transcript"), true);
        if (o.contains("transcriptProposed"))
            s.transcriptProposed = boolean(o.value("transcriptProposed"), member(field, "transcriptProposed"));
        if (o.contains("transcriptFit")) {
            const QJsonValue fit = o.value("transcriptFit");
            if (!fit.isDouble() || !std::isfinite(fit.toDouble()))
                fail(member(field, "transcriptFit"), "must be a number (nats per frame), found " + describe(fit));
            // Fits measured before aligners gave their own thresholds are our aligner's.
            double threshold = kTranscriptFitThreshold;
            if (o.contains("transcriptFitThreshold")) {
                const QJsonValue t = o.value("transcriptFitThreshold");
                if (!t.isDouble() || !std::isfinite(t.toDouble()))
                    fail(member(field, "transcriptFitThreshold"), "must be a number (nats per frame), found " + describe(t));
                threshold = t.toDouble();
            }
            s.transcriptFit = TranscriptFit{fit.toDouble(), threshold};
        } else if (o.contains("transcriptFitThreshold")) {
            fail(member(field, "transcriptFitThreshold"), "is given without a transcriptFit");
        }
        if (o.contains("transcriptConfidence"))
            s.transcriptConfidence = readConfidence(o.value("transcriptConfidence"),
                                                    member(field, "transcriptConfidence"), s.transcript);

        if (o.contains("tiers")) {
            const std::string tiersField = member(field, "tiers");
            const QJsonObject tiers = object(o.value("tiers"), tiersField);
            checkKeys(tiers, tiersField, {"words", "phones"});
            if (tiers.contains("words"))
                s.words.intervals = readIntervals(tiers.value("words"), member(tiersField, "words"));
            if (tiers.contains("phones"))
                s.phones.intervals = readIntervals(tiers.value("phones"), member(tiersField, "phones"));
        }

        if (o.contains("landmarks")) {
            const std::string lmField = member(field, "landmarks");
            const QJsonArray frames = array(o.value("landmarks"), lmField);
            for (qsizetype i = 0; i < frames.size(); ++i) {
                const std::string frameField = element(lmField, i);
                const QJsonObject frame = object(frames[i], frameField);
                checkKeys(frame, frameField, {"frame", "points"});
                const int index = integer(require(frame, "frame", frameField),
                                          member(frameField, "frame"), 0);
                if (index >= s.frameCount)
                    fail(member(frameField, "frame"), std::to_string(index)
                                                          + " is not below frameCount "
                                                          + std::to_string(s.frameCount));
                if (s.landmarks.count(index))
                    fail(member(frameField, "frame"), std::to_string(index)
                                                          + " appears twice");
                s.landmarks[index] = readLandmarks(require(frame, "points", frameField),
                                                   member(frameField, "points"));
            }
        }

        if (o.contains("features")) {
            const std::string featuresField = member(field, "features");
            const std::string relative = string(o.value("features"), featuresField, false);
            if (m_readFeatures)
                s.features = readFeatures(relative, s, featuresField);
        }

        if (o.contains("fitErrors")) {
            const std::string errorsField = member(field, "fitErrors");
            const QJsonArray errors = array(o.value("fitErrors"), errorsField);
            if (errors.size() != s.frameCount)
                fail(errorsField, "has " + std::to_string(errors.size()) + " values, expected one per frame ("
                                      + std::to_string(s.frameCount) + ")");
            s.fitErrors.reserve(size_t(errors.size()));
            for (qsizetype i = 0; i < errors.size(); ++i) {
                if (errors[i].isNull()) {
                    s.fitErrors.push_back(Sequence::kNoFace);
                    continue;
                }
                const double e = number(errors[i], element(errorsField, i));
                if (e < 0)
                    fail(element(errorsField, i), "must not be negative (null marks a frame without a face)");
                s.fitErrors.push_back(e);
            }
        }
        return s;
    }

    std::vector<Interval> readIntervals(const QJsonValue &value, const std::string &field) const
    {
        const QJsonArray items = array(value, field);
        std::vector<Interval> intervals;
        for (qsizetype i = 0; i < items.size(); ++i) {
            const std::string f = element(field, i);
            const QJsonObject o = object(items[i], f);
            checkKeys(o, f, {"start", "end", "label", "userEdited"});
            Interval interval;
            interval.start = number(require(o, "start", f), member(f, "start"));
            interval.end = number(require(o, "end", f), member(f, "end"));
            interval.label = string(require(o, "label", f), member(f, "label"), true);
            if (o.contains("userEdited"))
                interval.userEdited = boolean(o.value("userEdited"), member(f, "userEdited"));
            intervals.push_back(std::move(interval));
        }
        // The tier's one invariant (Tier::defect), which the studio's edits keep as well.
        const Tier tier{"", intervals};
        if (const std::optional<TierDefect> d = tier.defect())
            fail(member(element(field, d->index), d->member.c_str()), d->message);
        return intervals;
    }

    LandmarkSet readLandmarks(const QJsonValue &value, const std::string &field) const
    {
        const QJsonArray points = array(value, field);
        if (points.size() != LandmarkSet::kPointCount)
            fail(field, "has " + std::to_string(points.size()) + " points, expected "
                            + std::to_string(LandmarkSet::kPointCount));
        LandmarkSet set;
        for (qsizetype i = 0; i < points.size(); ++i) {
            const std::string f = element(field, i);
            if (points[i].isNull())
                continue; // undefined at (0, 0)
            const QJsonArray p = array(points[i], f);
            if (p.size() != 3)
                fail(f, "must be null or [x, y, state]");
            LandmarkPoint &point = set.points[size_t(i)];
            point.x = number(p[0], element(f, 0));
            point.y = number(p[1], element(f, 1));
            const std::string state = string(p[2], element(f, 2), false);
            if (!pointStateFromName(state, point.state))
                fail(element(f, 2), "unknown state '" + state
                                        + "' (expected undefined, placed, automatic or fixed)");
        }
        return set;
    }

    Eigen::MatrixXd readFeatures(const std::string &relative, const Sequence &s,
                                 const std::string &field) const
    {
        const QString path = QDir::cleanPath(QDir(toQString(m_folder)).absoluteFilePath(toQString(relative)));
        const std::string where = "sequence '" + s.id + "': ";
        if (!QFileInfo(path).isFile())
            fail(field, where + "referenced features file '" + path.toStdString()
                            + "' does not exist");
        FeatureTable table;
        try {
            table = readFeatureCsv(path.toStdString());
        } catch (const Error &e) {
            fail(field, where + e.what());
        }
        if (table.values.rows() != s.frameCount)
            fail(field, where + "'" + path.toStdString() + "' has "
                            + std::to_string(table.values.rows()) + " rows, expected frameCount "
                            + std::to_string(s.frameCount));
        for (size_t r = 0; r < table.frames.size(); ++r)
            if (table.frames[r] != int(r))
                fail(field, where + "'" + path.toStdString() + "' row " + std::to_string(r)
                                + " is frame " + std::to_string(table.frames[r])
                                + ", expected " + std::to_string(r));
        return table.values;
    }

    // [{"word": "lipsync", "phones": "L IH P S IH NG K"}, ...]: one entry per word, phones of
    // PhoneSet (stress digits allowed).
    std::map<std::string, std::string> readPronunciations(const QJsonValue &value, const std::string &field) const
    {
        const QJsonArray entries = array(value, field);
        std::map<std::string, std::string> out;
        for (qsizetype i = 0; i < entries.size(); ++i) {
            const std::string f = element(field, i);
            const QJsonObject o = object(entries[i], f);
            checkKeys(o, f, {"word", "phones"});
            const std::string word = string(require(o, "word", f), member(f, "word"), false);
            if (std::any_of(word.begin(), word.end(), [](char c) { return std::isspace((unsigned char)c) || std::isupper((unsigned char)c); }))
                fail(member(f, "word"), "'" + word + "' must be one lower-case word without spaces");
            const std::string phones = string(require(o, "phones", f), member(f, "phones"), false);
            std::istringstream in(phones);
            std::string label;
            int count = 0;
            while (in >> label) {
                ++count;
                if (PhoneSet::index(label) < 0)
                    fail(member(f, "phones"), "'" + label + "' is not one of the 41 phones (ARPAbet, sil, br)");
            }
            if (count == 0)
                fail(member(f, "phones"), "must hold at least one phone");
            if (!out.emplace(word, phones).second)
                fail(member(f, "word"), "'" + word + "' has an earlier entry");
        }
        return out;
    }

    ModelReference readModel(const QJsonObject &o, const std::string &field) const
    {
        checkKeys(o, field, {"kind", "name", "file"});
        ModelReference model;
        model.kind = string(require(o, "kind", field), member(field, "kind"), false);
        model.name = string(require(o, "name", field), member(field, "name"), true);
        model.file = string(require(o, "file", field), member(field, "file"), false);
        return model;
    }

    std::string m_path;
    std::string m_folder;
    bool m_readFeatures;
};

// ---- writing ------------------------------------------------------------------------------

QJsonValue pointToJson(const LandmarkPoint &p)
{
    // An untouched point is null; an undefined one that kept coordinates keeps them, so a
    // save/load round trip is exact.
    if (p.state == PointState::Undefined && p.x == 0.0 && p.y == 0.0)
        return QJsonValue::Null;
    return QJsonArray{p.x, p.y, QString::fromLatin1(pointStateName(p.state))};
}

QJsonArray tierToJson(const Tier &tier)
{
    QJsonArray out;
    for (const Interval &i : tier.intervals)
        out.append(QJsonObject{{"start", i.start},
                               {"end", i.end},
                               {"label", toQString(i.label)},
                               {"userEdited", i.userEdited}});
    return out;
}

// Manifest keys in reading order; keys not listed follow alphabetically.
const QStringList &keyOrder()
{
    static const QStringList order{"format",     "version",   "kind",      "name",      "aligner",
                                   "sequences",  "models",    "pronunciations", "word",
                                   "id",         "mediaFile", "frameRate", "frameCount",
                                   "firstFrameTime", "frameTimes",
                                   "transcript", "transcriptProposed", "transcriptFit", "transcriptFitThreshold",
                                   "transcriptConfidence", "features", "tiers", "words",
                                   "phones",     "landmarks", "fitErrors", "frame",
                                   "points",     "start",     "end",       "label",
                                   "userEdited", "file",      "study", "mouthShapes"};
    return order;
}

QStringList orderedKeys(const QJsonObject &object)
{
    QStringList keys = object.keys();
    const QStringList &order = keyOrder();
    std::stable_sort(keys.begin(), keys.end(), [&](const QString &a, const QString &b) {
        qsizetype ia = order.indexOf(a), ib = order.indexOf(b);
        if (ia < 0)
            ia = order.size();
        if (ib < 0)
            ib = order.size();
        return ia < ib;
    });
    return keys;
}

bool isScalar(const QJsonValue &v)
{
    return !v.isArray() && !v.isObject();
}

// On one line: scalars, containers of scalars, and arrays of scalar arrays (a frame's points).
bool isFlat(const QJsonValue &v)
{
    if (isScalar(v))
        return true;
    if (v.isObject()) {
        const QJsonObject o = v.toObject();
        return std::all_of(o.begin(), o.end(), [](const QJsonValue &c) { return isScalar(c); });
    }
    const QJsonArray a = v.toArray();
    return std::all_of(a.begin(), a.end(), [](const QJsonValue &c) {
        if (isScalar(c))
            return true;
        if (!c.isArray())
            return false;
        const QJsonArray inner = c.toArray();
        return std::all_of(inner.begin(), inner.end(),
                           [](const QJsonValue &x) { return isScalar(x); });
    });
}

QByteArray scalarText(const QJsonValue &v)
{
    // QJsonDocument does the escaping and the shortest round-trip number formatting.
    const QByteArray text = QJsonDocument(QJsonArray{v}).toJson(QJsonDocument::Compact);
    return text.mid(1, text.size() - 2);
}

void writeValue(QByteArray &out, const QJsonValue &v, int indent)
{
    if (isScalar(v)) {
        out += scalarText(v);
        return;
    }
    const bool flat = isFlat(v);
    const QByteArray pad(indent + 2, ' ');
    const char *separator = flat ? ", " : ",\n";
    if (v.isArray()) {
        const QJsonArray a = v.toArray();
        if (a.isEmpty()) {
            out += "[]";
            return;
        }
        out += flat ? "[" : "[\n";
        for (qsizetype i = 0; i < a.size(); ++i) {
            if (i > 0)
                out += separator;
            if (!flat)
                out += pad;
            writeValue(out, a[i], indent + 2);
        }
        out += flat ? QByteArray("]") : "\n" + QByteArray(indent, ' ') + "]";
        return;
    }
    const QJsonObject o = v.toObject();
    if (o.isEmpty()) {
        out += "{}";
        return;
    }
    out += flat ? "{" : "{\n";
    bool first = true;
    for (const QString &key : orderedKeys(o)) {
        if (!first)
            out += separator;
        first = false;
        if (!flat)
            out += pad;
        out += scalarText(key) + ": ";
        writeValue(out, o.value(key), indent + 2);
    }
    out += flat ? QByteArray("}") : "\n" + QByteArray(indent, ' ') + "}";
}

} // namespace

std::string rebaseRelativePath(const std::string &path, const std::string &fromFolder,
                               const std::string &toFolder)
{
    if (path.empty() || QDir::isAbsolutePath(toQString(path)))
        return path;
    const std::string from = absoluteFolder(fromFolder);
    const std::string to = absoluteFolder(toFolder);
    if (from == to)
        return path;
    const QString target = QDir::cleanPath(QDir(toQString(from)).absoluteFilePath(toQString(path)));
    return QDir(toQString(to)).relativeFilePath(target).toStdString();
}

QJsonObject ProjectManifest::toJson(const Project &project, const std::string &targetFolder)
{
    // A project never saved has no folder yet: its paths are already relative to the target.
    const std::string from = project.folder().empty() ? targetFolder : project.folder();
    QJsonArray sequences;
    for (const Sequence &s : project.sequences) {
        QJsonObject o{{"id", toQString(s.id)},
                      {"mediaFile", toQString(rebaseRelativePath(s.mediaFile, from, targetFolder))},
                      {"frameRate", s.frameRate},
                      {"frameCount", s.frameCount},
                      {"transcript", toQString(s.transcript)},
                      {"tiers", QJsonObject{{"words", tierToJson(s.words)},
                                            {"phones", tierToJson(s.phones)}}}};
        if (s.transcriptProposed)
            o.insert("transcriptProposed", true);
        if (s.transcriptFit && std::isfinite(s.transcriptFit->value) && std::isfinite(s.transcriptFit->threshold)) {
            o.insert("transcriptFit", s.transcriptFit->value);
            o.insert("transcriptFitThreshold", s.transcriptFit->threshold);
        }
        if (!s.transcriptConfidence.empty()) {
            QJsonArray confidence;
            for (double c : s.transcriptConfidence)
                confidence.append(c);
            o.insert("transcriptConfidence", confidence);
        }
        if (s.firstFrameTime != 0.0)
            o.insert("firstFrameTime", s.firstFrameTime);
        if (!s.frameTimes.empty()) {
            QJsonArray times;
            for (double t : s.frameTimes)
                times.append(t);
            o.insert("frameTimes", times);
        }
        if (s.features.size() > 0)
            o.insert("features", toQString(featureFileName(s.id)));
        QJsonArray landmarks;
        for (const auto &[frame, set] : s.landmarks) {
            QJsonArray points;
            for (const LandmarkPoint &p : set.points)
                points.append(pointToJson(p));
            landmarks.append(QJsonObject{{"frame", frame}, {"points", points}});
        }
        o.insert("landmarks", landmarks);
        if (!s.fitErrors.empty()) {
            QJsonArray errors;
            for (double e : s.fitErrors)
                errors.append(e >= 0 ? QJsonValue(e) : QJsonValue(QJsonValue::Null));
            o.insert("fitErrors", errors);
        }
        sequences.append(o);
    }
    QJsonArray models;
    for (const ModelReference &m : project.models)
        models.append(QJsonObject{{"kind", toQString(m.kind)},
                                  {"name", toQString(m.name)},
                                  {"file", toQString(rebaseRelativePath(m.file, from, targetFolder))}});
    QJsonObject manifest{{"format", kFormatName},
                         {"version", Project::kFormatVersion},
                         {"name", toQString(project.name)},
                         {"sequences", sequences},
                         {"models", models}};
    if (project.study)
        manifest.insert("study", QString::fromLatin1(Project::kStudyFileName));
    if (!project.aligner.empty())
        manifest.insert("aligner", toQString(project.aligner));
    // Written only when there are some, so projects without overrides keep their manifest.
    if (!project.pronunciations.empty()) {
        QJsonArray pronunciations;
        for (const auto &[word, phones] : project.pronunciations)
            pronunciations.append(QJsonObject{{"word", toQString(word)}, {"phones", toQString(phones)}});
        manifest.insert("pronunciations", pronunciations);
    }
    if (!project.mouthShapes.empty()) {
        QJsonObject shapes;
        for (const auto &[letter, f] : project.mouthShapes)
            shapes.insert(toQString(letter), QJsonArray{f[0], f[1], f[2], f[3]});
        manifest.insert("mouthShapes", shapes);
    }
    return manifest;
}

QByteArray ProjectManifest::serialize(const QJsonObject &manifest)
{
    QByteArray out;
    writeValue(out, manifest, 0);
    out += '\n';
    return out;
}

Project ProjectManifest::parse(const QByteArray &text, const std::string &manifestPath,
                               const std::string &folder, bool readFeatures)
{
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(text, &error);
    if (error.error != QJsonParseError::NoError) {
        // Line and column are what an editor shows; QJsonParseError only has a byte offset.
        const QByteArray before = text.left(error.offset);
        const qsizetype line = before.count('\n') + 1;
        const qsizetype column = error.offset - (before.lastIndexOf('\n') + 1) + 1;
        throw Error("not valid JSON: " + error.errorString().toStdString(), manifestPath,
                    "line " + std::to_string(line) + ", column " + std::to_string(column));
    }
    if (!document.isObject())
        throw Error("must be a JSON object", manifestPath, "(top level)");
    return fromJson(document.object(), manifestPath, folder, readFeatures);
}

Project ProjectManifest::fromJson(const QJsonObject &manifest, const std::string &manifestPath,
                                  const std::string &folder, bool readFeatures)
{
    return Reader(manifestPath, folder, readFeatures).read(manifest);
}

} // namespace lipsync
