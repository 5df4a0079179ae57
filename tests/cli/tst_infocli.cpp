// `lipsync info` as users run it: values of a GRID clip, a project's sequences, and one-line
// errors with exit code 1 for bad files.
#include "CliRun.h"

#include "aam/AamModel.h"
#include "project/Project.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTest>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

namespace {

QString gridClip()
{
    return QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/bbaf2n.mpg");
}

QString media(const char *name)
{
    return QStringLiteral(LIPSYNC_TEST_DATA "/media/") + QLatin1String(name);
}

} // namespace

class TestInfoCli : public QObject
{
    Q_OBJECT

private slots:
    void mediaJson()
    {
        const Run run = runLipsync({QStringLiteral("info"), gridClip(), QStringLiteral("--json")});
        QCOMPARE(run.exitCode, 0);
        QVERIFY(run.err.isEmpty());
        QJsonParseError error;
        const QJsonObject o = QJsonDocument::fromJson(run.out, &error).object();
        QCOMPARE(error.error, QJsonParseError::NoError);
        QCOMPARE(o.value(QLatin1String("path")).toString(), gridClip());
        QCOMPARE(o.value(QLatin1String("kind")).toString(), QStringLiteral("media"));
        QCOMPARE(o.value(QLatin1String("frames")).toInt(), 75);
        QCOMPARE(o.value(QLatin1String("fps")).toDouble(), 25.0);
        QVERIFY(std::abs(o.value(QLatin1String("duration")).toDouble() - 3.0) < 1e-6);
        QCOMPARE(o.value(QLatin1String("width")).toInt(), 360);
        QCOMPARE(o.value(QLatin1String("height")).toInt(), 288);
        QCOMPARE(o.value(QLatin1String("has_audio")).toBool(), true);
        QCOMPARE(o.value(QLatin1String("audio_rate")).toInt(), 44100);
        QCOMPARE(o.value(QLatin1String("audio_channels")).toInt(), 2);
        QVERIFY(std::abs(o.value(QLatin1String("audio_duration")).toDouble() - 3.0) < 0.05);
    }

    void jsonFlagBeforePath()
    {
        const Run run = runLipsync({QStringLiteral("info"), QStringLiteral("--json"), gridClip()});
        QCOMPARE(run.exitCode, 0);
        QCOMPARE(QJsonDocument::fromJson(run.out).object().value(QLatin1String("frames")).toInt(), 75);
    }

