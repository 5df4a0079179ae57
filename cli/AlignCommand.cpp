// lipsync align MEDIA --transcript FILE [--model MODEL | --model sphinx[:DIR]] [--project DIR]
//               [--pronunciations DICT] [--adapt] --out FILE.TextGrid [--json]
// Forced alignment of one recording: writes a TextGrid with tiers "words" and "phones". Words
// are pronounced from the project's pronunciations (--project), a CMU-format file (--pronunciations,
// which wins), the CMU dictionary, then espeak-ng; --json lists the words espeak-ng guessed.
// --adapt first adapts the model to the recording's speaker (SpeakerAdaptation: MLLR + MAP of the
// means on the recording's own alignment, 3 passes), for voices unlike the model's training data.
// --model sphinx aligns with CMU Sphinx's generic US-English model instead (SphinxAligner; the
// Debian model folder, or DIR); with --adapt, aligned, MLLR-adapted to the recording
// (SphinxAdaptation) and aligned again.
#include "AlignerSupport.h"
#include "Command.h"

#include "align/AlignerUtterance.h"
#include "align/ForcedAligner.h"
#include "align/FrameLabels.h"
#include "align/SpeakerAdaptation.h"
#include "align/SphinxAligner.h"
#include "io/MediaInfo.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

#include <cstdio>
#include <optional>

using namespace lipsync;

