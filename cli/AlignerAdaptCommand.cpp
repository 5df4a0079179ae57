// lipsync aligner adapt --media DIR --transcripts DIR --out MODEL [--aligner MODEL]
//                       [--pronunciations DICT] [--json]
// Adapts an aligner model (default: the shipped GRID s1 model) to one speaker from a folder of
// their transcribed recordings (SpeakerAdaptation: MLLR per regression class + MAP of the means,
// on the recordings' own alignments, 3 passes) and writes it as a model file for
// `--aligner` or the studio ($LIPSYNC_ALIGNER_MODEL). Unlike `aligner train` it needs only
// a little speech (tens of seconds) and keeps what the model learnt elsewhere. Recordings that
// cannot be used are reported and skipped.
#include "AlignerSupport.h"
#include "CommandLine.h"

#include "align/SpeakerAdaptation.h"

#include <QElapsedTimer>
#include <QJsonArray>

#include <cstdio>

using namespace lipsync;

namespace {

int runAlignerAdapt(const cli::CommandLine &a)
{
    const bool json = a.isSet("json");
    const QString modelPath = cli::alignerModelOrDefault(a.value("aligner"), QStringLiteral("aligner adapt"));
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
    const AcousticModel adapted = SpeakerAdaptation::adapt(model, utterances, {}, Feedback::none(), &report);
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

const cli::CommandRegistration registration{
    cli::CommandSpec{QStringLiteral("aligner adapt"),
     QStringLiteral("adapt the aligner's model to a speaker from their transcribed recordings"),
     QStringLiteral("Adapts an aligner model to one speaker from a folder of their transcribed recordings (MLLR per "
                    "regression class + MAP of the means, on the recordings' own alignments, 3 passes) and writes "
                    "it as a model file for --aligner or the studio ($LIPSYNC_ALIGNER_MODEL). Unlike `aligner "
                    "train` it needs only tens of seconds of speech and keeps what the model learnt elsewhere."),
     {{QStringLiteral("out"), QStringLiteral("MODEL"), QStringLiteral("the adapted aligner model to write"), {},
       cli::CommandOption::Required},
      {QStringLiteral("aligner"), QStringLiteral("MODEL"),
       QStringLiteral("the aligner model to adapt (default: the shipped GRID s1 model, or $LIPSYNC_ALIGNER_MODEL)"),
       {}, cli::CommandOption::Optional, {QStringLiteral("model")}}},
     {}}
        .add(cli::transcribedFolderOptions()),
    &runAlignerAdapt};

} // namespace
