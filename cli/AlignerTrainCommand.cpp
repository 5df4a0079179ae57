// lipsync aligner train --media DIR --transcripts DIR --out MODEL [--mixtures N] [--iterations N]
//                       [--normalize none|mean|cmvn] [--pronunciations DICT] [--json]
// lipsync aligner train --accumulate-only [--model CURRENT] --media DIR --transcripts DIR --out PART.stats
// lipsync aligner train --merge DIR [--split-to N] --out MODEL
// Trains the aligner's monophone HMMs on transcribed recordings: every media file in DIR with a
// transcript of the same name (.align, .TextGrid, .lab, .txt, .srt or .vtt) in the transcripts folder.
// Recordings that cannot be used (no transcript, unknown words, undecodable or silent audio, a
// transcript that does not fit) are reported and skipped; the others train the model.
// By parts on many machines (AlignerTrainer, TrainingStatistics): each part's flat-start
// statistics (no --model) or Baum-Welch statistics under the current model, then one merge of a
// folder of parts into the next model (scripts/cluster/aligner-train drives the iterations).
#include "AlignerSupport.h"
#include "BatchRunner.h"
#include "CommandLine.h"

#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "align/TrainingStatistics.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

#include <cstdio>

using namespace lipsync;

namespace {

// --merge DIR: every *.stats file of the folder summed, and the next model made from them.
int mergeStatistics(const cli::CommandLine &a)
{
    const QDir dir(a.value("merge"));
    const QStringList parts = dir.entryList({QStringLiteral("*.stats")}, QDir::Files, QDir::Name);
    if (parts.isEmpty())
        throw Error("no training statistics (*.stats) to merge", dir.path().toStdString());
    TrainingStatistics total = readTrainingStatistics(dir.filePath(parts.front()).toStdString());
    for (qsizetype i = 1; i < parts.size(); ++i) {
        const std::string path = dir.filePath(parts[i]).toStdString();
        try {
            total.add(readTrainingStatistics(path));
        } catch (const Error &e) {
            throw Error(e.reason(), path);
        }
    }
    TrainerOptions options;
    options.features = total.model.featureOptions();
    options.normalization = total.model.normalization();
    AcousticModel model;
    double logLikelihood = 0;
    long long frames = 0;
    if (total.kind == TrainingStatistics::Kind::FlatStart) {
        model = AlignerTrainer::flatStart(total.flatStart, options);
        frames = total.flatStart.frames[0] + total.flatStart.frames[1];
    } else {
        model = total.model;
        std::vector<double> occupancy;
        logLikelihood = AlignerTrainer::update(model, *total.baumWelch, options, &occupancy);
        frames = total.baumWelch->frames;
        if (a.isSet("split-to"))
            AlignerTrainer::splitMixtures(model, a.integer("split-to", 1, 64), occupancy,
                                          options.minimumMixtureOccupancy * model.dimension());
    }
    model.save(a.value("out").toStdString());
    const QString kind = total.kind == TrainingStatistics::Kind::FlatStart ? QStringLiteral("flat start")
                                                                            : QStringLiteral("baum-welch");
    if (a.isSet("json"))
        cli::printJson(QJsonObject{{QStringLiteral("model"), a.value("out")},
                                   {QStringLiteral("kind"), kind},
                                   {QStringLiteral("parts"), int(parts.size())},
                                   {QStringLiteral("frames"), double(frames)},
                                   {QStringLiteral("logLikelihoodPerFrame"), logLikelihood}});
    else
        std::printf("merged %lld parts (%s, %lld frames) -> %s\n", (long long)parts.size(), qPrintable(kind), frames,
                    qPrintable(a.value("out")));
    return 0;
}

// The transcribed recordings of --media and --transcripts, features as `model` computes them.
std::vector<TrainingUtterance> loadFolder(const cli::CommandLine &a, const AcousticModel &model, QJsonArray &skipped)
{
    if (!a.isSet("media") || !a.isSet("transcripts"))
        throw cli::UsageError(QStringLiteral("--media DIR and --transcripts DIR name the recordings to train on"));
    const auto lexicon = cli::makeLexicon(a.value("pronunciations"));
    const cli::Shard shard = cli::shardOf(a);
    std::vector<TrainingUtterance> utterances = cli::loadTranscribedFolder(
        a.value("media"), a.value("transcripts"), model, *lexicon, a.isSet("json"), skipped, shard.index, shard.count);
    if (utterances.empty())
        throw Error("no usable recordings", a.value("media").toStdString());
    return utterances;
}

// --accumulate-only: this part's statistics (flat start, or Baum-Welch under --model).
int accumulateStatistics(const cli::CommandLine &a, const TrainerOptions &flatOptions)
{
    TrainingStatistics st;
    QJsonArray skipped, failed;
    TrainerOptions options = flatOptions;
    if (a.isSet("model")) {
        st.kind = TrainingStatistics::Kind::BaumWelch;
        st.model = AcousticModel::load(a.value("model").toStdString());
        options.features = st.model.featureOptions();
        options.normalization = st.model.normalization();
        const std::vector<TrainingUtterance> utterances = loadFolder(a, st.model, skipped);
        std::vector<std::string> didNotFit;
        st.baumWelch = AlignerTrainer::accumulate(st.model, utterances, options, &didNotFit);
        for (const std::string &id : didNotFit)
            failed.append(QString::fromStdString(id));
    } else {
        st.model = featureModel(options);
        st.flatStart = AlignerTrainer::flatStartStatistics(loadFolder(a, st.model, skipped), options);
    }
    writeTrainingStatistics(a.value("out").toStdString(), st);
    if (a.isSet("json"))
        cli::printJson(QJsonObject{{QStringLiteral("statistics"), a.value("out")},
                                   {QStringLiteral("kind"), a.isSet("model") ? QStringLiteral("baum-welch")
                                                                             : QStringLiteral("flat start")},
                                   {QStringLiteral("skipped"), skipped},
                                   {QStringLiteral("didNotFit"), failed}});
    else
        std::printf("statistics of %s -> %s\n", qPrintable(a.value("media")), qPrintable(a.value("out")));
    return 0;
}

int runAlignerTrain(const cli::CommandLine &a)
{
    if (a.isSet("merge") && a.isSet("accumulate-only"))
        throw cli::UsageError(QStringLiteral("--merge and --accumulate-only are two steps: one at a time"));
    if (a.isSet("merge"))
        return mergeStatistics(a);
    for (const char *option : {"model", "shard"})
        if (a.isSet(option) && !a.isSet("accumulate-only"))
            throw cli::UsageError(QStringLiteral("--%1 goes with --accumulate-only").arg(QLatin1String(option)));
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
    if (a.isSet("accumulate-only"))
        return accumulateStatistics(a, options);

    QElapsedTimer timer;
    timer.start();
    QJsonArray skipped;
    const std::vector<TrainingUtterance> utterances = loadFolder(a, featureModel(options), skipped);
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

// --media and --transcripts, not needed with --merge.
std::vector<cli::CommandOption> optionalFolderOptions()
{
    std::vector<cli::CommandOption> options = cli::transcribedFolderOptions();
    for (cli::CommandOption &o : options)
        o.presence = cli::CommandOption::Optional;
    return options;
}

const cli::CommandRegistration registration{
    cli::CommandSpec{QStringLiteral("aligner train"), QStringLiteral("train the forced aligner's phone HMMs on transcribed media"),
     QStringLiteral("Trains the aligner's monophone HMMs on transcribed recordings: every media file in the media "
                    "folder with a transcript of the same name (.align, .TextGrid, .lab, .txt, .srt or .vtt) in the "
                    "transcripts folder. Recordings that cannot be used are reported and skipped.\n"
                    "On many machines, as HTK's HERest -p: each machine writes the statistics of its part "
                    "(--accumulate-only: the flat start's without --model, one Baum-Welch pass's under --model), "
                    "then --merge sums a folder of them into the next model; scripts/cluster/aligner-train "
                    "runs the whole schedule that way."),
     {{QStringLiteral("out"), QStringLiteral("MODEL|PART.stats"),
       QStringLiteral("the aligner model to write (with --accumulate-only: the part's statistics)"), {},
       cli::CommandOption::Required},
      {QStringLiteral("accumulate-only"), {},
       QStringLiteral("write this part's training statistics instead of a model")},
      {QStringLiteral("model"), QStringLiteral("CURRENT"),
       QStringLiteral("with --accumulate-only: the model to collect Baum-Welch statistics under (without it: "
                      "the flat start's statistics)")},
      {QStringLiteral("merge"), QStringLiteral("DIR"),
       QStringLiteral("sum the statistics (*.stats) in DIR and write the next model (--out)")},
      {QStringLiteral("split-to"), QStringLiteral("N"),
       QStringLiteral("with --merge: then split every state's mixture to N Gaussians, as a new mixture stage "
                      "starts")},
      {QStringLiteral("mixtures"), QStringLiteral("N"), QStringLiteral("Gaussians per state (1..64)"), QStringLiteral("16")},
      {QStringLiteral("iterations"), QStringLiteral("N"), QStringLiteral("EM iterations per mixture stage (1..100)"),
       QStringLiteral("6")},
      {QStringLiteral("normalize"), QStringLiteral("none|mean|cmvn"),
       QStringLiteral("per-recording feature normalisation, stored in the model"), QStringLiteral("mean")}},
     {}}
        .add(optionalFolderOptions())
        .add({cli::shardOption()}),
    &runAlignerTrain};

} // namespace
