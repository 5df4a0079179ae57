// lipsync align MEDIA --transcript FILE --out FILE.TextGrid [--aligner MODEL|sphinx[:DIR]] [--adapt]
//               [--project DIR] [--pronunciations DICT] [--json]
// lipsync align FOLDER|PROJECT --out DIR [--transcript DIR] [-j N] [--force] [...]
// Forced alignment of one recording: writes a TextGrid with tiers "words" and "phones". The aligner
// and the pronunciations are SpeechAligner's shared options (the same as `lipsync render`'s);
// --json adds per-video-frame labels and the words espeak-ng guessed. The folder form aligns every
// recording of a media folder or project into DIR/ID.TextGrid (BatchRunner), for `lipsync project
// import --alignments DIR`.
#include "BatchRunner.h"
#include "CommandLine.h"
#include "SpeechAligner.h"

#include "align/FrameLabels.h"
#include "align/Lexicon.h"
#include "io/MediaInfo.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "util/Error.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

#include <cmath>
#include <cstdio>
#include <optional>

using namespace lipsync;

namespace {

// How a transcript that does not fit its sound is met: a warning, or with --strict a refusal;
// below the aligner's own threshold (TranscriptFit) or --min-fit F.
struct FitCheck
{
    bool strict = false;
    std::optional<double> minimum;
};

FitCheck fitCheck(const cli::CommandLine &a)
{
    FitCheck check{a.isSet("strict"), std::nullopt};
    if (!a.isSet("min-fit"))
        return check;
    bool ok = false;
    const double fit = a.value("min-fit").toDouble(&ok);
    if (!ok || !(fit < 0))
        throw cli::UsageError(QStringLiteral("--min-fit must be a negative number (nats per frame)"));
    check.minimum = fit;
    return check;
}

QJsonArray tierJson(const Tier &tier)
{
    QJsonArray out;
    for (const Interval &i : tier.intervals)
        out.append(QJsonObject{{QStringLiteral("start"), i.start}, {QStringLiteral("end"), i.end},
                               {QStringLiteral("label"), QString::fromStdString(i.label)}});
    return out;
}

// Aligns `media` to `words` and writes the TextGrid `out`; the --json report of one recording.
// A transcript whose fit to the sound is below the threshold is taken not to be what the
// recording says: a warning naming the file, or with --strict an Error, nothing written.
QJsonObject alignOne(const cli::SpeechAligner &aligner, const QString &media, const std::vector<std::string> &words,
                     const QString &transcriptPath, const QString &out, Feedback &feedback, const FitCheck &check)
{
    QElapsedTimer timer;
    timer.start();
    const AlignerOutput aligned = aligner.align(media, words, transcriptPath, feedback);
    const AlignmentResult &result = aligned.alignment;
    std::optional<TranscriptFit> fit = aligned.transcriptFit;
    if (fit && check.minimum)
        fit->threshold = *check.minimum;
    if (transcriptMisfit(fit)) {
        const std::string file = (transcriptPath.isEmpty() ? media : transcriptPath).toStdString();
        if (check.strict)
            throw Error(fit->reason(), file);
        std::fprintf(stderr, "lipsync: warning: %s: %s; check the words (--strict refuses it)\n", file.c_str(),
                     fit->reason().c_str());
    }
    // Per-video-frame phone labels (docs/models.md §0 voting) when the media has a readable video
    // stream (the sound of a damaged video may still align).
    QJsonArray frameLabels;
    double frameRate = 0;
    MediaInfo info;
    try {
        info = MediaInfo::probe(media.toStdString());
    } catch (const Error &) {
        info.hasVideo = false;
    }
    if (info.hasVideo && info.frameRate > 0) {
        frameRate = info.frameRate;
        for (const std::string &label : voteFrameLabels(result.phones, info.frames, aligned.audioFrames))
            frameLabels.append(QString::fromStdString(label));
    }
    writeTextGrid(out.toStdString(), makeTextGrid({result.words, result.phones}, aligned.duration));
    QJsonArray adaptationLogLikelihoods;
    for (double l : aligned.adaptation.logLikelihoodPerFrame)
        adaptationLogLikelihoods.append(l);
    QJsonArray guessed;
    for (const auto &[word, phones] : aligner.lexicon().guessed(words))
        guessed.append(QJsonObject{{QStringLiteral("word"), QString::fromStdString(word)},
                                   {QStringLiteral("phones"), QString::fromStdString(PronunciationDictionary::toString(phones))}});
    return QJsonObject{
        {QStringLiteral("guessed"), guessed},
        {QStringLiteral("adaptationLogLikelihoodPerFrame"), adaptationLogLikelihoods},
        {QStringLiteral("frameRate"), frameRate},
        {QStringLiteral("frameLabels"), frameLabels},
        {QStringLiteral("media"), media},
        {QStringLiteral("model"), aligner.modelName()},
        {QStringLiteral("out"), out},
        {QStringLiteral("duration"), aligned.duration},
        {QStringLiteral("frames"), result.frames},
        {QStringLiteral("logLikelihood"), result.logLikelihood},
        {QStringLiteral("transcriptFit"), fit ? QJsonValue(fit->value) : QJsonValue()},
        {QStringLiteral("transcriptFitThreshold"), fit ? QJsonValue(fit->threshold) : QJsonValue()},
        {QStringLiteral("seconds"), timer.elapsed() / 1000.0},
        {QStringLiteral("wordCount"), int(words.size())},
        {QStringLiteral("words"), tierJson(result.words)},
        {QStringLiteral("phones"), tierJson(result.phones)},
    };
}

// Every recording of a media folder or a project, into `--out` DIR/ID.TextGrid.
int alignFolder(const cli::CommandLine &a, const cli::SpeechAligner &aligner)
{
    const QString folder = a.positional().front();
    const QString transcripts = a.value("transcript");
    if (!transcripts.isEmpty() && !QFileInfo(transcripts).isDir())
        throw cli::UsageError(QStringLiteral("with a folder to align, --transcript names the folder of the transcripts"));
    const QDir out = cli::batchOutputFolder(a);
    const std::vector<cli::BatchRecording> recordings = cli::batchRecordings(folder, transcripts);
    std::vector<cli::BatchJob> jobs;
    for (const cli::BatchRecording &r : recordings) {
        const QString transcript = r.transcriptFile.isEmpty() ? r.project : r.transcriptFile;
        jobs.push_back({r.id, r.media, {r.media, transcript, aligner.modelFile()}, out.filePath(r.id + ".TextGrid")});
    }
    cli::makeOutputsUnique(jobs);
    const cli::BatchRunner runner(a);
    const QJsonObject summary = runner.run(jobs, [&](const cli::BatchJob &job, Feedback &feedback) {
        const cli::BatchRecording &r = recordings[size_t(&job - jobs.data())];
        if (r.transcriptFile.isEmpty() && r.transcript.empty())
            throw Error(r.project.isEmpty() ? "no transcript of the same name (.align, .TextGrid, .lab, .txt, .srt, .vtt)"
                                            : "the sequence has no transcript",
                        r.media.toStdString());
        const std::vector<std::string> words = r.transcriptFile.isEmpty()
                                                   ? Lexicon::splitWords(r.transcript)
                                                   : readTranscript(r.transcriptFile.toStdString()).words;
        QJsonObject result =
            alignOne(aligner, r.media, words, r.transcriptFile, job.output, feedback, fitCheck(a));
        // The summary keeps what a project import needs, not every interval.
        for (const char *key : {"words", "phones", "frameLabels", "adaptationLogLikelihoodPerFrame"})
            result.remove(QLatin1String(key));
        return result;
    });
    return runner.finish(summary, QStringLiteral("aligned"));
}

int runAlign(const cli::CommandLine &a)
{
    // Every alignment's transcript is checked against its sound (TranscriptFit).
    // A project to align is also the project whose pronunciations and aligner are used, unless
    // --project names another.
    const QString input = a.positional().front();
    const bool isProject = !a.isSet("project") && QFileInfo::exists(QDir(input).filePath(Project::kManifestName));
    const cli::SpeechAligner aligner(a, isProject ? input : a.value(QStringLiteral("project")), true);
    if (cli::isBatchInput(a.positional().front()))
        return alignFolder(a, aligner);
    const QString media = a.positional().front();
    if (!a.isSet("transcript"))
        throw cli::UsageError(QStringLiteral("--transcript FILE is needed to align one recording"));
    const Transcript transcript = readTranscript(a.value("transcript").toStdString());
    const QJsonObject result =
        alignOne(aligner, media, transcript.words, a.value("transcript"), a.value("out"), Feedback::none(),
                 fitCheck(a));
    if (a.isSet("json")) {
        cli::printJson(result);
    } else {
        std::printf("aligned %zu words, %lld phones of %s in %.2f s -> %s\n", transcript.words.size(),
                    static_cast<long long>(result.value("phones").toArray().size()), qPrintable(media), result.value("seconds").toDouble(),
                    qPrintable(a.value("out")));
    }
    return 0;
}

const cli::CommandRegistration registration{
    cli::CommandSpec{
        QStringLiteral("align"),
        QStringLiteral("forced alignment of a recording to its transcript (TextGrid)"),
        QStringLiteral("Forced alignment of one recording to its transcript; writes a TextGrid with tiers \"words\" "
                       "and \"phones\". Words are pronounced from --pronunciations, the project's pronunciations "
                       "(--project), the CMU dictionary, then espeak-ng; --json lists the words espeak-ng guessed.\n"
                       "Given a folder of recordings (transcripts of the same name beside them, or in the folder "
                       "--transcript names) or a project folder, aligns every one in this process into --out "
                       "DIR/NAME.TextGrid, for `lipsync project import PROJECT --alignments DIR`: -j at a time, "
                       "skipping those whose TextGrid is newer than their media, transcript and aligner model, "
                       "with progress on stderr and a list of the failures at the end (exit code 1 if any)."),
        {{QStringLiteral("transcript"), QStringLiteral("FILE|DIR"),
          QStringLiteral("the words spoken (.align, .lab, .txt, a TextGrid words tier, or .srt/.vtt subtitles); "
                         "with a folder to align, the folder of the transcripts (default: beside the media)")},
         {QStringLiteral("out"), QStringLiteral("FILE.TextGrid|DIR"),
          QStringLiteral("the TextGrid to write; with a folder to align, the folder of the TextGrids"), {},
          cli::CommandOption::Required},
         {QStringLiteral("strict"), {},
          QStringLiteral("refuse a transcript that does not fit the sound (its transcriptFit below the aligner's "
                         "threshold or --min-fit: docs/pipeline.md), nothing written; without it, a warning")},
         {QStringLiteral("min-fit"), QStringLiteral("F"),
          QStringLiteral("the least transcript fit, nats per frame (default: the aligner's own, %1 for ours "
                         "trained on the speaker, %2 for CMU Sphinx's)")
              .arg(kTranscriptFitThreshold)
              .arg(kSphinxTranscriptFitThreshold)}},
        {{QStringLiteral("MEDIA"), QStringLiteral("the recording (any audio or video file with speech), or a folder of "
                                                  "them, or a project folder")}}}
        .add(cli::SpeechAligner::options({QStringLiteral("model")}))
        .add(cli::batchOptions()),
    &runAlign};

} // namespace
