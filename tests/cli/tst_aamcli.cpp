// The face commands as users run them: landmarks detect, aam build, aam eval, track.
#include "CliRun.h"

#include "aam/PtsFile.h"
#include "io/FeatureCsv.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <opencv2/imgcodecs.hpp>

using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

using namespace lipsync;

namespace {

const QString kGrid = QStringLiteral(LIPSYNC_TEST_DATA "/faces/grid");
const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo/media/");

} // namespace

class TestAamCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_model;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // Train on 18 frames, hold out the two sgivzn frames for eval.
        QDir(m_dir.path()).mkdir("train");
        QDir(m_dir.path()).mkdir("test");
        for (const QString &name : QDir(kGrid).entryList(QDir::Files)) {
            const QString sub = name.startsWith("sgivzn") ? "test" : "train";
            QVERIFY(QFile::copy(kGrid + "/" + name, m_dir.path() + "/" + sub + "/" + name));
        }
        m_model = m_dir.path() + "/grid.aam";
    }

    void aamBuild()
    {
        const Run r = runLipsync({"aam", "build", "--images", m_dir.path() + "/train", "--out", m_model, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject j = parseJsonObject(r.out);
        QCOMPARE(j["images"].toInt(), 18);
        QCOMPARE(j["points"].toInt(), 23);
        QVERIFY(j["combined_modes"].toInt() >= 2);
        QVERIFY(j["identifier"].toString().startsWith("aam-"));
        QVERIFY(QFile::exists(m_model));
    }

    void aamEval()
    {
        const Run r = runLipsync({"aam", "eval", "--aam", m_model, "--images", m_dir.path() + "/test", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject j = parseJsonObject(r.out);
        for (const char *key : {"images", "nme_mean", "nme_median", "fps"})
            QVERIFY2(j.contains(key), key);
        QCOMPARE(j["images"].toInt(), 2);
        QVERIFY2(j["nme_mean"].toDouble() < 0.05, qPrintable(QString::number(j["nme_mean"].toDouble())));
        QVERIFY(j["fps"].toDouble() > 0);

        // The generic-face fitter (Wiberg, shape prior, several starts) fits these too.
        const Run w = runLipsync({"aam", "eval", "--aam", m_model, "--images", m_dir.path() + "/test",
                                  "--algorithm", "wiberg", "--multi-start", "--json"});
        QVERIFY2(w.exitCode == 0, w.err.constData());
        const QJsonObject jw = parseJsonObject(w.out);
        QCOMPARE(jw["algorithm"].toString(), QString("wiberg"));
        QVERIFY(jw["multi_start"].toBool());
        QVERIFY2(jw["nme_mean"].toDouble() < 0.05, qPrintable(QString::number(jw["nme_mean"].toDouble())));
    }

    void aamBuildGenericAndEvalWithPriorWeight()
    {
        // --generic: mirrored images (twice the examples) and gradient-orientation textures.
        const QString model = m_dir.path() + "/generic.aam";
        const Run r = runLipsync({"aam", "build", "--images", m_dir.path() + "/train", "--out", model,
                                  "--generic", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject j = parseJsonObject(r.out);
        QCOMPARE(j["images"].toInt(), 36);
        QVERIFY(j["mirrored"].toBool());
        QCOMPARE(j["features"].toString(), QString("igo"));
        const Run w = runLipsync({"aam", "eval", "--aam", model, "--images", m_dir.path() + "/test",
                                  "--algorithm", "wiberg", "--multi-start", "--prior-weight", "5", "--json"});
        QVERIFY2(w.exitCode == 0, w.err.constData());
        const QJsonObject jw = parseJsonObject(w.out);
        QCOMPARE(jw["prior_weight"].toDouble(), 5.0);
        QVERIFY2(jw["nme_mean"].toDouble() < 0.05, qPrintable(QString::number(jw["nme_mean"].toDouble())));
        QVERIFY(jw["nme_mean"].toDouble() < jw["nme_init_mean"].toDouble());
        // Bad values are usage errors.
        QCOMPARE(runLipsync({"aam", "build", "--images", m_dir.path() + "/train", "--out", model, "--features",
                             "colour"}).exitCode,
                 2);
        QCOMPARE(runLipsync({"aam", "eval", "--aam", model, "--images", m_dir.path(), "--prior-weight", "-1"})
                     .exitCode,
                 2);
    }

    void landmarksDetectVideoFrame()
    {
        const QString out = m_dir.path() + "/frame10.pts";
        const Run r = runLipsync({"landmarks", "detect", kDemo + "bbaf2n.mpg", "--frame", "10", "--out", out, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out)["points"].toArray().size(), 23);
        QCOMPARE(parseJsonObject(r.out)["state"].toString(), QString("automatic"));
        const Eigen::VectorXd s = readFaceShape(out.toStdString());
        QCOMPARE(s.size(), Eigen::Index(46));
        QVERIFY(s.minCoeff() > 0 && s.maxCoeff() < 360);
    }

    void landmarksDetectWithModelAndTemplate()
    {
        const QString image = kGrid + "/bbaf3s_22.jpg";
        for (const QString &method : {QString("aam"), QString("template")}) {
            const QString out = m_dir.path() + "/" + method + ".pts";
            const Run r = runLipsync({"landmarks", "detect", image, "--out", out, "--method", method,
                                      "--aam", m_model, "--json"});
            QVERIFY2(r.exitCode == 0, r.err.constData());
            QCOMPARE(parseJsonObject(r.out)["method"].toString(), method);
        }
        const Eigen::VectorXd truth = readFaceShape((kGrid + "/bbaf3s_22.pts").toStdString());
        const Eigen::VectorXd fitted = readFaceShape((m_dir.path() + "/aam.pts").toStdString());
        QVERIFY((fitted - truth).cwiseAbs().mean() < 3.0);
    }

    void track()
    {
        const QString csv = m_dir.path() + "/bbaf2n.csv";
        const Run r = runLipsync({"track", "--aam", m_model, kDemo + "bbaf2n.mpg", "--out", csv, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject j = parseJsonObject(r.out);
        QCOMPARE(j["frames"].toInt(), 75);
        QCOMPARE(j["tracked"].toInt(), 75);
        const FeatureTable table = readFeatureCsv(csv.toStdString());
        QCOMPARE(int(table.frames.size()), 75);
        QCOMPARE(table.frames.front(), 0);
        QCOMPARE(table.frames.back(), 74);
        QCOMPARE(int(table.values.cols()), j["parameters"].toInt());
        // The features move with speech: not constant over the clip.
        QVERIFY((table.values.colwise().maxCoeff() - table.values.colwise().minCoeff()).maxCoeff() > 0.1);
    }

    void badInput()
    {
        // Usage errors: exit 2.
        QCOMPARE(runLipsync({"aam", "build", "--images", m_dir.path()}).exitCode, 2);
        QCOMPARE(runLipsync({"landmarks", "detect", "--out", "x.pts"}).exitCode, 2);
        QCOMPARE(runLipsync({"track", "--aam", m_model, "--out", "x.csv"}).exitCode, 2);
        QCOMPARE(runLipsync({"aam", "eval", "--aam", m_model, "--images", m_dir.path(), "--bogus"}).exitCode, 2);
        QCOMPARE(runLipsync({"aam", "eval", "--aam", m_model, "--images", m_dir.path(), "--algorithm", "x"}).exitCode, 2);
        // No face: exit 1 with a message naming the file.
        const QString blank = m_dir.path() + "/blank.png";
        cv::imwrite(blank.toStdString(), cv::Mat(288, 360, CV_8UC3, cv::Scalar(90, 90, 90)));
        Run r = runLipsync({"landmarks", "detect", blank, "--out", m_dir.path() + "/b.pts"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("no face"), r.err.constData());
        QVERIFY(!QFile::exists(m_dir.path() + "/b.pts"));
        // A frame past the end of the video.
        r = runLipsync({"landmarks", "detect", kDemo + "bbaf2n.mpg", "--frame", "500", "--out", m_dir.path() + "/c.pts"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("no frame 500"), r.err.constData());
        // Missing directory, too few images, not a model.
        r = runLipsync({"aam", "build", "--images", m_dir.path() + "/missing", "--out", m_dir.path() + "/m.aam"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("does not exist"), r.err.constData());
        r = runLipsync({"aam", "build", "--images", m_dir.path() + "/test", "--out", m_dir.path() + "/m.aam"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("at least 3"), r.err.constData());
        r = runLipsync({"track", "--aam", blank, kDemo + "bbaf2n.mpg", "--out", m_dir.path() + "/t.csv"});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("not an AAM model"), r.err.constData());
    }
};

QTEST_GUILESS_MAIN(TestAamCli)
#include "tst_aamcli.moc"
