// lipsync align MEDIA --transcript FILE --out FILE.TextGrid [--aligner MODEL|sphinx[:DIR]] [--adapt]
//               [--project DIR] [--pronunciations DICT] [--json]
// Forced alignment of one recording: writes a TextGrid with tiers "words" and "phones". The aligner
// and the pronunciations are SpeechAligner's shared options (the same as `lipsync render`'s);
// --json adds per-video-frame labels and the words espeak-ng guessed.
#include "CommandLine.h"
#include "SpeechAligner.h"

#include "align/FrameLabels.h"
#include "io/MediaInfo.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"

#include <QElapsedTimer>
#include <QJsonArray>

#include <cstdio>

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

int runAlign(const cli::CommandLine &a)
{
    const QString media = a.positional().front();
    QElapsedTimer timer;
    timer.start();
    const cli::SpeechAligner aligner(a);
    const Transcript transcript = readTranscript(a.value("transcript").toStdString());
    const AlignerOutput aligned = aligner.align(media, transcript.words, a.value("transcript"));
    const AlignmentResult &result = aligned.alignment;
    const double duration = aligned.duration;
    writeTextGrid(a.value("out").toStdString(), makeTextGrid({result.words, result.phones}, duration));
    const double seconds = timer.elapsed() / 1000.0;
    if (a.isSet("json")) {
        // Per-video-frame phone labels (docs/models.md §0 voting) when the media has video.
        QJsonArray frameLabels;
        double frameRate = 0;
        const MediaInfo info = MediaInfo::probe(media.toStdString());
        if (info.hasVideo && info.frameRate > 0) {
            frameRate = info.frameRate;
            for (const std::string &label :
                 voteFrameLabels(result.phones, info.frameRate, info.frameCount, aligned.audioFrames))
                frameLabels.append(QString::fromStdString(label));
        }
        QJsonArray adaptationLogLikelihoods;
        for (double l : aligned.adaptation.logLikelihoodPerFrame)
            adaptationLogLikelihoods.append(l);
        QJsonArray guessed;
        for (const auto &[word, phones] : aligner.lexicon().guessed(transcript.words))
            guessed.append(QJsonObject{{QStringLiteral("word"), QString::fromStdString(word)},
                                       {QStringLiteral("phones"),
                                        QString::fromStdString(PronunciationDictionary::toString(phones))}});
        cli::printJson(QJsonObject{
            {QStringLiteral("guessed"), guessed},
            {QStringLiteral("adaptationLogLikelihoodPerFrame"), adaptationLogLikelihoods},
            {QStringLiteral("frameRate"), frameRate},
            {QStringLiteral("frameLabels"), frameLabels},
            {QStringLiteral("media"), media},
            {QStringLiteral("model"), aligner.modelName()},
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
    cli::CommandSpec{
        QStringLiteral("align"),
        QStringLiteral("forced alignment of a recording to its transcript (TextGrid)"),
        QStringLiteral("Forced alignment of one recording to its transcript; writes a TextGrid with tiers \"words\" "
                       "and \"phones\". Words are pronounced from --pronunciations, the project's pronunciations "
                       "(--project), the CMU dictionary, then espeak-ng; --json lists the words espeak-ng guessed."),
        {{QStringLiteral("transcript"), QStringLiteral("FILE"),
          QStringLiteral("the words spoken (.align, .lab, .txt, a TextGrid words tier, or .srt/.vtt subtitles)"), {}, cli::CommandOption::Required},
         {QStringLiteral("out"), QStringLiteral("FILE.TextGrid"), QStringLiteral("the TextGrid to write"), {},
          cli::CommandOption::Required}},
        {{QStringLiteral("MEDIA"), QStringLiteral("the recording: any audio or video file with speech")}}}
        .add(cli::SpeechAligner::options({QStringLiteral("model")})),
    &runAlign};

} // namespace
