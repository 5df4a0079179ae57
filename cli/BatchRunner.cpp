#include "BatchRunner.h"

#include "CommandLine.h"

#include "io/MediaFolder.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QSet>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <thread>

#include <unistd.h>

namespace lipsync::cli {

namespace {

// Whether `job`'s output exists and is newer than each of its inputs.
bool upToDate(const BatchJob &job)
{
    const QFileInfo out(job.output);
    if (!out.isFile())
        return false;
    const QDateTime written = out.lastModified();
    return std::all_of(job.inputs.begin(), job.inputs.end(), [&](const QString &input) {
        const QFileInfo in(input);
        return in.exists() && in.lastModified() <= written;
    });
}

QString clock(double seconds)
{
    const int s = int(seconds + 0.5);
    return s >= 3600 ? QStringLiteral("%1:%2:%3").arg(s / 3600).arg(s / 60 % 60, 2, 10, QLatin1Char('0')).arg(s % 60, 2, 10, QLatin1Char('0'))
                     : QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'));
}

// Progress on stderr: on a terminal one line redrawn in place (a bar, counts, the ETA from the
// jobs done so far, the last job); otherwise one line per finished job.
class Progress
{
public:
    Progress(int total, int skipped)
        : m_total(total), m_finished(skipped), m_terminal(isatty(fileno(stderr)) != 0),
          m_start(std::chrono::steady_clock::now())
    {
    }