namespace {

QJsonArray tierJson(const Tier &tier)
{
    QJsonArray out;
    for (const Interval &i : tier.intervals)
        out.append(QJsonObject{{QStringLiteral("start"), i.start}, {QStringLiteral("end"), i.end},
                               {QStringLiteral("label"), QString::fromStdString(i.label)}});
    return out;
}

const char *kUsage =
    "usage: lipsync align MEDIA --transcript FILE [--model MODEL | --model sphinx[:DIR]] [--project DIR]\n"
    "                     [--pronunciations DICT] [--adapt] --out FILE.TextGrid [--json]\n"
    "Forced alignment of one recording to its transcript; writes a TextGrid with tiers \"words\" and \"phones\".\n"
    "  --model MODEL        an aligner model of ours (lipsync aligner train/adapt); default: the shipped\n"
    "                       GRID s1 model (one speaker)\n"
    "  --model sphinx[:DIR] CMU Sphinx's generic US-English triphone model (many speakers; Debian package\n"
    "                       pocketsphinx-en-us, BSD-2) at its Debian folder, or at DIR\n"
    "  --project DIR        pronounce words with the project's pronunciations first\n"
    "  --pronunciations DICT  a CMU-format dictionary that wins over all others\n"
    "  --adapt              adapt the model to the recording's speaker first (ours: MLLR + MAP, 3 passes;\n"
    "                       sphinx: one MLLR pass, about twice the time)\n"
    "  --json               print the tiers, per-video-frame labels and the words espeak-ng guessed\n";

// `--model sphinx` or `--model sphinx:DIR`: the model folder ("" = default); nullopt otherwise.
std::optional<std::string> sphinxModel(const QString &model)
{
    if (model == QLatin1String("sphinx"))
        return std::string();
    if (model.startsWith(QLatin1String("sphinx:")))
        return model.mid(7).toStdString();
    return std::nullopt;
}

int runAlign(const QStringList &args)
{
    const cli::Arguments a(args, cli::Arguments::defaultBooleanFlags() << QStringLiteral("adapt"));
    if (a.flag("help")) {
        std::fputs(kUsage, stdout);
        return 0;
    }
    const QStringList unknown = a.unknown({"transcript", "model", "out", "json", "pronunciations", "project", "adapt"});
    if (!unknown.isEmpty())
        return cli::fail(QStringLiteral("align: unknown option %1").arg(unknown.join(' ')), 2);
    if (a.positional().size() != 1 || a.value("transcript").isEmpty() || a.value("out").isEmpty())
        return cli::fail(QString::fromLatin1(kUsage).section(QLatin1Char('\n'), 0, 1).simplified(), 2);
    const std::optional<std::string> sphinxDir = sphinxModel(a.value("model"));
    const QString media = a.positional().front();
    QElapsedTimer timer;
    timer.start();
    std::optional<SphinxAligner> sphinx;
    std::optional<AcousticModel> model;
    QString modelName;
    if (sphinxDir) {
        sphinx.emplace(SphinxAligner::Options{*sphinxDir, {}, a.flag("adapt") ? 1 : 0});
        modelName = QStringLiteral("sphinx:") + QString::fromStdString(sphinx->modelDir());
    } else {
        modelName = cli::alignerModelOrDefault(a.value("model"), QStringLiteral("align"));
        model = AcousticModel::load(modelName.toStdString());
    }
    std::map<std::string, std::string> projectPronunciations;
    if (!a.value("project").isEmpty())
        projectPronunciations = Project::load(a.value("project").toStdString()).pronunciations;
    const auto lexicon = cli::makeLexicon(a.value("pronunciations"), projectPronunciations);
    const Transcript transcript = readTranscript(a.value("transcript").toStdString());
    AlignmentResult result;
    AdaptationReport adaptation;
    double duration = 0;
    if (sphinx) {
        // The CMU Sphinx model computes its own features from 16 kHz audio (decoded once); its
        // errors name the media file, and its tiers end with the audio.
        result = sphinx->align(media.toStdString(), transcript.words, *lexicon);
        duration = result.phones.intervals.back().end;
    } else {
        const PreparedUtterance u = prepareUtterance(QFileInfo(media).completeBaseName().toStdString(),
                                                     media.toStdString(), transcript.words, *model, *lexicon);
        duration = u.duration;
        try {
            std::optional<AcousticModel> adapted;
            if (a.flag("adapt"))
                adapted = SpeakerAdaptation::adapt(*model, u.pronunciations, u.features, {}, nullptr, &adaptation);
            result = ForcedAligner(adapted ? *adapted : *model).align(u.features, u.words, u.pronunciations, u.duration);
        } catch (const Error &e) {
            throw Error(e.reason(), media.toStdString());
        }
    }
    writeTextGrid(a.value("out").toStdString(), makeTextGrid({result.words, result.phones}, duration));
    const double seconds = timer.elapsed() / 1000.0;
    if (a.flag("json")) {
        // Per-video-frame phone labels (docs/models.md §0 voting) when the media has video.
        QJsonArray frameLabels;
        double frameRate = 0;
        const MediaInfo info = MediaInfo::probe(media.toStdString());
        if (info.hasVideo && info.frameRate > 0) {
            frameRate = info.frameRate;
            for (const std::string &label : voteFrameLabels(result.phones, info.frameRate, info.frameCount,
                                                            model ? model->featureOptions() : MfccOptions{}))
                frameLabels.append(QString::fromStdString(label));
        }
        QJsonArray adaptationLogLikelihoods;
        for (double l : adaptation.logLikelihoodPerFrame)
            adaptationLogLikelihoods.append(l);
        QJsonArray guessed;
        for (const auto &[word, phones] : lexicon->guessed(transcript.words))
            guessed.append(QJsonObject{{QStringLiteral("word"), QString::fromStdString(word)},
                                       {QStringLiteral("phones"),
                                        QString::fromStdString(PronunciationDictionary::toString(phones))}});
        cli::printJson(QJsonObject{
            {QStringLiteral("guessed"), guessed},
            {QStringLiteral("adaptationLogLikelihoodPerFrame"), adaptationLogLikelihoods},
            {QStringLiteral("frameRate"), frameRate},
            {QStringLiteral("frameLabels"), frameLabels},
            {QStringLiteral("media"), media},
            {QStringLiteral("model"), modelName},
            {QStringLiteral("out"), a.value("out")},
            {QStringLiteral("duration"), duration},
            {QStringLiteral("frames"), result.frames},
            {QStringLiteral("logLikelihood"), result.logLikelihood},
            {QStringLiteral("seconds"), seconds},
            {QStringLiteral("words"), tierJson(result.words)},
            {QStringLiteral("phones"), tierJson(result.phones)},
        });
    } else {
        std::printf("aligned %zu words, %zu phones of %s in %.2f s -> %s\n", transcript.words.size(),
                    result.phones.intervals.size(), qPrintable(media), seconds, qPrintable(a.value("out")));
    }
    return 0;
}

const cli::CommandRegistration registration{
    QStringLiteral("align"), QStringLiteral("forced alignment of a recording to its transcript (TextGrid)"), &runAlign};

} // namespace
