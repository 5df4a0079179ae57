// Bad media and files end to end through the CLI: truncated, zero-length, unsupported and
// garbled video, video without audio, damaged model files (AAM, aligner, dynamic model),
// damaged projects and unwritable output folders. Every case ends in exit 0 (the input is
// usable) or exit 1 with exactly one line on stderr naming the file — never a crash (exit -1
// here) or a hang (the runner's time-out). The damaged inputs are made here from repo data.
#include "CliRun.h"
#include "../DamagedFiles.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using namespace lipsync::testing;

namespace {

const QString kSource = QStringLiteral(LIPSYNC_SOURCE_DIR);
const QString kMedia = kSource + QStringLiteral("/resources/demo/media/");

} // namespace

class TestBadInputCli : public QObject
{
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString path(const QString &name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        const QByteArray clip = readAll(kMedia + QStringLiteral("bbaf2n.mpg"));
        QVERIFY(clip.size() > 100000);
        QVERIFY(writeAll(path("empty.mpg"), {}));
        QVERIFY(writeAll(path("truncated.mpg"), clip.left(clip.size() / 5)));
        QVERIFY(writeAll(path("text.mpg"), "this is not a video\n"));
        QVERIFY(writeAll(path("garbled.mpg"), flipped(clip)));
        QVERIFY(QFile::copy(QStringLiteral(LIPSYNC_TEST_DATA "/media/no_audio_29.97fps.mp4"), path("silent.mp4")));

        const QByteArray aam = readAll(kSource + QStringLiteral("/resources/demo/aam/demo.aam"));
        QVERIFY(writeAll(path("truncated.aam"), aam.left(aam.size() / 2)));
        QVERIFY(writeAll(path("flipped.aam"), flipped(aam)));
        QVERIFY(writeAll(path("empty.aam"), {}));
        const QByteArray aligner = readAll(kSource + QStringLiteral("/resources/aligner/grid-s1.aligner"));
        QVERIFY(writeAll(path("truncated.aligner"), aligner.left(aligner.size() / 2)));
        QVERIFY(writeAll(path("flipped.aligner"), flipped(aligner)));

        // A real dynamic model, trained on the demo project, then damaged.
        const Run train = runLipsync({"train", "--kind", "hmm", "--project", kSource + "/resources/demo", "--out",
                                      path("hmm.model")});
        QVERIFY2(train.exitCode == 0, train.err.constData());
        const QByteArray model = readAll(path("hmm.model"));
        QVERIFY(writeAll(path("truncated.model"), model.left(model.size() / 2)));
        QVERIFY(writeAll(path("flipped.model"), flipped(model)));
        QVERIFY(writeAll(path("labels.lab"), "0 0.5 sil\n0.5 1.0 b\n1.0 1.5 sil\n"));

        // Damaged copies of the demo project: the manifest, then a features file.
        const QString demo = kSource + QStringLiteral("/resources/demo/");
        const QByteArray manifest = readAll(demo + QStringLiteral("project.json"));
        QVERIFY(writeAll(path("flipped-project/project.json"), flipped(manifest)));
        QVERIFY(writeAll(path("truncated-project/project.json"), manifest.left(manifest.size() / 2)));
        QVERIFY(writeAll(path("bad-features/project.json"), manifest));
        for (const QString &csv : QDir(demo + QStringLiteral("features")).entryList({QStringLiteral("*.csv")})) {
            const QByteArray text = readAll(demo + QStringLiteral("features/") + csv);
            QVERIFY(writeAll(path("bad-features/features/") + csv, csv == QLatin1String("bbaf2n.csv") ? text.left(text.size() / 3) : text));
        }

        // An output location nothing can be written to, even as root (who ignores permission
        // bits): below a regular file.
        QVERIFY(writeAll(path("a-file"), "x"));
        QVERIFY(QDir().mkpath(path("media")));
        QVERIFY(QFile::copy(kMedia + QStringLiteral("bbaf2n.mpg"), path("media/bbaf2n.mpg")));
    }

