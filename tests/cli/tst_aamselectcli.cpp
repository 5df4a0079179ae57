// `lipsync aam select` as users run it on the demo's ten clips: diverse frames written with their
// automatic points, built into an AAM by `aam build`, whose JSON says how many modes it kept and
// why.
#include "CliRun.h"

#include "aam/PtsFile.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

using namespace lipsync;

namespace {

const QString kDemoMedia = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media");

} // namespace

class TestAamSelectCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_frames;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_frames = m_dir.path() + "/frames";
    }

    void selectsDiverseLabelledFrames()
    {
        const Run r = runLipsync({"aam", "select", "--media", kDemoMedia, "--count", "8", "--step", "10", "--out",
                                  m_frames, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject j = parseJsonObject(r.out);
        for (const char *key : {"out", "sources", "clips_used", "candidates", "isolated", "count", "step",
                                "dimensions", "detector", "methods", "selected", "review", "seconds", "warnings"})
            QVERIFY2(j.contains(key), key);
        QCOMPARE(j["sources"].toInt(), 10);
        QCOMPARE(j["count"].toInt(), 8);
        // Frames 5, 15, ..., 65 of each 75-frame clip, less any without a confident face.
        QVERIFY(j["candidates"].toInt() > 60 && j["candidates"].toInt() <= 70);
        const QJsonArray selected = j["selected"].toArray();
        QCOMPARE(selected.size(), 8);
        QSet<QString> clips, images;
        int methods = 0;
        for (const QJsonValue &v : selected) {
            const QJsonObject f = v.toObject();
            QVERIFY(QFile::exists(f["image"].toString()));
            QCOMPARE(readFaceShape(f["pts"].toString().toStdString()).size(), 46);
            QCOMPARE(f["frame"].toInt() % 10, 5);
            QVERIFY(f["disagreement"].toDouble() >= 0);
            clips.insert(f["source"].toString());
            images.insert(f["image"].toString());
        }
        QCOMPARE(images.size(), 8);
        // Eight of 66 frames of ten clips of one speaker: spread over the clips, not eight
        // neighbours of one clip.
        QVERIFY2(clips.size() >= 4, qPrintable(QString::number(clips.size())));
        QCOMPARE(j["clips_used"].toInt(), int(clips.size()));
        for (const QJsonValue &v : j["methods"].toObject())
            methods += v.toInt();
        QCOMPARE(methods, 8);
        // Review order: the largest disagreement first.
        const QJsonArray review = j["review"].toArray();
        QCOMPARE(review.size(), 8);
        for (int i = 1; i < review.size(); ++i)
            QVERIFY(review[i - 1].toObject()["disagreement"].toDouble()
                    >= review[i].toObject()["disagreement"].toDouble());
    }

    void buildsFromTheSelectionAndSaysWhyItKeptTheModes()
    {
        const QString model = m_dir.path() + "/selected.aam";
        const Run r = runLipsync({"aam", "build", "--images", m_frames, "--out", model, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject j = parseJsonObject(r.out);
        QCOMPARE(j["images"].toInt(), 8);
        const QJsonObject modes = j["modes"].toObject();
        for (const char *part : {"shape", "texture", "combined"}) {
            const QJsonObject m = modes[part].toObject();
            QVERIFY2(m["modes"].toInt() >= 1 && m["modes"].toInt() <= 7, part); // 8 images: 7 modes at most
            QVERIFY(QStringList({"variance", "cap", "samples", "rank"}).contains(m["limit"].toString()));
            QVERIFY(!m["reason"].toString().isEmpty());
            QVERIFY(m["retained_variance"].toDouble() > 0 && m["retained_variance"].toDouble() <= 1 + 1e-9);
        }
        QCOMPARE(modes["combined"].toObject()["modes"].toInt(), j["combined_modes"].toInt());

        // A cap below what the variance asks for is the reason given.
        const Run capped = runLipsync({"aam", "build", "--images", m_frames, "--out", model, "--max-modes", "2",
                                       "--combined-variance", "0.99", "--json"});
        QVERIFY2(capped.exitCode == 0, capped.err.constData());
        const QJsonObject c = parseJsonObject(capped.out)["modes"].toObject()["combined"].toObject();
        QCOMPARE(c["modes"].toInt(), 2);
        QCOMPARE(c["limit"].toString(), QString("cap"));
        QCOMPARE(c["cap"].toInt(), 2);
        QVERIFY(c["retained_variance"].toDouble() < 0.99);

        // All the variance of 8 images: the number of images is the limit, and the text says so.
        const Run all = runLipsync({"aam", "build", "--images", m_frames, "--out", model, "--combined-variance",
                                    "1", "--texture-variance", "1", "--shape-variance", "1"});
        QVERIFY2(all.exitCode == 0, all.err.constData());
        QVERIFY2(all.out.contains("combined: 8 training images allow at most"), all.out.constData());
    }

    void badUsage()
    {
        QCOMPARE(runLipsync({"aam", "select", "--media", kDemoMedia}).exitCode, 2);
        QCOMPARE(runLipsync({"aam", "select", "--media", kDemoMedia, "--out", m_dir.path() + "/x", "--count", "0"})
                     .exitCode,
                 2);
        QCOMPARE(runLipsync({"aam", "select", "--media", kDemoMedia, "--out", m_dir.path() + "/x", "--colour"})
                     .exitCode,
                 2);
        const Run missing = runLipsync({"aam", "select", "--media", m_dir.path() + "/nothing", "--out",
                                        m_dir.path() + "/x"});
        QCOMPARE(missing.exitCode, 1);
        QVERIFY(missing.err.contains("nothing"));
    }
};

QTEST_GUILESS_MAIN(TestAamSelectCli)
#include "tst_aamselectcli.moc"
