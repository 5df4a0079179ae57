// lipsync info PATH [--json]: what a media file, a project folder, an AAM or a model file holds.
//   media file:     frames, fps, duration, size, audio rate/channels/duration (decoded counts)
//   project folder: its sequences (count, total frames and duration, per sequence id/frames/fps)
//   AAM (.aam):     points, modes (shape, texture, combined), texture pixels, training images
//   dynamic model:  kind, dimension, states, frame rate, compensation, prior, the AAM it is for,
//                   the aligner of its training phones
// The kind of a file is read from its first bytes (an AAM's magic, a model's JSON), never
// from its name: FFmpeg takes almost any bytes for some audio format. Bad input (missing, empty,
// truncated, unsupported) exits 1 with one line naming the file.
#include "CommandLine.h"

#include "aam/AamModel.h"
#include "dynamics/ContextDependentModel.h"
#include "dynamics/ModelFile.h"
#include "io/MediaInfo.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QTextStream>

#include <cmath>
#include <cstdio>

namespace {

using lipsync::cli::fail;
using lipsync::cli::printJson;

QString number(double value, int decimals)
{
    return QString::number(value, 'f', decimals);
}

// Seven significant digits: 25 -> "25", NTSC's 30000/1001 -> "29.97003", told apart from a
// container's rounded 29.97.
QString rate(double fps)
{
    return QString::number(fps, 'g', 7);
}

void printRows(const QList<QPair<QString, QString>> &rows)
{
    int width = 0;
    for (const auto &row : rows)
        width = std::max(width, int(row.first.size()));
    QTextStream out(stdout);
    for (const auto &row : rows)
        out << row.first.leftJustified(width + 2) << row.second << '\n';
}

int infoMedia(const QString &path, bool json)
{
    const lipsync::MediaInfo info = lipsync::MediaInfo::probe(path.toStdString());
    const double duration = info.hasVideo ? info.videoDuration : info.audioDuration;
    if (json) {
        QJsonObject o;
        o[QStringLiteral("path")] = path;
        o[QStringLiteral("kind")] = QStringLiteral("media");
        o[QStringLiteral("format")] = QString::fromStdString(info.format);
        o[QStringLiteral("has_video")] = info.hasVideo;
        o[QStringLiteral("frames")] = info.frameCount;
        o[QStringLiteral("fps")] = info.frameRate;
        o[QStringLiteral("duration")] = duration;
        o[QStringLiteral("width")] = info.width;
        o[QStringLiteral("height")] = info.height;
        o[QStringLiteral("video_codec")] = QString::fromStdString(info.videoCodec);
        o[QStringLiteral("has_audio")] = info.hasAudio;
        o[QStringLiteral("audio_rate")] = info.audioSampleRate;
        o[QStringLiteral("audio_channels")] = info.audioChannels;
        o[QStringLiteral("audio_duration")] = info.audioDuration;
        o[QStringLiteral("audio_codec")] = QString::fromStdString(info.audioCodec);
        // The media timeline (seconds from the file's start, as a player presents it).
        if (info.hasVideo) {
            o[QStringLiteral("fps_fraction")] = QStringLiteral("%1/%2").arg(info.frameRateNum).arg(info.frameRateDen);
            o[QStringLiteral("variable_frame_rate")] = info.variableFrameRate;
            o[QStringLiteral("video_start")] = info.videoStartTime();
            o[QStringLiteral("video_end")] = info.videoEndTime();
        }
        if (info.hasAudio) {
            o[QStringLiteral("audio_start")] = info.audioStartTime;
            o[QStringLiteral("audio_end")] = info.audioEndTime;
            o[QStringLiteral("audio_gaps")] = info.audioGaps;
            o[QStringLiteral("audio_gap_seconds")] = info.audioGapSeconds;
            o[QStringLiteral("audio_overlaps")] = info.audioOverlaps;
            o[QStringLiteral("audio_overlap_seconds")] = info.audioOverlapSeconds;
            o[QStringLiteral("audio_discontinuities")] = info.audioDiscontinuities;
            QJsonArray gaps;
            for (const lipsync::AudioGap &g : info.audioGapList)
                gaps.append(QJsonObject{{QStringLiteral("at"), g.at}, {QStringLiteral("length"), g.length}});
            o[QStringLiteral("audio_gap_list")] = gaps;
        }
        if (info.hasAudio && info.hasVideo) {
            o[QStringLiteral("audio_video_start_difference")] = info.audioStartTime - info.videoStartTime();
            o[QStringLiteral("audio_video_end_difference")] = info.audioVideoEndDifference();
        }
        printJson(o);
        return 0;
    }
    QList<QPair<QString, QString>> rows;
    rows << qMakePair(QStringLiteral("path"), path);
    rows << qMakePair(QStringLiteral("kind"),
                      QStringLiteral("media (%1)").arg(QString::fromStdString(info.format)));
    if (info.hasVideo) {
        rows << qMakePair(QStringLiteral("frames"), QString::number(info.frameCount));
        rows << qMakePair(QStringLiteral("fps"),
                          rate(info.frameRate)
                              + (info.frameRateDen > 1 ? QStringLiteral(" (%1/%2)").arg(info.frameRateNum).arg(info.frameRateDen)
                                                       : QString())
                              + (info.variableFrameRate ? QStringLiteral(", variable") : QString()));
        rows << qMakePair(QStringLiteral("duration"), number(duration, 3) + QStringLiteral(" s"));
        rows << qMakePair(QStringLiteral("size"),
                          QStringLiteral("%1 x %2").arg(info.width).arg(info.height));
        rows << qMakePair(QStringLiteral("video codec"), QString::fromStdString(info.videoCodec));
        rows << qMakePair(QStringLiteral("video from"), QStringLiteral("%1 to %2 s").arg(number(info.videoStartTime(), 3),
                                                                                     number(info.videoEndTime(), 3)));
    } else {
        rows << qMakePair(QStringLiteral("video"), QStringLiteral("none"));
    }
    if (info.hasAudio) {
        rows << qMakePair(QStringLiteral("audio rate"),
                          QStringLiteral("%1 Hz").arg(info.audioSampleRate));
        rows << qMakePair(QStringLiteral("audio channels"), QString::number(info.audioChannels));
        rows << qMakePair(QStringLiteral("audio duration"),
                          number(info.audioDuration, 3) + QStringLiteral(" s"));
        rows << qMakePair(QStringLiteral("audio codec"), QString::fromStdString(info.audioCodec));
        rows << qMakePair(QStringLiteral("audio from"), QStringLiteral("%1 to %2 s").arg(number(info.audioStartTime, 3),
                                                                                     number(info.audioEndTime, 3)));
        if (info.audioGaps > 0)
            rows << qMakePair(QStringLiteral("audio gaps"), QStringLiteral("%1, %2 s of silence filled")
                                                                .arg(info.audioGaps)
                                                                .arg(number(info.audioGapSeconds, 3)));
        if (info.audioOverlaps > 0)
            rows << qMakePair(QStringLiteral("audio overlaps"), QStringLiteral("%1, %2 s dropped")
                                                                    .arg(info.audioOverlaps)
                                                                    .arg(number(info.audioOverlapSeconds, 3)));
        if (info.audioDiscontinuities > 0)
            rows << qMakePair(QStringLiteral("audio jumps"),
                              QStringLiteral("%1 timestamp jumps past the end, not filled").arg(info.audioDiscontinuities));
        if (info.hasVideo) {
            const double start = info.audioStartTime - info.videoStartTime();
            const double end = info.audioVideoEndDifference();
            rows << qMakePair(QStringLiteral("audio vs video"),
                              QStringLiteral("starts %1 s %2, ends %3 s %4")
                                  .arg(number(std::abs(start), 3), start >= 0 ? QStringLiteral("later") : QStringLiteral("earlier"),
                                       number(std::abs(end), 3), end >= 0 ? QStringLiteral("later") : QStringLiteral("earlier")));
        }
    } else {
        rows << qMakePair(QStringLiteral("audio"), QStringLiteral("none"));
    }
    printRows(rows);
    return 0;
}

// Prints the path, the kind and `facts` as aligned rows, or as one JSON object whose keys are
// the facts' names in snake case.
int printFacts(const QString &path, const QString &kind, const QList<QPair<QString, QJsonValue>> &facts, bool json)
{
    if (json) {
        QJsonObject o;
        o[QStringLiteral("path")] = path;
        o[QStringLiteral("kind")] = kind;
        for (const auto &[key, value] : facts)
            o[QString(key).replace(QLatin1Char(' '), QLatin1Char('_'))] = value;
        printJson(o);
        return 0;
    }
    QList<QPair<QString, QString>> rows{{QStringLiteral("path"), path}, {QStringLiteral("kind"), kind}};
    for (const auto &[key, value] : facts)
        rows << qMakePair(key, value.isString() ? value.toString()
                               : value.isBool() ? (value.toBool() ? QStringLiteral("yes") : QStringLiteral("no"))
                               : value.isNull() ? QStringLiteral("-")
                                                : QString::number(value.toDouble(), 'g', 6));
    printRows(rows);
    return 0;
}

int infoAam(const QString &path, bool json)
{
    const lipsync::AamModel aam = lipsync::AamModel::load(path.toStdString());
    return printFacts(path, QStringLiteral("aam"),
                      {{QStringLiteral("identifier"), QString::fromStdString(aam.identifier)},
                       {QStringLiteral("points"), aam.pointCount()},
                       {QStringLiteral("shape modes"), aam.shapeModes()},
                       {QStringLiteral("texture modes"), aam.textureModes()},
                       {QStringLiteral("combined modes"), aam.combinedModes()},
                       {QStringLiteral("texture pixels"), int(aam.textureMean.size() / 3)},
                       {QStringLiteral("reference scale"), aam.referenceScale},
                       {QStringLiteral("training images"), aam.trainingImages},
                       {QStringLiteral("exemplars"), aam.exemplarCount()},
                       {QStringLiteral("fit features"), aam.fitFeatures == lipsync::AamFitFeatures::Grey
                                                            ? QStringLiteral("grey")
                                                            : QStringLiteral("gradient orientation")}},
                      json);
}

// "sphinx", "shipped" (GRID s1's) or the aligner model's path, with " adapted"; null: not recorded.
QJsonValue trainingAligner(const lipsync::DynamicModel &model)
{
    const std::optional<lipsync::AlignerChoice> &aligner = model.trainingAligner();
    if (!aligner)
        return {};
    const QString name = aligner->model.empty() ? QStringLiteral("shipped") : QString::fromStdString(aligner->model);
    return aligner->adapt ? name + QStringLiteral(" adapted") : name;
}

int infoModel(const QString &path, bool json)
{
    std::string aamId;
    const std::unique_ptr<lipsync::DynamicModel> model = lipsync::loadModel(path.toStdString(), {}, &aamId);
    const auto *context = dynamic_cast<const lipsync::ContextDependentModel *>(model.get());
    return printFacts(path, QStringLiteral("model"),
                      {{QStringLiteral("model kind"), QString::fromStdString(model->kind())},
                       {QStringLiteral("dimension"), model->dimension()},
                       // Phones in context: the tied states of the trees (§5.2), else one per phone.
                       {QStringLiteral("states"), context ? context->inner().stateCount() : model->stateCount()},
                       {QStringLiteral("phones in context"), context != nullptr},
                       {QStringLiteral("variance compensation"), model->compensatesVariance()},
                       // Whether its means started from other speakers' mouths (§5.4).
                       {QStringLiteral("prior"), model->startedFromOtherSpeakers()},
                       // And how much they weighed, in frames (0: not recorded).
                       {QStringLiteral("prior weight"), model->startedFromOtherSpeakers()
                                                            ? QJsonValue(model->priorWeight())
                                                            : QJsonValue()},
                       {QStringLiteral("fps"), model->frameRate() > 0 ? QJsonValue(model->frameRate()) : QJsonValue()},
                       {QStringLiteral("aam"), QString::fromStdString(aamId)},
                       // What aligned its training phones, and so new speech for it (render).
                       {QStringLiteral("aligner"), trainingAligner(*model)}},
                      json);
}

// What the file's first bytes say it is: "aam", "model" (JSON) or "" (anything else: media).
QString fileKind(const QString &path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    const QByteArray head = file.read(256);
    if (lipsync::AamModel::hasMagic(std::string_view(head.constData(), size_t(head.size()))))
        return QStringLiteral("aam");
    // JSON is never media; model files are the JSON `info` reads (loadModel names other JSON).
    if (head.trimmed().startsWith('{'))
        return QStringLiteral("model");
    return {};
}

int infoProject(const QString &path, bool json)
{
    const lipsync::Project project = lipsync::Project::load(path.toStdString());
    long long totalFrames = 0;
    double totalDuration = 0.0;
    double commonRate = -1.0; // -1: none yet, 0: mixed
    double lowestRate = 0.0, highestRate = 0.0;
    for (const lipsync::Sequence &s : project.sequences) {
        lowestRate = lowestRate > 0 ? std::min(lowestRate, s.frameRate) : s.frameRate;
        highestRate = std::max(highestRate, s.frameRate);
        totalFrames += s.frameCount;
        totalDuration += s.duration();
        if (commonRate < 0)
            commonRate = s.frameRate;
        else if (std::abs(commonRate - s.frameRate) > 1e-9)
            commonRate = 0.0;
    }

    if (json) {
        QJsonArray sequences;
        for (const lipsync::Sequence &s : project.sequences) {
            QJsonObject o;
            o[QStringLiteral("id")] = QString::fromStdString(s.id);
            o[QStringLiteral("media")] = QString::fromStdString(s.mediaFile);
            o[QStringLiteral("frames")] = s.frameCount;
            o[QStringLiteral("fps")] = s.frameRate;
            o[QStringLiteral("duration")] = s.duration();
            o[QStringLiteral("transcript")] = QString::fromStdString(s.transcript);
            sequences.append(o);
        }
        QJsonObject o;
        o[QStringLiteral("path")] = path;
        o[QStringLiteral("kind")] = QStringLiteral("project");
        o[QStringLiteral("name")] = QString::fromStdString(project.name);
        o[QStringLiteral("sequence_count")] = int(project.sequences.size());
        o[QStringLiteral("frames")] = double(totalFrames);
        // The frame rate the sequences share, null when they differ or there are none.
        o[QStringLiteral("fps")] = commonRate > 0 ? QJsonValue(commonRate) : QJsonValue();
        o[QStringLiteral("duration")] = totalDuration;
        // Media-level facts are per sequence (run `lipsync info` on a sequence's media file).
        for (const char *key : {"width", "height", "audio_rate", "audio_channels",
                                "audio_duration", "has_audio"})
            o[QLatin1String(key)] = QJsonValue();
        o[QStringLiteral("sequences")] = sequences;
        printJson(o);
        return 0;
    }

    QList<QPair<QString, QString>> rows;
    rows << qMakePair(QStringLiteral("path"), path);
    rows << qMakePair(QStringLiteral("kind"),
                      project.name.empty()
                          ? QStringLiteral("project")
                          : QStringLiteral("project \"%1\"").arg(QString::fromStdString(project.name)));
    rows << qMakePair(QStringLiteral("sequences"), QString::number(project.sequences.size()));
    rows << qMakePair(QStringLiteral("frames"), QString::number(totalFrames));
    rows << qMakePair(QStringLiteral("fps"),
                      commonRate > 0 ? rate(commonRate)
                                     : (commonRate == 0
                                            ? QStringLiteral("mixed, %1 to %2").arg(rate(lowestRate), rate(highestRate))
                                            : QStringLiteral("-")));
    rows << qMakePair(QStringLiteral("duration"), number(totalDuration, 3) + QStringLiteral(" s"));
    printRows(rows);
    if (project.sequences.empty())
        return 0;

    // Sequence table.
    int idWidth = 2;
    for (const lipsync::Sequence &s : project.sequences)
        idWidth = std::max(idWidth, int(s.id.size()));
    QTextStream out(stdout);
    out << '\n'
        << QStringLiteral("id").leftJustified(idWidth + 2) << QStringLiteral("frames").rightJustified(7)
        << QStringLiteral("fps").rightJustified(9) << QStringLiteral("duration").rightJustified(11)
        << QStringLiteral("  media") << '\n';
    for (const lipsync::Sequence &s : project.sequences)
        out << QString::fromStdString(s.id).leftJustified(idWidth + 2)
            << QString::number(s.frameCount).rightJustified(7) << rate(s.frameRate).rightJustified(9)
            << (number(s.duration(), 3) + QStringLiteral(" s")).rightJustified(11) << QStringLiteral("  ")
            << QString::fromStdString(s.mediaFile) << '\n';
    return 0;
}

int runInfo(const lipsync::cli::CommandLine &arguments)
{
    const QString path = arguments.positional(0);
    const bool json = arguments.isSet(QStringLiteral("json"));
    try {
        const QFileInfo file(path);
        if (!file.exists())
            return fail(QStringLiteral("%1: file not found").arg(path));
        if (file.isDir()) {
            if (!QFileInfo::exists(QDir(path).filePath(QString::fromLatin1(lipsync::Project::kManifestName))))
                return fail(QStringLiteral("%1: a folder without %2 (neither a media file nor a project)")
                                .arg(path, QString::fromLatin1(lipsync::Project::kManifestName)));
            return infoProject(path, json);
        }
        if (file.fileName() == QLatin1String(lipsync::Project::kManifestName))
            return infoProject(file.absolutePath(), json);
        const QString kind = fileKind(path);
        if (kind == QLatin1String("aam"))
            return infoAam(path, json);
        if (kind == QLatin1String("model"))
            return infoModel(path, json);
        return infoMedia(path, json);
    } catch (const lipsync::Error &e) {
        return fail(QString::fromUtf8(e.what()));
    }
}

const lipsync::cli::CommandRegistration registration{
    {QStringLiteral("info"),
     QStringLiteral("summary of a media file, project, AAM or model (frames, fps, audio, modes)"),
     QStringLiteral("What a media file, a project folder, an AAM or a dynamic model holds. A media file: frames, "
                    "fps, duration, size, audio rate, channels and duration (decoded counts). A project folder (or "
                    "its project.json): its sequences, their frames and frame rates. An AAM: its points, shape, "
                    "texture and combined modes, texture pixels and training images. A model file: its kind, "
                    "dimension, states, frame rate, compensation, whether it started from other speakers (prior) and the AAM it generates parameters of."),
     {},
     {{QStringLiteral("PATH"), QStringLiteral("a media file, a project folder or its project.json, an AAM or a model "
                                              "file")}}},
    &runInfo};

} // namespace