    void badInput_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("file"); // named on stderr when the command fails
        QTest::addColumn<bool>("mayWork"); // exit 0 is also right (a usable input)
        const QString clip = kMedia + QStringLiteral("bbaf2n.mpg");
        const QString transcript = kMedia + QStringLiteral("bbaf2n.align");
        const QString aam = kSource + QStringLiteral("/resources/demo/aam/demo.aam");
        for (const char *video : {"empty.mpg", "truncated.mpg", "text.mpg", "garbled.mpg"}) {
            const QString v = path(video);
            const bool garbled = QLatin1String(video) == QLatin1String("garbled.mpg");
            QTest::addRow("info %s", video) << QStringList{"info", v} << v << garbled;
            QTest::addRow("track %s", video) << QStringList{"track", "--aam", aam, v, "--out", path("t.csv")} << v << garbled;
            QTest::addRow("align %s", video)
                << QStringList{"align", v, "--transcript", transcript, "--out", path("a.TextGrid")} << v << garbled;
            QTest::addRow("export %s", video) << QStringList{"export", "video", "--media", v, "--out", path("e.mp4")} << v << garbled;
            QTest::addRow("landmarks %s", video) << QStringList{"landmarks", "detect", v, "--out", path("l.pts")} << v << garbled;
        }
        // A video without sound: its pictures are fine, aligning needs the sound.
        const QString silent = path("silent.mp4");
        QTest::addRow("align silent video") << QStringList{"align", silent, "--transcript", transcript, "--out", path("s.TextGrid")} << silent << false;
        QTest::addRow("info silent video") << QStringList{"info", silent} << silent << true;
        for (const char *model : {"truncated.aam", "flipped.aam", "empty.aam"})
            QTest::addRow("track with %s", model) << QStringList{"track", "--aam", path(model), clip, "--out", path("m.csv")} << path(model) << false;
        for (const char *model : {"truncated.aligner", "flipped.aligner"})
            QTest::addRow("align with %s", model)
                << QStringList{"align", clip, "--transcript", transcript, "--aligner", path(model), "--out", path("m.TextGrid")} << path(model) << false;
        for (const char *model : {"truncated.model", "flipped.model"})
            QTest::addRow("generate with %s", model)
                << QStringList{"generate", "--model", path(model), "--labels", path("labels.lab"), "--out", path("g.csv")} << path(model) << false;
        for (const char *project : {"flipped-project", "truncated-project", "bad-features"}) {
            const QString manifest = path(project) + QStringLiteral("/project.json");
            const QString named = QLatin1String(project) == QLatin1String("bad-features") ? QStringLiteral("bbaf2n.csv") : manifest;
            QTest::addRow("project check %s", project) << QStringList{"project", "check", path(project)} << named << false;
            QTest::addRow("train on %s", project)
                << QStringList{"train", "--kind", "hmm", "--project", path(project), "--out", path("p.model")} << named << false;
        }
        QTest::addRow("project create below a file")
            << QStringList{"project", "create", "--media", path("media"), "--out", path("a-file/project")} << path("a-file") << false;
        QTest::addRow("project create in /proc")
            << QStringList{"project", "create", "--media", path("media"), "--out", "/proc/lipsync-test-project"}
            << QStringLiteral("/proc/lipsync-test-project") << false;
        QTest::addRow("generate output below a file")
            << QStringList{"generate", "--model", path("hmm.model"), "--labels", path("labels.lab"), "--out", path("a-file/g.csv")}
            << QStringLiteral("a-file") << false;
    }

    void badInput()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, file);
        QFETCH(bool, mayWork);
        const Run r = runLipsync(args, QProcessEnvironment::systemEnvironment(), 60000);
        QVERIFY2(r.exitCode != -1, "crashed or hung");
        if (mayWork && r.exitCode == 0)
            return;
        QVERIFY2(r.exitCode == 1, qPrintable(QStringLiteral("exit %1: %2").arg(r.exitCode).arg(QString::fromUtf8(r.err))));
        QVERIFY2(r.err.count('\n') == 1 && r.err.endsWith('\n'), r.err.constData());
        QVERIFY2(r.err.contains(QFileInfo(file).fileName().toUtf8()), r.err.constData());
    }

    void readOnlyFolder()
    {
        // Permission bits only stop other users; root gets the /proc and below-a-file cases above.
        if (::geteuid() == 0)
            QSKIP("running as root, which ignores permission bits (covered by the cases above)");
        const QString folder = path("read-only");
        QVERIFY(QDir().mkpath(folder));
        QVERIFY(QFile::setPermissions(folder, QFile::ReadOwner | QFile::ExeOwner));
        const Run r = runLipsync({"project", "create", "--media", path("media"), "--out", folder + "/project"});
        QFile::setPermissions(folder, QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner);
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.count('\n') == 1 && r.err.contains("read-only"), r.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestBadInputCli)
#include "tst_badinputcli.moc"
