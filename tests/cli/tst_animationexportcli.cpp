// `lipsync export cues` and `lipsync export controls` as a user runs them on the demo project:
//  - a tracked sequence's cues in every format, read back by the core readers; --dat-fps and
//    --dat-letters; --json reports;
//  - new speech generated with a model trained on the other sequences (held out), as controls;
//  - the user's own mouth shapes in the project change the cues;
//  - wrong use and bad input: one line naming what is wrong.
#include "CliRun.h"

#include "animation/AnimationControls.h"
#include "animation/MouthCues.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>

using namespace lipsync;
using namespace lipsync::testing;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");

} // namespace

class TestAnimationExportCli : public QObject
{
    Q_OBJECT
private slots:
    void cuesOfATrackedSequence_data()
    {
        QTest::addColumn<QString>("suffix");
        for (const char *s : {"tsv", "json", "xml", "dat"})
            QTest::newRow(s) << QString::fromLatin1(s);
    }

    void cuesOfATrackedSequence()
    {
        QFETCH(QString, suffix);
        QTemporaryDir dir;
        const QString out = dir.filePath("cues." + suffix);
        const Run r = runLipsync({"export", "cues", "--project", kDemo, "--sequence", "bbaf2n", "--out", out, "--json",
                                  "--dat-fps", "25"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json["duration"].toDouble(), 3.0);
        QVERIFY(json["soundFile"].toString().endsWith("media/bbaf2n.mpg"));
        DatOptions dat;
        dat.frameRate = 25;
        const MouthCueTrack cues = readMouthCues(out.toStdString(), dat);
        QCOMPARE(int(cues.cues.size()), json["cues"].toInt());
        QCOMPARE(cues.cues.front().shape, MouthShape::X); // the clip starts in silence
        QVERIFY(cues.cues.size() > 8);
    }

    void datOptions()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("cues.dat");
        Run r = runLipsync({"export", "cues", "--project", kDemo, "--sequence", "bbaf2n", "--out", out, "--dat-letters"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QFile file(out);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.startsWith("MohoSwitch1\n1 X\n"));
        QVERIFY(!text.contains("rest"));
        r = runLipsync({"export", "cues", "--project", kDemo, "--sequence", "bbaf2n", "--out", out, "--dat-fps", "12"});
        verifyOneLineError(r, 1, "from 24 to 100 fps");
    }

    void controlsOfNewSpeech()
    {
        // A per-phone mean model trained without the clip: its face for the clip's speech.
        QTemporaryDir dir;
        const QString model = dir.filePath("hmm.model");
        Run r = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--exclude", "bbaf2n", "--out", model});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QString out = dir.filePath("controls.csv");
        r = runLipsync({"export", "controls", "--project", kDemo, "--media", kDemo + "/media/bbaf2n.mpg", "--transcript",
                        kDemo + "/media/bbaf2n.align", "--model", model, "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out)["frames"].toInt(), 75);
        const AnimationControls c = readAnimationControls(out.toStdString());
        QCOMPARE(c.frameCount(), 75);
        QCOMPARE(c.frameRate, 25.0);
        QVERIFY(QString::fromStdString(c.soundFile).endsWith("media/bbaf2n.mpg"));
        const int open = c.column("mouthOpen");
        QVERIFY(open >= 0);
        // Speech opens the mouth the silence around it keeps shut.
        QVERIFY(c.values.col(open).segment(30, 20).maxCoeff() > c.values.col(open).head(10).maxCoeff() + 0.2);
    }

    void usersShapesChangeTheCues()
    {
        // The project's copy with every speech shape but B drawn far from any frame: B takes
        // the speech the phones do not pin to A.
        QTemporaryDir dir;
        QDir(kDemo).mkpath(dir.path());
        for (const QString &sub : {QStringLiteral("aam"), QStringLiteral("features"), QStringLiteral("media")}) {
            QDir().mkpath(dir.filePath(sub));
            for (const QString &f : QDir(kDemo + "/" + sub).entryList(QDir::Files))
                QVERIFY(QFile::copy(kDemo + "/" + sub + "/" + f, dir.filePath(sub + "/" + f)));
        }
        QFile manifest(kDemo + "/project.json");
        QVERIFY(manifest.open(QIODevice::ReadOnly));
        QByteArray text = manifest.readAll();
        text.replace("\"aligner\": \"builtin\",",
                     "\"aligner\": \"builtin\",\n  \"mouthShapes\": {\"C\": [1, 0, 1, 0], \"D\": [1, 0, 1, 0], "
                     "\"E\": [1, 0, 1, 0], \"F\": [1, 0, 1, 0], \"G\": [1, 0, 1, 0], \"H\": [1, 0, 1, 0], "
                     "\"B\": [0.5, 0.5, 0.5, 0.5]},");
        QFile copy(dir.filePath("project.json"));
        QVERIFY(copy.open(QIODevice::WriteOnly));
        copy.write(text);
        copy.close();
        const QString out = dir.filePath("cues.json");
        const Run r = runLipsync({"export", "cues", "--project", dir.path(), "--sequence", "bbaf2n", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject shapes = parseJsonObject(r.out)["shapes"].toObject();
        QVERIFY2(shapes.keys() == QStringList({"A", "B", "X"}), QJsonDocument(shapes).toJson().constData());
    }

    // `export prior` learns a project's mouths; `train --kind hmm --prior-file` starts a person's
    // phone means from them (here the demo's own, on the demo with a clip left out) and the
    // shipped GRID s1 prior (`--prior`) is found, for HMM-mean and Brand; the weight taken is
    // reported (chosen on the person's clips unless given, none said so); the SLDS and bad weights
    // are refused.
    void mouthPriorForTraining()
    {
        QTemporaryDir dir;
        const QString prior = dir.filePath("demo.mouthprior");
        Run r = runLipsync({"export", "prior", "--project", kDemo, "--out", prior, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out)["sequences"].toInt(), 10);
        QVERIFY(parseJsonObject(r.out)["phones"].toInt() > 20);
        const QString model = dir.filePath("hmm.model");
        r = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--exclude", "bbaf2n", "--prior-file", prior,
                        "--prior-weight", "20", "--out", model});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        r = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior", "--out", model, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY(parseJsonObject(r.out)["coverage"].toObject()["prior"].toBool());
        // The weight is chosen on the person's own clips (--prior-weight cv, the default) unless given.
        // The demo's own mouths predict its clips left out better than its other clips do: a heavy
        // weight.
        r = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior-file", prior, "--out", model, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(parseJsonObject(r.out)["priorWeight"].toDouble() >= 80.0, r.out.constData());
        // The model file records it; `info` reads it back.
        QCOMPARE(parseJsonObject(runLipsync({"info", model, "--json"}).out)["prior_weight"].toDouble(),
                 parseJsonObject(r.out)["priorWeight"].toDouble());
        r = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior-file", prior, "--prior-weight", "5",
                        "--out", model, "--json"});
        QCOMPARE(parseJsonObject(r.out)["priorWeight"].toDouble(), 5.0);
        // Weighed at nothing: said so, the model is the person's own, and the prior is not offered again.
        r = runLipsync({"train", "--kind", "brand", "--project", kDemo, "--prior-file", prior, "--prior-weight", "0",
                        "--out", model});
        QVERIFY2(r.exitCode == 0 && r.err.contains("weigh 0 frames") && !r.err.contains("Starting from other"),
                 r.err.constData());
        QCOMPARE(parseJsonObject(runLipsync({"info", model, "--json"}).out)["prior"].toBool(), false);
        r = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior-file", prior, "--prior-weight", "cv",
                        "--out", model});
        QVERIFY2(QString::fromUtf8(r.out).contains(QRegularExpression("started from other speakers' mouths \\(weight [0-9]+ frames\\)")),
                 r.out.constData());
        // Brand takes it too: its static means move, its delta means stay the person's own.
        const QString brand = dir.filePath("brand.model"), brandPrior = dir.filePath("brand-prior.model");
        QCOMPARE(runLipsync({"train", "--kind", "brand", "--project", kDemo, "--out", brand}).exitCode, 0);
        r = runLipsync({"train", "--kind", "brand", "--project", kDemo, "--prior", "--out", brandPrior});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QVERIFY2(!r.err.contains("Starting from other speakers"), r.err.constData()); // it did
        QVERIFY2(r.out.contains("started from other speakers' mouths"), r.out.constData());
        const auto parameters = [](const QString &file) {
            QFile f(file);
            return f.open(QIODevice::ReadOnly) ? parseJsonObject(f.readAll())["parameters"].toObject() : QJsonObject();
        };
        const QJsonObject plain = parameters(brand), moved = parameters(brandPrior);
        QVERIFY(!plain.isEmpty());
        QVERIFY(plain["staticMean"] != moved["staticMean"]);
        QCOMPARE(plain["deltaMean"], moved["deltaMean"]);
        // The file says it started from other speakers; `info` reads it back.
        for (const auto &[file, started] : {std::pair{brand, false}, std::pair{brandPrior, true}}) {
            r = runLipsync({"info", file, "--json"});
            QCOMPARE(r.exitCode, 0);
            QCOMPARE(parseJsonObject(r.out)["prior"].toBool(), started);
        }
        r = runLipsync({"train", "--kind", "brand", "--project", kDemo, "--out", brand});
        QVERIFY2(r.err.contains("Starting from other speakers' mouths"), r.err.constData()); // offered for 30 s
        verifyOneLineError(runLipsync({"train", "--kind", "slds", "--project", kDemo, "--prior", "--out", model}), 2,
                           "--kind hmm or brand");
        verifyOneLineError(runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior", "--prior-weight", "-1",
                                       "--out", model}),
                           2, "--prior-weight");
        verifyOneLineError(runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior-weight", "5", "--out",
                                       model}),
                           2, "--prior-weight goes with");
        verifyOneLineError(runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--prior-file",
                                       dir.filePath("none.mouthprior"), "--out", model}),
                           1, "none.mouthprior");
    }

    void wrongUseIsNamed()
    {
        QTemporaryDir dir;
        const QString out = dir.filePath("cues.tsv");
        verifyOneLineError(runLipsync({"export", "cues", "--project", kDemo, "--out", out}), 2, "--sequence ID");
        verifyOneLineError(runLipsync({"export", "cues", "--sequence", "x", "--out", out}), 2, "--project DIR");
        verifyOneLineError(runLipsync({"export", "cues", "--project", kDemo, "--sequence", "nope", "--out", out}), 1,
                           "no sequence 'nope'");
        verifyOneLineError(runLipsync({"export", "cues", "--project", kDemo, "--sequence", "bbaf2n", "--out",
                                       dir.filePath("cues.txt")}),
                           1, ".tsv, .json, .xml or .dat");
        verifyOneLineError(runLipsync({"export", "controls", "--project", kDemo, "--sequence", "bbaf2n", "--out",
                                       dir.filePath("c.xml")}),
                           1, ".json or .csv");
        QVERIFY(QDir(dir.path()).isEmpty());
    }
};

QTEST_GUILESS_MAIN(TestAnimationExportCli)
#include "tst_animationexportcli.moc"
