// `lipsync transcribe MEDIA --out FILE.txt` / `lipsync transcribe FOLDER|PROJECT --out DIR`: a
// proposed transcript for recordings that have none (SpeechRecognizer: CMU Sphinx's generic
// US-English model and language model), written as plain text for the user to correct, then to
// align (`project create` takes NAME.txt beside the clip). The folder form proposes one for every
// recording without a transcript (BatchRunner: -j, resumable, failures listed); given a project,
// its sequences get the proposals, marked as proposed (Sequence::transcriptProposed).
#include "BatchRunner.h"
#include "CommandLine.h"

#include "align/SpeechRecognizer.h"
#include "eval/Evaluation.h"
#include "io/Transcript.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/ObjectPool.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QJsonArray>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

// Recognizers for the worker threads: each holds a decoder with its language model (about a second
// to load) and decodes one recording at a time.
using RecognizerPool = ObjectPool<SpeechRecognizer>;

QJsonObject transcribeOne(RecognizerPool &pool, const QString &media, const QString &out, Feedback &feedback)
{
    QElapsedTimer timer;
    timer.start();
    const SpeechRecognizer::Result r = RecognizerPool::Lease(pool)->recognize(media.toStdString(), feedback);
    if (r.words.empty())
        throw Error("no speech recognised", media.toStdString());
    Transcript t;
    t.words = r.words;
    writePlainTranscript(out.toStdString(), t);
    QJsonArray timing;
    for (const Interval &i : r.timing.intervals)
        timing.append(QJsonObject{{QStringLiteral("start"), i.start}, {QStringLiteral("end"), i.end},
                                  {QStringLiteral("label"), QString::fromStdString(i.label)}});
    QStringList words;
    for (const std::string &w : r.words)
        words << QString::fromStdString(w);
    QJsonArray doubtful;
    for (int i : doubtfulWords(r))
        doubtful.append(QJsonObject{{QStringLiteral("index"), i},
                                    {QStringLiteral("word"), QString::fromStdString(r.words[size_t(i)])},
                                    {QStringLiteral("confidence"), r.confidence[size_t(i)]}});
    return QJsonObject{{QStringLiteral("media"), media},
                       {QStringLiteral("out"), out},
                       {QStringLiteral("transcript"), words.join(QLatin1Char(' '))},
                       {QStringLiteral("confidence"), jsonNumbers(r.confidence)},
                       {QStringLiteral("doubtful"), doubtful},
                       {QStringLiteral("verified"), false},
                       {QStringLiteral("timing"), timing},
                       {QStringLiteral("duration"), r.duration},
                       {QStringLiteral("seconds"), timer.elapsed() / 1000.0}};
}

int runTranscribe(const CommandLine &a)
{
    const std::string modelDir = a.value("model").toStdString();
    RecognizerPool pool([modelDir] { return std::make_unique<SpeechRecognizer>(modelDir); });
    pool.give(pool.take()); // a missing model fails here, once
    const QString input = a.positional().front();
    if (isBatchInput(input)) {
        const QDir out = batchOutputFolder(a);
        std::vector<BatchJob> jobs;
        QString manifest;
        for (const BatchRecording &r : batchRecordings(input))
            if (r.transcriptFile.isEmpty() && r.transcript.empty()) { // only those without words
                jobs.push_back({r.id, r.media, {r.media}, out.filePath(r.id + QStringLiteral(".txt"))});
                manifest = r.project;
            }
        makeOutputsUnique(jobs);
        const BatchRunner runner(a);
        const QJsonObject summary = runner.run(jobs, [&](const BatchJob &job, Feedback &feedback) {
            return transcribeOne(pool, job.file, job.output, feedback);
        });
        if (!manifest.isEmpty()) {
            // A project's sequences get their proposals, marked as such until someone checks them.
            Project project = Project::load(QFileInfo(manifest).absolutePath().toStdString());
            // Each word's posterior, from the job's result, kept with the proposal for review.
            std::map<QString, std::vector<double>> confidence;
            for (const QJsonValue &r : summary.value(QStringLiteral("results")).toArray()) {
                std::vector<double> c;
                for (const QJsonValue &v : r[QStringLiteral("confidence")].toArray())
                    c.push_back(v.isDouble() ? v.toDouble() : -1.0); // none: the proposal keeps no posteriors
                if (std::all_of(c.begin(), c.end(), [](double x) { return x >= 0 && x <= 1; }))
                    confidence[r[QStringLiteral("out")].toString()] = c;
            }
            int proposed = 0;
            for (const BatchJob &job : jobs)
                if (Sequence *s = project.sequence(job.name.toStdString());
                    s && s->transcript.empty() && QFileInfo::exists(job.output)) {
                    const Transcript proposal = readTranscript(job.output.toStdString());
                    s->transcript = proposal.text();
                    s->transcriptProposed = true;
                    if (const auto it = confidence.find(job.output);
                        it != confidence.end() && it->second.size() == proposal.words.size())
                        s->transcriptConfidence = it->second;
                    ++proposed;
                }
            if (proposed > 0)
                project.save();
        }
        return runner.finish(summary, QStringLiteral("transcribed"));
    }
    Feedback feedback;
    const QJsonObject result = transcribeOne(pool, input, a.value("out"), feedback);
    if (a.isSet("json"))
        printJson(result);
    else {
        std::printf("%s (proposed, check it) -> %s\n", qPrintable(result["transcript"].toString()),
                    qPrintable(a.value("out")));
        // The words to check first: the recogniser's least sure, the most doubtful first.
        QStringList doubtful;
        for (const QJsonValue &d : result["doubtful"].toArray())
            doubtful << QStringLiteral("%1 (%2)").arg(d["word"].toString()).arg(d["confidence"].toDouble(), 0, 'f', 2);
        if (!doubtful.isEmpty())
            std::printf("doubtful: %s\n", qPrintable(doubtful.join(QStringLiteral(", "))));
    }
    return 0;
}

const CommandRegistration registration{
    CommandSpec{QStringLiteral("transcribe"),
                QStringLiteral("propose a transcript for a recording that has none (CMU Sphinx's US-English models)"),
                QStringLiteral("Decodes the speech with CMU Sphinx's generic US-English acoustic and language models "
                               "(Debian package pocketsphinx-en-us) and writes the words as a plain transcript: a "
                               "proposal to check and correct before aligning with it, not a reference. Recordings "
                               "up to 2 minutes.\nGiven a folder of recordings or a project folder, proposes a "
                               "transcript for each one that has none (no transcript of the same name beside it, "
                               "or an empty one in the project) into --out DIR/NAME.txt, -j at a time; a project's "
                               "sequences also get them, marked as proposed (unverified in the studio until edited "
                               "or accepted)."),
                {{QStringLiteral("out"), QStringLiteral("FILE.txt|DIR"),
                  QStringLiteral("the transcript to write; with a folder, the folder of the transcripts"), {},
                  CommandOption::Required},
                 {QStringLiteral("model"), QStringLiteral("DIR"),
                  QStringLiteral("CMU Sphinx's en-us acoustic model folder, its language model and dictionary beside "
                                 "it (default: Debian's, or $LIPSYNC_SPHINX_MODEL)")}},
                {{QStringLiteral("MEDIA"), QStringLiteral("the recording, or a folder of them, or a project folder")}}}
        .add(batchOptions()),
    &runTranscribe};

} // namespace
