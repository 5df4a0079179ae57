// lipsync aligner train --media DIR --transcripts DIR --out MODEL [--mixtures N] [--iterations N]
//                       [--normalize none|mean|cmvn] [--pronunciations DICT] [--json]
// Trains the aligner's monophone HMMs on transcribed recordings: every media file in DIR with a
// transcript of the same name (.align, .TextGrid, .lab, .txt, .srt or .vtt) in the transcripts folder.
// Recordings that cannot be used (no transcript, unknown words, undecodable or silent audio, a
// transcript that does not fit) are reported and skipped; the others train the model.
#include "AlignerSupport.h"
#include "CommandLine.h"

#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

#include <cstdio>

using namespace lipsync;

namespace {

int runAlignerTrain(const cli::CommandLine &a)
{
    const bool json = a.isSet("json");
    TrainerOptions options;
    const int mixtures = a.integer("mixtures", 1, 64);
    options.mixtureSchedule = {1};
    while (options.mixtureSchedule.back() < mixtures)
        options.mixtureSchedule.push_back(std::min(mixtures, options.mixtureSchedule.back() * 2));
    const int iterations = a.integer("iterations", 1, 100);
    options.iterationsPerStage = iterations;
    options.firstStageIterations = iterations + 2;
    // Per-utterance feature normalisation, stored in the model (AcousticModel.h).
    const QString normalize = a.value("normalize");
    if (normalize == QLatin1String("none"))
        options.normalization = CepstralNormalization::None;
    else if (normalize == QLatin1String("mean"))
        options.normalization = CepstralNormalization::Mean;
    else if (normalize == QLatin1String("cmvn"))
        options.normalization = CepstralNormalization::MeanAndVariance;
    else
        throw cli::UsageError(QStringLiteral("--normalize must be none, mean or cmvn"));

    const QDir mediaDir(a.value("media")), transcriptDir(a.value("transcripts"));
    if (!mediaDir.exists())
        return cli::fail(QStringLiteral("%1: no such folder").arg(a.value("media")));
    if (!transcriptDir.exists())
        return cli::fail(QStringLiteral("%1: no such folder").arg(a.value("transcripts")));

    QElapsedTimer timer;
    timer.start();
    const auto lexicon = cli::makeLexicon(a.value("pronunciations"));
    const AcousticModel features = featureModel(options);
    QJsonArray skipped;
    std::vector<TrainingUtterance> utterances =
        cli::loadTranscribedFolder(mediaDir.path(), transcriptDir.path(), features, *lexicon, json, skipped);
    if (utterances.empty())
        return cli::fail(QStringLiteral("aligner train: no usable recordings in %1").arg(mediaDir.path()));
    const double prepareSeconds = timer.elapsed() / 1000.0;

    Feedback feedback;
    if (!json)
        feedback.onIteration = [](int iteration, double ll) {
            std::fprintf(stderr, "iteration %d: log-likelihood per frame %.4f\n", iteration + 1, ll);
        };
    TrainingReport report;
    const AcousticModel model = AlignerTrainer::train(utterances, options, feedback, &report);
    model.save(a.value("out").toStdString());
    const double seconds = timer.elapsed() / 1000.0;

    QJsonArray failed, likelihood;
    for (const std::string &id : report.failedUtterances)
        failed.append(QString::fromStdString(id));
    for (double ll : report.logLikelihoodPerFrame)
        likelihood.append(ll);
    if (json) {
        cli::printJson(QJsonObject{
            {QStringLiteral("model"), a.value("out")},
            {QStringLiteral("utterances"), int(utterances.size())},
            {QStringLiteral("frames"), double(report.frames)},
            {QStringLiteral("audioSeconds"), report.frames * options.features.shiftSeconds},
            {QStringLiteral("mixtures"), mixtures},
            {QStringLiteral("logLikelihoodPerFrame"), likelihood},
            {QStringLiteral("skipped"), skipped},
            {QStringLiteral("didNotFit"), failed},
            {QStringLiteral("prepareSeconds"), prepareSeconds},
            {QStringLiteral("seconds"), seconds},
        });
    } else {
        for (const std::string &id : report.failedUtterances)
            std::fprintf(stderr, "lipsync: %s: the transcript does not fit the audio (not used)\n", id.c_str());
        std::printf("trained on %zu recordings (%.1f min of audio, %lld skipped) in %.1f s -> %s\n", utterances.size(),
                    report.frames * options.features.shiftSeconds / 60.0, (long long)skipped.size(), seconds,
                    qPrintable(a.value("out")));
    }
    return 0;
}

const cli::CommandRegistration registration{
    cli::CommandSpec{QStringLiteral("aligner train"), QStringLiteral("train the forced aligner's phone HMMs on transcribed media"),
     QStringLiteral("Trains the aligner's monophone HMMs on transcribed recordings: every media file in the media "
                    "folder with a transcript of the same name (.align, .TextGrid, .lab, .txt, .srt or .vtt) in the "
                    "transcripts folder. Recordings that cannot be used are reported and skipped."),
     {{QStringLiteral("out"), QStringLiteral("MODEL"), QStringLiteral("the aligner model to write"), {},
       cli::CommandOption::Required},
      {QStringLiteral("mixtures"), QStringLiteral("N"), QStringLiteral("Gaussians per state (1..64)"), QStringLiteral("16")},
      {QStringLiteral("iterations"), QStringLiteral("N"), QStringLiteral("EM iterations per mixture stage (1..100)"),
       QStringLiteral("6")},
      {QStringLiteral("normalize"), QStringLiteral("none|mean|cmvn"),
       QStringLiteral("per-recording feature normalisation, stored in the model"), QStringLiteral("mean")}},
     {}}
        .add(cli::transcribedFolderOptions()),
    &runAlignerTrain};

} // namespace
