// lipsync aligner adapt --media DIR --transcripts DIR --out MODEL [--model MODEL]
//                       [--pronunciations DICT] [--json]
// Adapts an aligner model (default: the shipped GRID s1 model) to one speaker from a folder of
// their transcribed recordings (SpeakerAdaptation: MLLR per regression class + MAP of the means,
// on the recordings' own alignments, 3 passes) and writes it as a model file for
// `align --model` or the studio ($LIPSYNC_ALIGNER_MODEL). Unlike `aligner train` it needs only
// a little speech (tens of seconds) and keeps what the model learnt elsewhere. Recordings that
// cannot be used are reported and skipped.
#include "AlignerSupport.h"
#include "Command.h"

#include "align/SpeakerAdaptation.h"

#include <QDir>
#include <QElapsedTimer>
#include <QJsonArray>

#include <cstdio>

using namespace lipsync;

namespace {

int runAlignerAdapt(const QStringList &args)
{
    const cli::Arguments a(args);
    const QStringList unknown = a.unknown({"media", "transcripts", "out", "model", "json", "pronunciations"});
    if (!unknown.isEmpty())
        return cli::fail(QStringLiteral("aligner adapt: unknown option %1").arg(unknown.join(' ')), 2);
    if (a.value("media").isEmpty() || a.value("transcripts").isEmpty() || a.value("out").isEmpty() || !a.positional().isEmpty())
        return cli::fail(QStringLiteral("usage: lipsync aligner adapt --media DIR --transcripts DIR --out MODEL "
                                        "[--model MODEL] [--pronunciations DICT] [--json]"), 2);
    const bool json = a.flag("json");
    for (const char *folder : {"media", "transcripts"})
        if (!QDir(a.value(folder)).exists())
            return cli::fail(QStringLiteral("%1: no such folder").arg(a.value(folder)));
    const QString modelPath = cli::alignerModelOrDefault(a.value("model"), QStringLiteral("aligner adapt"));
    QElapsedTimer timer;
    timer.start();
    const AcousticModel model = AcousticModel::load(modelPath.toStdString());
    const auto lexicon = cli::makeLexicon(a.value("pronunciations"));
    QJsonArray skipped;
    const std::vector<TrainingUtterance> utterances =
        cli::loadTranscribedFolder(a.value("media"), a.value("transcripts"), model, *lexicon, json, skipped);
    if (utterances.empty())
        return cli::fail(QStringLiteral("aligner adapt: no usable recordings in %1").arg(a.value("media")));
    double audioSeconds = 0;
    for (const TrainingUtterance &u : utterances)
        audioSeconds += u.features.rows() * model.featureOptions().shiftSeconds;
    AdaptationReport report;
    const AcousticModel adapted = SpeakerAdaptation::adapt(model, utterances, {}, nullptr, &report);
    adapted.save(a.value("out").toStdString());
    const double seconds = timer.elapsed() / 1000.0;
    if (json) {
        QJsonArray likelihood;
        for (double ll : report.logLikelihoodPerFrame)
            likelihood.append(ll);
        cli::printJson(QJsonObject{
            {QStringLiteral("model"), a.value("out")},
            {QStringLiteral("from"), modelPath},
            {QStringLiteral("utterances"), int(utterances.size())},
            {QStringLiteral("audioSeconds"), audioSeconds},
            {QStringLiteral("logLikelihoodPerFrame"), likelihood},
            {QStringLiteral("skipped"), skipped},
            {QStringLiteral("seconds"), seconds},
        });
    } else {
        std::printf("adapted %s to %zu recordings (%.1f s of audio; log-likelihood per frame %.2f -> %.2f) in %.1f s -> %s\n",
                    qPrintable(modelPath), utterances.size(), audioSeconds, report.logLikelihoodPerFrame.front(),
                    report.logLikelihoodPerFrame.back(), seconds, qPrintable(a.value("out")));
    }
    return 0;
}

const cli::CommandRegistration registration{QStringLiteral("aligner adapt"),
                                            QStringLiteral("adapt the aligner's model to a speaker from their transcribed recordings"),
                                            &runAlignerAdapt};

} // namespace