    void finished(const QString &name, const QString &problem)
    {
        const std::lock_guard lock(m_mutex);
        ++m_finished;
        ++m_run;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count();
        const double eta = elapsed / m_run * (m_total - m_finished);
        const QString counts = QStringLiteral("%1/%2").arg(m_finished).arg(m_total);
        if (!m_terminal) {
            std::fprintf(stderr, "[%s] %s%s\n", qPrintable(counts), qPrintable(name),
                         problem.isEmpty() ? "" : qPrintable(QStringLiteral(": failed: ") + problem));
            return;
        }
        if (!problem.isEmpty())
            std::fprintf(stderr, "\r\033[K%s: failed: %s\n", qPrintable(name), qPrintable(problem));
        constexpr int kWidth = 30;
        const int filled = m_total > 0 ? kWidth * m_finished / m_total : kWidth;
        const QString bar = QString(filled, QLatin1Char('=')) + QString(kWidth - filled, QLatin1Char(' '));
        std::fprintf(stderr, "\r\033[K[%s] %s  %3d %%  ETA %s  %s", qPrintable(bar), qPrintable(counts),
                     m_total > 0 ? 100 * m_finished / m_total : 100, qPrintable(clock(eta)), qPrintable(name));
        if (m_finished == m_total)
            std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }

private:
    std::mutex m_mutex;
    const int m_total;
    int m_finished; // skipped ones included
    int m_run = 0;  // jobs run in this process
    const bool m_terminal;
    const std::chrono::steady_clock::time_point m_start;
};

} // namespace

void makeOutputsUnique(std::vector<BatchJob> &jobs)
{
    QSet<QString> seen;
    for (BatchJob &job : jobs) {
        if (seen.contains(job.output)) {
            const QString ext = QFileInfo(job.file).suffix().toLower();
            const QFileInfo out(job.output);
            job.name += QLatin1Char('_') + ext;
            job.output = out.dir().filePath(out.completeBaseName() + QLatin1Char('_') + ext + QLatin1Char('.') + out.suffix());
        }
        seen.insert(job.output);
    }
}

bool isBatchInput(const QString &path)
{
    return QFileInfo(path).isDir();
}

std::vector<BatchRecording> batchRecordings(const QString &folder, const QString &transcriptFolder)
{
    std::vector<BatchRecording> out;
    const QDir dir(folder);
    if (QFileInfo(dir.filePath(QString::fromLatin1(Project::kManifestName))).isFile()) {
        const Project project = Project::load(folder.toStdString());
        for (const Sequence &s : project.sequences)
            out.push_back({QString::fromStdString(s.id), QString::fromStdString(project.mediaPath(s)), {}, s.transcript,
                           dir.absoluteFilePath(QString::fromLatin1(Project::kManifestName))});
        if (out.empty())
            throw Error("the project has no sequences", folder.toStdString());
        return out;
    }
    for (const MediaFile &file : listMediaFolder(folder.toStdString(), transcriptFolder.toStdString()))
        out.push_back({QString::fromStdString(file.id), QString::fromStdString(file.path),
                       QString::fromStdString(file.transcript), {}, {}});

    if (out.empty())
        throw Error("no media files (" + mediaExtensionList() + ") and no project.json", folder.toStdString());
    return out;
}

QDir batchOutputFolder(const CommandLine &args)
{
    const QDir out(args.value(QStringLiteral("out")));
    if (!out.mkpath(QStringLiteral(".")))
        throw Error("cannot create the output folder", out.path().toStdString());
    return out;
}

CommandOption shardOption()
{
    return {QStringLiteral("shard"), QStringLiteral("I/N"),
            QStringLiteral("only every N-th recording from the I-th (I = 1..N), for N machines or the tasks of a "
                           "cluster job array (scripts/cluster)")};
}

Shard shardOf(const CommandLine &args)
{
    if (!args.isSet(QStringLiteral("shard")))
        return {};
    const QString value = args.value(QStringLiteral("shard"));
    const QStringList parts = value.split(QLatin1Char('/'));
    bool okIndex = false, okCount = false;
    const int index = parts.size() == 2 ? parts[0].toInt(&okIndex) : 0;
    const int count = parts.size() == 2 ? parts[1].toInt(&okCount) : 0;
    if (!okIndex || !okCount || count < 1 || index < 1 || index > count)
        throw UsageError(QStringLiteral("--shard must be I/N with 1 <= I <= N, not %1").arg(value));
    return {index - 1, count};
}

std::vector<CommandOption> batchOptions()
{
    return {
        {QStringLiteral("jobs"), QStringLiteral("N"),
         QStringLiteral("with a folder: how many recordings at once (default: one per core)"), {},
         CommandOption::Optional, {QStringLiteral("j")}},
        {QStringLiteral("force"), {},
         QStringLiteral("with a folder: redo recordings whose output is newer than their inputs (skipped otherwise)")},
        shardOption(),
    };
}

BatchRunner::BatchRunner(const CommandLine &args)
    : m_threads(args.isSet(QStringLiteral("jobs")) ? args.integer(QStringLiteral("jobs"), 1, 256)
                                                     : std::max(1, int(std::thread::hardware_concurrency()))),
      m_force(args.isSet(QStringLiteral("force"))), m_json(args.isSet(QStringLiteral("json")))
{
    m_shard = shardOf(args);
}

QJsonObject BatchRunner::run(const std::vector<BatchJob> &jobs, const Work &work) const
{
    const auto start = std::chrono::steady_clock::now();
    std::vector<size_t> mine, todo;
    for (size_t i = size_t(m_shard.index); i < jobs.size(); i += size_t(m_shard.count))
        mine.push_back(i);
    for (size_t i : mine)
        if (m_force || !upToDate(jobs[i]))
            todo.push_back(i);
    const int skipped = int(mine.size() - todo.size());
    Progress progress(int(mine.size()), skipped);
    std::vector<QJsonObject> results(jobs.size());
    std::vector<QString> problems(jobs.size());
    std::atomic<size_t> next{0};
    auto worker = [&] {
        for (size_t k = next++; k < todo.size(); k = next++) {
            const BatchJob &job = jobs[todo[k]];
            QString problem;
            try {
                Feedback feedback;
                results[todo[k]] = work(job, feedback);
            } catch (const std::exception &e) {
                problem = QString::fromUtf8(e.what());
                // An Error's message starts with its file, which the failure names on its own.
                if (problem.startsWith(job.file + QLatin1String(": ")))
                    problem = problem.mid(job.file.size() + 2);
                problems[todo[k]] = problem;
            }
            progress.finished(job.name, problem);
        }
    };
    std::vector<std::thread> pool;
    for (int t = 1; t < std::min<int>(m_threads, int(todo.size())); ++t)
        pool.emplace_back(worker);
    worker();
    for (std::thread &t : pool)
        t.join();

    QJsonArray failures, done;
    for (size_t i = 0; i < jobs.size(); ++i) {
        if (!problems[i].isEmpty())
            failures.append(QJsonObject{{QStringLiteral("name"), jobs[i].name},
                                        {QStringLiteral("file"), jobs[i].file},
                                        {QStringLiteral("reason"), problems[i]}});
        else if (!results[i].isEmpty())
            done.append(results[i]);
    }
    return QJsonObject{
        {QStringLiteral("jobs"), int(mine.size())},
        {QStringLiteral("done"), int(done.size())},
        {QStringLiteral("skipped"), skipped},
        {QStringLiteral("failed"), int(failures.size())},
        {QStringLiteral("threads"), m_threads},
        {QStringLiteral("seconds"), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()},
        {QStringLiteral("failures"), failures},
        {QStringLiteral("results"), done},
    };
}

int BatchRunner::finish(const QJsonObject &summary, const QString &verb) const
{
    const QJsonArray failures = summary.value(QStringLiteral("failures")).toArray();
    if (m_json) {
        printJson(summary);
    } else {
        std::printf("%s %d of %d (%d up to date, %d failed) in %.1f s\n", qPrintable(verb),
                    summary.value(QStringLiteral("done")).toInt(), summary.value(QStringLiteral("jobs")).toInt(),
                    summary.value(QStringLiteral("skipped")).toInt(), int(failures.size()),
                    summary.value(QStringLiteral("seconds")).toDouble());
        for (const QJsonValue &f : failures)
            std::printf("  failed: %s: %s\n", qPrintable(f[QStringLiteral("file")].toString()),
                        qPrintable(f[QStringLiteral("reason")].toString()));
    }
    return failures.isEmpty() ? 0 : 1;
}

} // namespace lipsync::cli
