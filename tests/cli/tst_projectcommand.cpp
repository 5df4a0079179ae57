// `lipsync project create` and `lipsync project check`, run as a user runs them.
#include "CliRun.h"

#include "align/SphinxAligner.h"
#include "project/Project.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using lipsync::Project;
using lipsync::SphinxAligner;
using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;
using lipsync::testing::verifyOneLineError;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");

} // namespace

class TestProjectCommand : public QObject
{
    Q_OBJECT

private slots:
    void createFromDemoMedia()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("demo");
        const Run r = runLipsync({"project", "create", "--media", kDemo + "/media", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("project").toString(), out + "/project.json");
        const QJsonArray sequences = json.value("sequences").toArray();
        QCOMPARE(sequences.size(), 10);
        for (const QJsonValue &v : sequences) {
            const QJsonObject s = v.toObject();
            QCOMPARE(s.value("frameCount").toInt(), 75);
            QCOMPARE(s.value("frameRate").toDouble(), 25.0);
            QVERIFY(s.value("mediaFound").toBool());
            QVERIFY(!s.value("transcript").toString().isEmpty());
            // Relative to the new project folder, pointing back at the demo clips.
            QVERIFY(!QDir::isAbsolutePath(s.value("mediaFile").toString()));
        }
        QVERIFY(QFileInfo(out + "/project.json").isFile());
        // A new project's speaker is nobody the shipped model knows: the generic aligner.
        QCOMPARE(json.value("aligner").toString(), QString("generic"));
        QCOMPARE(Project::load(out.toStdString()).aligner, std::string(Project::kGenericAligner));

        const Run check = runLipsync({"project", "check", out, "--json"});
        QVERIFY2(check.exitCode == 0, check.err.constData());
        QCOMPARE(parseJsonObject(check.out).value("sequences").toArray().size(), 10);
        QVERIFY(parseJsonObject(check.out).value("missingMedia").toArray().isEmpty());

        // An existing project is only replaced on request, and then backed up.
        verifyOneLineError(runLipsync({"project", "create", "--media", kDemo + "/media", "--out", out}), 1,
                           "already exists");
        QVERIFY(!QFileInfo::exists(out + "/project.json.bak"));
        const Run forced = runLipsync({"project", "create", "--media", kDemo + "/media", "--out", out, "--force"});
        QVERIFY2(forced.exitCode == 0, forced.err.constData());
        QVERIFY(forced.out.contains("10 sequences, 750 frames"));
        QVERIFY(QFileInfo(out + "/project.json.bak").isFile());
    }