    void mediaTable()
    {
        const Run run = runLipsync({QStringLiteral("info"), gridClip()});
        QCOMPARE(run.exitCode, 0);
        const QString text = QString::fromUtf8(run.out);
        QVERIFY2(text.contains(QRegularExpression(QStringLiteral("^frames\\s+75$"),
                                                  QRegularExpression::MultilineOption)),
                 qPrintable(text));
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^fps\\s+25$"),
                                                 QRegularExpression::MultilineOption)));
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^duration\\s+3\\.000 s$"),
                                                 QRegularExpression::MultilineOption)));
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^audio rate\\s+44100 Hz$"),
                                                 QRegularExpression::MultilineOption)));
        QVERIFY(text.contains(QLatin1String("360 x 288")));
    }

    void videoWithoutAudio()
    {
        const Run run = runLipsync({QStringLiteral("info"), media("no_audio_29.97fps.mp4"),
                                 QStringLiteral("--json")});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o.value(QLatin1String("has_audio")).toBool(), false);
        QCOMPARE(o.value(QLatin1String("frames")).toInt(), 15);
        QVERIFY(std::abs(o.value(QLatin1String("fps")).toDouble() - 29.97) < 0.001);
    }

    void badFiles_data()
    {
        QTest::addColumn<QString>("path");
        QTest::newRow("empty") << media("empty.mpg");
        QTest::newRow("truncated") << media("truncated_30pct.mpg");
        QTest::newRow("text as mpg") << media("text_renamed.mpg");
        QTest::newRow("missing") << media("no_such_file.mpg");
        QTest::newRow("folder without project") << media("");
    }

    void badFiles()
    {
        QFETCH(QString, path);
        for (const QStringList &extra : {QStringList{}, QStringList{QStringLiteral("--json")}}) {
            const Run run = runLipsync(QStringList{QStringLiteral("info"), path} + extra);
            QCOMPARE(run.exitCode, 1);
            QVERIFY(run.out.isEmpty());
            QVERIFY2(run.err.endsWith('\n') && run.err.count('\n') == 1, run.err.constData());
            QVERIFY2(run.err.startsWith("lipsync: "), run.err.constData());
            QVERIFY2(QString::fromUtf8(run.err).contains(QFileInfo(path).fileName()), run.err.constData());
        }
    }

    void badUsage()
    {
        QCOMPARE(runLipsync({QStringLiteral("info")}).exitCode, 2);
        QCOMPARE(runLipsync({QStringLiteral("info"), gridClip(), QStringLiteral("--frames")}).exitCode, 2);
        QCOMPARE(runLipsync({QStringLiteral("info"), gridClip(), gridClip()}).exitCode, 2);
    }

    void project()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        lipsync::Project project;
        project.name = "cli info";
        lipsync::Sequence a;
        a.id = "bbaf2n";
        a.mediaFile = gridClip().toStdString();
        a.frameRate = 25.0;
        a.frameCount = 75;
        a.transcript = "bin blue at f two now";
        lipsync::Sequence b;
        b.id = "ntsc";
        b.mediaFile = media("no_audio_29.97fps.mp4").toStdString();
        b.frameRate = 30000.0 / 1001.0;
        b.frameCount = 15;
        project.sequences = {a, b};
        try {
            project.save(dir.path().toStdString());
        } catch (const std::exception &e) {
            QFAIL(e.what());
        }

        const Run run = runLipsync({QStringLiteral("info"), dir.path(), QStringLiteral("--json")});
        QCOMPARE(run.exitCode, 0);
        const QJsonObject o = QJsonDocument::fromJson(run.out).object();
        QCOMPARE(o.value(QLatin1String("kind")).toString(), QStringLiteral("project"));
        QCOMPARE(o.value(QLatin1String("sequence_count")).toInt(), 2);
        QCOMPARE(o.value(QLatin1String("frames")).toInt(), 90);
        QVERIFY(o.value(QLatin1String("fps")).isNull()); // mixed rates
        QVERIFY(std::abs(o.value(QLatin1String("duration")).toDouble() - (3.0 + 15 * 1001.0 / 30000.0)) < 1e-6);
        const QJsonArray sequences = o.value(QLatin1String("sequences")).toArray();
        QCOMPARE(sequences.size(), 2);
        QCOMPARE(sequences[0].toObject().value(QLatin1String("id")).toString(), QStringLiteral("bbaf2n"));
        QCOMPARE(sequences[0].toObject().value(QLatin1String("frames")).toInt(), 75);
        QCOMPARE(sequences[0].toObject().value(QLatin1String("fps")).toDouble(), 25.0);
        QCOMPARE(sequences[1].toObject().value(QLatin1String("frames")).toInt(), 15);

        const Run table = runLipsync({QStringLiteral("info"), dir.path()});
        QCOMPARE(table.exitCode, 0);
        const QString text = QString::fromUtf8(table.out);
        QVERIFY2(text.contains(QRegularExpression(QStringLiteral("^sequences\\s+2$"),
                                                  QRegularExpression::MultilineOption)),
                 qPrintable(text));
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^bbaf2n\\s+75\\s+25\\s+3\\.000 s"),
                                                 QRegularExpression::MultilineOption)));
        // NTSC's rate to seven digits, told apart from a rounded 29.97; the range of mixed rates.
        QVERIFY(text.contains(QRegularExpression(QStringLiteral("^ntsc\\s+15\\s+29\\.97003\\s"),
                                                 QRegularExpression::MultilineOption)));
        QVERIFY2(text.contains(QRegularExpression(QStringLiteral("^fps\\s+mixed, 25 to 29\\.97003$"),
                                                  QRegularExpression::MultilineOption)),
                 qPrintable(text));
    }

    // An AAM and a model file are told by their first bytes, not taken for audio (FFmpeg reads
    // an AAM as AMR sound).
    void aamAndModel()
    {
        const QString aam = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/aam/demo.aam");
        const lipsync::AamModel model = lipsync::AamModel::load(aam.toStdString());
        const Run run = runLipsync({QStringLiteral("info"), aam, QStringLiteral("--json")});
        QVERIFY2(run.exitCode == 0, run.err.constData());
        const QJsonObject o = parseJsonObject(run.out);
        QCOMPARE(o[QStringLiteral("kind")].toString(), QStringLiteral("aam"));
        QCOMPARE(o[QStringLiteral("points")].toInt(), 23);
        QCOMPARE(o[QStringLiteral("combined_modes")].toInt(), model.combinedModes());
        QCOMPARE(o[QStringLiteral("identifier")].toString(), QString::fromStdString(model.identifier));
        const Run table = runLipsync({QStringLiteral("info"), aam});
        QVERIFY(table.out.contains("combined modes"));
        QVERIFY(!table.out.contains("audio"));

        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("hmm.model"));
        const Run train = runLipsync({"train", "--kind", "hmm", "--project", LIPSYNC_SOURCE_DIR "/resources/demo",
                                      "--out", file, "--context-states"});
        QVERIFY2(train.exitCode == 0, train.err.constData());
        const Run info = runLipsync({QStringLiteral("info"), file, QStringLiteral("--json")});
        QVERIFY2(info.exitCode == 0, info.err.constData());
        const QJsonObject m = parseJsonObject(info.out);
        QCOMPARE(m[QStringLiteral("kind")].toString(), QStringLiteral("model"));
        QCOMPARE(m[QStringLiteral("model_kind")].toString(), QStringLiteral("hmm"));
        QCOMPARE(m[QStringLiteral("dimension")].toInt(), model.combinedModes());
        QCOMPARE(m[QStringLiteral("fps")].toDouble(), 25.0);
        QVERIFY(m[QStringLiteral("phones_in_context")].toBool());
        QVERIFY(m[QStringLiteral("states")].toInt() > 41); // the trees' tied states
        QCOMPARE(m[QStringLiteral("aam")].toString(), QString::fromStdString(model.identifier));
        QCOMPARE(m[QStringLiteral("aligner")].toString(), QStringLiteral("shipped")); // the demo's, GRID s1's
        // A model file cut short is named, not probed as media.
        QFile whole(file), cut(dir.filePath(QStringLiteral("cut.model")));
        QVERIFY(whole.open(QIODevice::ReadOnly) && cut.open(QIODevice::WriteOnly));
        cut.write(whole.read(whole.size() / 2));
        cut.close();
        const Run bad = runLipsync({QStringLiteral("info"), cut.fileName()});
        QCOMPARE(bad.exitCode, 1);
        QVERIFY2(bad.err.contains("cut.model") && !bad.err.contains("media"), bad.err.constData());
    }

    void corruptProject()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        QFile manifest(dir.filePath(QStringLiteral("project.json")));
        QVERIFY(manifest.open(QIODevice::WriteOnly));
        manifest.write("{ not json");
        manifest.close();
        const Run run = runLipsync({QStringLiteral("info"), dir.path()});
        QCOMPARE(run.exitCode, 1);
        QCOMPARE(run.err.count('\n'), 1);
        QVERIFY2(run.err.contains("project.json"), run.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestInfoCli)
#include "tst_infocli.moc"
