#include "AlignerSupport.h"

#include "align/AlignerUtterance.h"
#include "align/ShippedAlignerModel.h"
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

QStringList alignerMediaFilters()
{
    return {QStringLiteral("*.mpg"), QStringLiteral("*.mp4"), QStringLiteral("*.mov"), QStringLiteral("*.avi"),
            QStringLiteral("*.mkv"), QStringLiteral("*.wav"), QStringLiteral("*.flac"), QStringLiteral("*.mp3"),
            QStringLiteral("*.ogg"), QStringLiteral("*.m4a")};
}

namespace {

QString findTranscript(const QDir &dir, const QString &stem)
{
    for (const std::string &ext : transcriptExtensions())
        for (const QString &candidate : dir.entryList({stem + QString::fromStdString(ext)}, QDir::Files))
            return dir.filePath(candidate); // entryList matches case-insensitively on the pattern
    return {};
}

struct Job
{
    QString id;
    QString media;
    QString transcript;
    std::optional<PreparedUtterance> prepared;
    QString error;
};

} // namespace

std::vector<TrainingUtterance> loadTranscribedFolder(const QString &mediaPath, const QString &transcriptPath,
                                                     const AcousticModel &model, const Lexicon &lexicon,
                                                     bool quiet, QJsonArray &skipped)
{
    const QDir mediaDir(mediaPath), transcriptDir(transcriptPath);
    std::vector<Job> jobs;
    for (const QString &name : mediaDir.entryList(alignerMediaFilters(), QDir::Files, QDir::Name)) {
        Job job;
        job.id = QFileInfo(name).completeBaseName();
        job.media = mediaDir.filePath(name);
        job.transcript = findTranscript(transcriptDir, job.id);
        if (job.transcript.isEmpty())
            job.error = QStringLiteral("no transcript %1.{align,TextGrid,lab,txt} in %2").arg(job.id, transcriptDir.path());
        jobs.push_back(std::move(job));
    }
    if (jobs.empty())
        throw Error("no media files", mediaDir.path().toStdString());
    // Decoding and features in parallel; each failure stays with its recording.
    QtConcurrent::blockingMap(jobs, [&](Job &job) {
        if (!job.error.isEmpty())
            return;
        try {
            const Transcript t = readTranscript(job.transcript.toStdString());
            job.prepared = prepareUtterance(job.id.toStdString(), job.media.toStdString(), t.words, model, lexicon);
        } catch (const std::exception &e) {
            job.error = QString::fromUtf8(e.what());
        }
    });
    std::vector<TrainingUtterance> utterances;
    for (Job &job : jobs) {
        if (job.prepared) {
            utterances.push_back({job.prepared->id, std::move(job.prepared->features), std::move(job.prepared->pronunciations)});
        } else {
            skipped.append(QJsonObject{{QStringLiteral("id"), job.id}, {QStringLiteral("reason"), job.error}});
            if (!quiet)
                std::fprintf(stderr, "lipsync: skipped %s: %s\n", qPrintable(job.id), qPrintable(job.error));
        }
    }
    return utterances;
}

} // namespace lipsync::cli