    // Commands given such a project align as it says: the generic model adapted to the speaker
    // (CMU Sphinx with MLLR) for a new project, the shipped model for one that says builtin,
    // and --aligner over both.
    void projectSaysWhoseAligner()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        QTemporaryDir dir;
        const QString generic = dir.filePath("generic"), builtin = dir.filePath("builtin");
        QCOMPARE(runLipsync({"project", "create", "--media", kDemo + "/media", "--out", generic}).exitCode, 0);
        QCOMPARE(runLipsync({"project", "create", "--media", kDemo + "/media", "--out", builtin, "--aligner", "builtin"})
                     .exitCode,
                 0);
        auto align = [&](const QString &project, QStringList extra) {
            QStringList args{"align", kDemo + "/media/bbaf2n.mpg", "--transcript", kDemo + "/media/bbaf2n.align",
                             "--out", dir.filePath("x.TextGrid"), "--project", project, "--json"};
            const Run r = runLipsync(args + extra);
            if (r.exitCode != 0)
                qWarning("%s", r.err.constData());
            return parseJsonObject(r.out);
        };
        const QJsonObject g = align(generic, {});
        QVERIFY2(g.value("model").toString().startsWith("sphinx"), qPrintable(g.value("model").toString()));
        // Adapted: as `--aligner sphinx --adapt`, and likelier than the model as it is.
        const QJsonObject adapted = align(builtin, {"--aligner", "sphinx", "--adapt"});
        const QJsonObject plain = align(builtin, {"--aligner", "sphinx"});
        QCOMPARE(g.value("logLikelihood").toDouble(), adapted.value("logLikelihood").toDouble());
        QVERIFY(g.value("logLikelihood").toDouble() > plain.value("logLikelihood").toDouble() + 10);
        const QJsonObject b = align(builtin, {});
        QVERIFY2(b.value("model").toString().endsWith("grid-s1.aligner"), qPrintable(b.value("model").toString()));
        QVERIFY(b.value("adaptationLogLikelihoodPerFrame").toArray().isEmpty());
        const QJsonObject asked = align(generic, {"--aligner", QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/aligner/grid-s1.aligner")});
        QVERIFY(asked.value("model").toString().endsWith("grid-s1.aligner"));
    }

    // From nothing: a clip without a transcript goes in (to be transcribed), a damaged or foreign
    // one is listed and left out, the rest go in.
    void createSkipsDamagedClips()
    {
        QTemporaryDir dir;
        const QString media = dir.filePath(QStringLiteral("media"));
        QDir().mkpath(media);
        QVERIFY(QFile::copy(kDemo + "/media/bbaf2n.mpg", media + "/a.mpg")); // no transcript
        QVERIFY(QFile::copy(kDemo + "/media/bgin3a.mpg", media + "/b.mpg"));
        QVERIFY(QFile::copy(kDemo + "/media/bgin3a.align", media + "/b.align"));
        QFile whole(kDemo + "/media/bwbg8n.mpg");
        QVERIFY(whole.open(QIODevice::ReadOnly));
        QFile cut(media + "/broken.mpg");
        QVERIFY(cut.open(QIODevice::WriteOnly));
        cut.write(whole.read(20000)); // truncated
        cut.close();
        const Run r = runLipsync({"project", "create", "--media", media, "--out", dir.filePath("p"), "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = parseJsonObject(r.out);
        const QJsonArray skipped = o.value("skipped").toArray();
        QCOMPARE(skipped.size(), 1);
        QVERIFY(skipped.first().toString().contains("broken.mpg"));
        QVERIFY(r.err.contains("skipped") && r.err.contains("broken.mpg"));
        const lipsync::Project p = lipsync::Project::load(dir.filePath("p").toStdString());
        QCOMPARE(int(p.sequences.size()), 2);
        QVERIFY(p.sequence("a") && p.sequence("a")->transcript.empty());
        QCOMPARE(p.sequence("b")->transcript, std::string("bin green in n three again"));
    }

    void checkBundledDemo()
    {
        const Run r = runLipsync({"project", "check", "--json", kDemo});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("name").toString(), QString("demo"));
        QCOMPARE(json.value("aligner").toString(), QString("builtin")); // GRID's speaker
        QCOMPARE(json.value("sequences").toArray().size(), 10);
        QCOMPARE(json.value("sequences").toArray()[0].toObject().value("mediaFile").toString(),
                 QString("media/bbaf2n.mpg"));
        QVERIFY(json.value("missingMedia").toArray().isEmpty());
    }

    void checkReportsMissingMedia()
    {
        const QString dir = QStringLiteral(LIPSYNC_TEST_DATA "/project/valid_media_elsewhere");
        const Run r = runLipsync({"project", "check", dir, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("missingMedia").toArray().size(), 3);
        QCOMPARE(json.value("missingMedia").toArray()[1].toString(), QString("/elsewhere/disk/b.mpg"));
        QCOMPARE(json.value("sequences").toArray()[1].toObject().value("featureRows").toInt(), 3);
        const Run text = runLipsync({"project", "check", dir});
        QCOMPARE(text.exitCode, 0);
        QVERIFY(text.out.contains("[media not found]"));
    }

    void checkCorruptManifest()
    {
        const QString dir = QStringLiteral(LIPSYNC_TEST_DATA "/project/frame_rate_negative");
        verifyOneLineError(runLipsync({"project", "check", dir}), 1,
                           dir + "/project.json: sequences[2].frameRate: must be a positive number");
        verifyOneLineError(runLipsync({"project", "check", dir, "--json"}), 1, "sequences[2].frameRate");
        verifyOneLineError(runLipsync({"project", "check", QStringLiteral(LIPSYNC_TEST_DATA "/project/not_json")}),
                           1, "not valid JSON");
    }

    void badUsage()
    {
        verifyOneLineError(runLipsync({"project", "check"}), 2, "usage: lipsync project check");
        verifyOneLineError(runLipsync({"project", "create", "--media", kDemo + "/media"}), 2,
                           "usage: lipsync project create");
        verifyOneLineError(runLipsync({"project", "check", kDemo, "--verbose"}), 2, "unknown option --verbose");
        QTemporaryDir dir;
        verifyOneLineError(runLipsync({"project", "create", "--media", kDemo + "/media", "--out", dir.filePath("g"),
                                       "--aligner", "grid"}),
                           2, "--aligner: builtin or generic, not 'grid'");
        QVERIFY(!QFileInfo::exists(dir.filePath("g")));
        verifyOneLineError(runLipsync({"project", "create", "--media", dir.filePath("none"), "--out",
                                dir.filePath("p")}),
                           1, "no such media folder");
        QVERIFY(!QFileInfo::exists(dir.filePath("p")));
    }
};

QTEST_GUILESS_MAIN(TestProjectCommand)
#include "tst_projectcommand.moc"
