// lipsync align MEDIA --transcript FILE [--model MODEL] [--project DIR] [--pronunciations DICT]
//               [--adapt] --out FILE.TextGrid [--json]
// Forced alignment of one recording: writes a TextGrid with tiers "words" and "phones". Words
// are pronounced from the project's pronunciations (--project), a CMU-format file (--pronunciations,
// which wins), the CMU dictionary, then espeak-ng; --json lists the words espeak-ng guessed.
// --adapt first adapts the model to the recording's speaker (SpeakerAdaptation: MLLR + MAP of the
// means on the recording's own alignment, 3 passes), for voices unlike the model's training data.
#include "AlignerSupport.h"
#include "Command.h"

#include "align/AlignerUtterance.h"
#include "align/ForcedAligner.h"
#include "align/FrameLabels.h"
#include "align/SpeakerAdaptation.h"
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

int runAlign(const QStringList &args)
{
    const cli::Arguments a(args, cli::Arguments::defaultBooleanFlags() << QStringLiteral("adapt"));
    const QStringList unknown = a.unknown({"transcript", "model", "out", "json", "pronunciations", "project", "adapt"});
    if (!unknown.isEmpty())
        return cli::fail(QStringLiteral("align: unknown option %1").arg(unknown.join(' ')), 2);
    if (a.positional().size() != 1 || a.value("transcript").isEmpty() || a.value("out").isEmpty())
        return cli::fail(QStringLiteral("usage: lipsync align MEDIA --transcript FILE [--model MODEL] "
                                        "[--project DIR] [--pronunciations DICT] [--adapt] --out FILE.TextGrid [--json]"), 2);
    const QString media = a.positional().front();
    const QString modelPath = cli::alignerModelOrDefault(a.value("model"), QStringLiteral("align"));
    QElapsedTimer timer;
    timer.start();
    const AcousticModel model = AcousticModel::load(modelPath.toStdString());
    std::map<std::string, std::string> projectPronunciations;
    if (!a.value("project").isEmpty())
        projectPronunciations = Project::load(a.value("project").toStdString()).pronunciations;
    const auto lexicon = cli::makeLexicon(a.value("pronunciations"), projectPronunciations);
    const Transcript transcript = readTranscript(a.value("transcript").toStdString());
    const PreparedUtterance u = prepareUtterance(QFileInfo(media).completeBaseName().toStdString(),
                                                 media.toStdString(), transcript.words, model, *lexicon);
    AlignmentResult result;
    AdaptationReport adaptation;
    try {
        std::optional<AcousticModel> adapted;
        if (a.flag("adapt"))
            adapted = SpeakerAdaptation::adapt(model, u.pronunciations, u.features, {}, nullptr, &adaptation);
        result = ForcedAligner(adapted ? *adapted : model).align(u.features, u.words, u.pronunciations, u.duration);
    } catch (const Error &e) {
        throw Error(e.reason(), media.toStdString());
    }
    writeTextGrid(a.value("out").toStdString(), makeTextGrid({result.words, result.phones}, u.duration));
    const double seconds = timer.elapsed() / 1000.0;
    if (a.flag("json")) {
        // Per-video-frame phone labels (models.md §0 voting) when the media has video.
        QJsonArray frameLabels;
        double frameRate = 0;
        const MediaInfo info = MediaInfo::probe(media.toStdString());
        if (info.hasVideo && info.frameRate > 0) {
            frameRate = info.frameRate;
            for (const std::string &label : voteFrameLabels(result.phones, info.frameRate, info.frameCount,
                                                            model.featureOptions()))
                frameLabels.append(QString::fromStdString(label));
        }
        QJsonArray adaptationLogLikelihoods;
        for (double l : adaptation.logLikelihoodPerFrame)
            adaptationLogLikelihoods.append(l);
        QJsonArray guessed;
        for (const auto &[word, phones] : lexicon->guessed(u.words))
            guessed.append(QJsonObject{{QStringLiteral("word"), QString::fromStdString(word)},
                                       {QStringLiteral("phones"),
                                        QString::fromStdString(PronunciationDictionary::toString(phones))}});
        cli::printJson(QJsonObject{
            {QStringLiteral("guessed"), guessed},
            {QStringLiteral("adaptationLogLikelihoodPerFrame"), adaptationLogLikelihoods},
            {QStringLiteral("frameRate"), frameRate},
            {QStringLiteral("frameLabels"), frameLabels},
            {QStringLiteral("media"), media},
            {QStringLiteral("model"), modelPath},
            {QStringLiteral("out"), a.value("out")},
            {QStringLiteral("duration"), u.duration},
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
