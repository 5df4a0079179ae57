// `lipsync project import`: tracked features (a lost frame filled from its neighbour), aligned
// phones and an AAM reference end up in the project, which still loads (`project check`); bad
// input is one line on stderr naming the file.
#include "CliRun.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

namespace {

void write(const QString &path, const QByteArray &bytes)
{
    QDir().mkpath(QFileInfo(path).absolutePath());
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(bytes);
}

const QString kMedia = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media");

const QByteArray kTextGrid = R"(File type = "ooTextFile"
Object class = "TextGrid"

xmin = 0
xmax = 3
tiers? <exists>
size = 1
item []:
    item [1]:
        class = "IntervalTier"
        name = "phones"
        xmin = 0
        xmax = 3
        intervals: size = 3
        intervals [1]:
            xmin = 0
            xmax = 1
            text = "sil"
        intervals [2]:
            xmin = 1
            xmax = 1.5
            text = "B"
        intervals [3]:
            xmin = 1.5
            xmax = 3
            text = "sil"
)";

} // namespace

class TestProjectImport : public QObject
{
    Q_OBJECT

private slots:
    void importsFeaturesPhonesAndAam()
    {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString project = dir.filePath("p");
        Run r = runLipsync({"project", "create", "--media", kMedia, "--out", project});
        QVERIFY2(r.exitCode == 0, r.err.constData());

        // bbaf2n: 75 frames of 2 parameters with frame 10 lost by the tracker.
        QByteArray csv = "frame,p0,p1\n";
        for (int f = 0; f < 75; ++f)
            if (f != 10)
                csv += QByteArray::number(f) + "," + QByteArray::number(f) + "," + QByteArray::number(-f) + "\n";
        write(dir.filePath("features/bbaf2n.csv"), csv);
        write(dir.filePath("align/bbaf2n.TextGrid"), kTextGrid);
        write(project + "/aam/face.aam", "not read by import");

        r = runLipsync({"project", "import", project, "--features", dir.filePath("features"), "--alignments",
                 dir.filePath("align"), "--aam", project + "/aam/face.aam", "--aam-name", "Face", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QJsonObject json = parseJsonObject(r.out);
        QCOMPARE(json.value("features").toInt(), 1);
        QCOMPARE(json.value("alignments").toInt(), 1);

        r = runLipsync({"project", "check", project, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        json = parseJsonObject(r.out);
        const QJsonObject first = json.value("sequences").toArray().at(0).toObject();
        QCOMPARE(first.value("id").toString(), QString("bbaf2n"));
        QCOMPARE(first.value("featureRows").toInt(), 75);
        QCOMPARE(first.value("featureColumns").toInt(), 2);
        QCOMPARE(first.value("phones").toInt(), 3);
        QCOMPARE(first.value("words").toInt(), 8); // GRID's words stay
        QCOMPARE(json.value("sequences").toArray().at(1).toObject().value("featureRows").toInt(), 0);
        const QJsonArray models = json.value("models").toArray();
        QCOMPARE(models.size(), 1);
        QCOMPARE(models.at(0).toObject().value("file").toString(), QString("aam/face.aam"));
        QCOMPARE(models.at(0).toObject().value("name").toString(), QString("Face"));

        // The lost frame took its nearest tracked neighbour's values (frame 9).
        QFile features(project + "/features/bbaf2n.csv");
        QVERIFY(features.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = features.readAll().split('\n');
        QCOMPARE(lines.at(11).split(',').at(1).toDouble(), 9.0);
        QCOMPARE(lines.at(12).split(',').at(1).toDouble(), 11.0);
    }

    void rejectsAnAlignmentWithoutPhones()
    {
        QTemporaryDir dir;
        const QString project = dir.filePath("p");
        QCOMPARE(runLipsync({"project", "create", "--media", kMedia, "--out", project}).exitCode, 0);
        QByteArray grid = kTextGrid;
        grid.replace("\"phones\"", "\"words\"");
        write(dir.filePath("align/bbaf2n.TextGrid"), grid);
        const Run r = runLipsync({"project", "import", project, "--alignments", dir.filePath("align")});
        QCOMPARE(r.exitCode, 1);
        QVERIFY(r.out.isEmpty());
        QVERIFY2(r.err.contains("bbaf2n.TextGrid") && r.err.contains("phones"), r.err.constData());
        QCOMPARE(runLipsync({"project", "import"}).exitCode, 2);
    }
};

QTEST_GUILESS_MAIN(TestProjectImport)
#include "tst_projectimport.moc"
