#include "AlignerSupport.h"

#include "align/AlignerUtterance.h"
#include "align/ShippedAlignerModel.h"
#include "io/MediaFolder.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QJsonObject>
#include <QtConcurrent/QtConcurrentMap>

#include <cstdio>
#include <optional>

namespace lipsync::cli {

QString defaultAlignerModel()
{
    return QString::fromStdString(shippedAlignerModelPath());
}

QString alignerModelOrDefault(const QString &given, const QString &command)
{
    if (!given.isEmpty())
        return given;
    const QString path = defaultAlignerModel();
    if (path.isEmpty())
        throw Error(command.toStdString() + ": no --model given and the shipped model "
                    "resources/aligner/grid-s1.aligner was not found (set LIPSYNC_ALIGNER_MODEL)");
    return path;
}

std::unique_ptr<Lexicon> makeLexicon(const QString &overridesPath,
                                     const std::map<std::string, std::string> &projectPronunciations)
{
    std::map<std::string, std::vector<Pronunciation>> overrides = Lexicon::parseOverrides(projectPronunciations);
    if (!overridesPath.isEmpty()) {
        const PronunciationDictionary user = PronunciationDictionary::read(overridesPath.toStdString());
        for (const auto &[word, variants] : user.entries())
            overrides[word] = variants;
    }
    return std::make_unique<Lexicon>(&PronunciationDictionary::cmu(), overrides);
}

CommandOption pronunciationsOption()
{
    return {QStringLiteral("pronunciations"), QStringLiteral("DICT"),
            QStringLiteral("a CMU-format dictionary (\"word PH ON EMES\") that wins over all other pronunciations "
                           "(a project's, the CMU dictionary, espeak-ng)")};
}

std::vector<CommandOption> transcribedFolderOptions()
{
    return {{QStringLiteral("media"), QStringLiteral("DIR"), QStringLiteral("the folder of recordings (audio or video)"),
             {}, CommandOption::Required},
            {QStringLiteral("transcripts"), QStringLiteral("DIR"),
             QStringLiteral("the folder of their transcripts, NAME.align, .TextGrid, .lab, .txt, .srt or .vtt for media NAME"), {},
             CommandOption::Required},
            pronunciationsOption()};
}

namespace {

struct Job
{
    QString id;
    QString media;
    QString transcript;
    std::optional<PreparedUtterance> prepared;
    Tier timing{"words", {}};
    QString error;
};

} // namespace

std::vector<TrainingUtterance> loadTranscribedFolder(const QString &mediaPath, const QString &transcriptPath,
                                                     const AcousticModel &model, const Lexicon &lexicon,
                                                     bool quiet, QJsonArray &skipped, int shard, int shards)
{
    std::vector<Job> jobs;
    // listMediaFolder names a missing media folder; a missing transcript folder is named here.
    if (!QDir(transcriptPath).exists())
        throw Error("no such folder", transcriptPath.toStdString());
    const std::vector<MediaFile> files = listMediaFolder(mediaPath.toStdString(), transcriptPath.toStdString());
    if (files.empty())
        throw Error("no media files (" + mediaExtensionList() + ")", mediaPath.toStdString());
    for (size_t i = size_t(shard); i < files.size(); i += size_t(std::max(1, shards))) {
        const MediaFile &file = files[i];
        Job job;
        job.id = QString::fromStdString(file.id);
        job.media = QString::fromStdString(file.path);
        job.transcript = QString::fromStdString(file.transcript);
        if (job.transcript.isEmpty())
            job.error = QStringLiteral("no transcript %1.{align,TextGrid,lab,txt,srt,vtt} in %2").arg(job.id, transcriptPath);
        jobs.push_back(std::move(job));
    }

    // Decoding and features in parallel; each failure stays with its recording.
    QtConcurrent::blockingMap(jobs, [&](Job &job) {
        if (!job.error.isEmpty())
            return;
        try {
            const Transcript t = readTranscript(job.transcript.toStdString());
            job.prepared = prepareUtterance(job.id.toStdString(), job.media.toStdString(), t.words, model, lexicon);
            job.timing = t.timing;
        } catch (const std::exception &e) {
            job.error = QString::fromUtf8(e.what());
        }
    });
    std::vector<TrainingUtterance> utterances;
    for (Job &job : jobs) {
        if (job.prepared) {
            utterances.push_back({job.prepared->id, std::move(job.prepared->features),
                                  std::move(job.prepared->pronunciations), std::move(job.timing)});
        } else {
            skipped.append(QJsonObject{{QStringLiteral("id"), job.id}, {QStringLiteral("reason"), job.error}});
            if (!quiet)
                std::fprintf(stderr, "lipsync: skipped %s: %s\n", qPrintable(job.id), qPrintable(job.error));
        }
    }
    return utterances;
}

} // namespace lipsync::cli
