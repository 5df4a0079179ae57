// Sound and picture on one clock, as users run the CLI on recordings made for it
// (tests/data/media/timing, README there): the sound starting 0.5 s after the picture, 48 ms
// timestamp gaps where clips were joined, a variable frame rate, 29.97 fps, and sound shorter
// than the picture. In each:
//  - `info` reports the offsets, gaps and frame timing;
//  - `align` places every word where a player presents it: the clean original's times shifted
//    as the streams' timestamps say (within 10 ms); the joined clips as ffmpeg presents their
//    sound with every gap filled;
//  - frame labels are voted over the time each frame is really on screen;
//  - `render` and `export video` write exactly the source's frames at the source's times.
#include "CliRun.h"

#include "io/MediaInfo.h"

#include <QDir>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using lipsync::MediaInfo;
using lipsync::testing::Run;
using lipsync::testing::parseJsonObject;
using lipsync::testing::runLipsync;

namespace {

const QString kDemo = QStringLiteral(LIPSYNC_SOURCE_DIR "/resources/demo");
const QString kTiming = QStringLiteral(LIPSYNC_SOURCE_DIR "/tests/data/media/timing/");
const QString kTranscript = kDemo + "/media/bbaf2n.align";

struct Word
{
    QString label;
    double start = 0, end = 0;
};

} // namespace

class TestMediaTimelineCli : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;
    QString m_model;

    QJsonObject json(const QStringList &args)
    {
        const Run r = runLipsync(QStringList(args) << "--json");
        if (r.exitCode != 0)
            qWarning("%s", r.err.constData());
        return r.exitCode == 0 ? parseJsonObject(r.out) : QJsonObject();
    }

    QJsonObject align(const QString &media, const QString &transcript)
    {
        return json({"align", media, "--transcript", transcript, "--out",
                     m_dir.filePath(QFileInfo(media).completeBaseName() + ".TextGrid")});
    }

    static std::vector<Word> spokenWords(const QJsonObject &aligned)
    {
        std::vector<Word> words;
        for (const QJsonValue &v : aligned.value("words").toArray()) {
            const QJsonObject w = v.toObject();
            const QString label = w.value("label").toString();
            if (!label.isEmpty() && label != "sil" && label != "sp")
                words.push_back({label, w.value("start").toDouble(), w.value("end").toDouble()});
        }
        return words;
    }

    // Every word of `got` at `want`'s times + shift, within 10 ms; words ending after `until`
    // (cut off by the end of the sound) are left out.
    static void verifyShifted(const std::vector<Word> &want, const std::vector<Word> &got, double shift,
                              double until = INFINITY)
    {
        QCOMPARE(got.size(), want.size());
        int compared = 0;
        for (size_t i = 0; i < want.size(); ++i) {
            QCOMPARE(got[i].label, want[i].label);
            if (want[i].end + shift > until)
                continue;
            QVERIFY2(std::abs(got[i].start - (want[i].start + shift)) <= 0.010 + 1e-9
                         && std::abs(got[i].end - (want[i].end + shift)) <= 0.010 + 1e-9,
                     qPrintable(QString("'%1' at %2-%3 s, expected %4-%5 s")
                                    .arg(got[i].label)
                                    .arg(got[i].start)
                                    .arg(got[i].end)
                                    .arg(want[i].start + shift)
                                    .arg(want[i].end + shift)));
            ++compared;
        }
        QVERIFY(compared >= 4);
    }

    // `render` and `export video` of `media` have its frames at its times and its duration.
    void verifyRendersKeepFrames(const QString &media)
    {
        const MediaInfo source = MediaInfo::probe(media.toStdString());
        const QString stem = QFileInfo(media).completeBaseName();
        const QString rendered = m_dir.filePath(stem + "-render.mp4");
        const QJsonObject r = json({"render", "--model", m_model, "--aam", kDemo + "/aam/demo.aam", "--media", media,
                                    "--transcript", kTranscript, "--out", rendered});
        QCOMPARE(r.value("frames").toInt(), source.frameCount);
        const QString exported = m_dir.filePath(stem + "-export.mp4");
        const QJsonObject e = json({"export", "video", "--media", media, "--out", exported});
        QCOMPARE(e.value("frames").toInt(), source.frameCount);
        for (const QString &out : {rendered, exported}) {
            const MediaInfo written = MediaInfo::probe(out.toStdString());
            QCOMPARE(written.frameCount, source.frameCount);
            QCOMPARE(written.variableFrameRate, source.variableFrameRate);
            for (int i = 0; i < source.frameCount; ++i)
                QVERIFY2(std::abs(written.frames.time(i) - (source.frames.time(i) - source.frames.startTime())) < 1e-3,
                         qPrintable(QString("%1: frame %2 at %3 s, the source's at %4 s")
                                        .arg(out)
                                        .arg(i)
                                        .arg(written.frames.time(i))
                                        .arg(source.frames.time(i))));
            QVERIFY2(std::abs(written.videoDuration - source.videoDuration) < 1e-3,
                     qPrintable(QString("%1 lasts %2 s, the source %3 s").arg(out).arg(written.videoDuration).arg(source.videoDuration)));
            // The sound lasts as long as the frames (within one AAC frame).
            QVERIFY2(std::abs(written.audioEndTime - written.videoEndTime()) <= 1024.0 / written.audioSampleRate + 1e-6,
                     qPrintable(QString("%1: sound to %2 s, frames to %3 s").arg(out).arg(written.audioEndTime).arg(written.videoEndTime())));
        }
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_model = m_dir.filePath("demo.model");
        const Run train = runLipsync({"train", "--kind", "hmm", "--project", kDemo, "--out", m_model});
        QVERIFY2(train.exitCode == 0, train.err.constData());
    }

    void infoReportsTheTimeline()
    {
        const QJsonObject late = json({"info", kTiming + "audio_late_0.5s.mp4"});
        // The first AAC frame (1024 priming samples, 23 ms) is stamped 0.476 s: the speech at 0.5 s.
        QVERIFY2(std::abs(late.value("audio_start").toDouble() - 0.4768) < 0.003, qPrintable(QString::number(late.value("audio_start").toDouble())));
        QVERIFY(std::abs(late.value("audio_video_start_difference").toDouble() - 0.4768) < 0.003);
        QCOMPARE(late.value("video_start").toDouble(), 0.0);

        const QJsonObject joined = json({"info", kTiming + "joined_gaps_48ms.mkv"});
        QCOMPARE(joined.value("audio_gaps").toInt(), 2);
        const QJsonArray gaps = joined.value("audio_gap_list").toArray();
        QCOMPARE(gaps.size(), 2);
        for (int k = 0; k < 2; ++k) {
            const QJsonObject g = gaps[k].toObject();
            QVERIFY(std::abs(g.value("at").toDouble() - (2.952 + 3.0 * k)) < 0.002);
            QVERIFY(std::abs(g.value("length").toDouble() - 0.048) < 0.002);
        }
        QVERIFY(std::abs(joined.value("audio_end").toDouble() - 8.952) < 0.002);

        const QJsonObject vfr = json({"info", kTiming + "vfr.mp4"});
        QCOMPARE(vfr.value("variable_frame_rate").toBool(), true);
        QCOMPARE(vfr.value("frames").toInt(), 51);
        QVERIFY(std::abs(vfr.value("video_end").toDouble() - 3.0) < 1e-3);

        const QJsonObject ntsc = json({"info", kTiming + "ntsc_29.97fps.mp4"});
        QCOMPARE(ntsc.value("fps_fraction").toString(), QStringLiteral("30000/1001"));
        QCOMPARE(ntsc.value("variable_frame_rate").toBool(), false);
        QCOMPARE(ntsc.value("frames").toInt(), 90);
        QVERIFY(std::abs(ntsc.value("video_end").toDouble() - 90 * 1001.0 / 30000) < 1e-6);

        const QJsonObject shortSound = json({"info", kTiming + "audio_short_2s.mp4"});
        QVERIFY(std::abs(shortSound.value("audio_video_end_difference").toDouble() + 0.98) < 0.03);
    }

    void wordsWhereAPlayerPresentsThem()
    {
        const std::vector<Word> clean = spokenWords(align(kTiming + "clean.mp4", kTranscript));
        QCOMPARE(clean.size(), size_t(6));
        // The sound starts 0.5 s after the picture: every word 0.5 s later.
        verifyShifted(clean, spokenWords(align(kTiming + "audio_late_0.5s.mp4", kTranscript)), 0.5);
        // The same sound under other frame timings, and cut at 2.0 s.
        verifyShifted(clean, spokenWords(align(kTiming + "vfr.mp4", kTranscript)), 0.0);
        verifyShifted(clean, spokenWords(align(kTiming + "ntsc_29.97fps.mp4", kTranscript)), 0.0);
        verifyShifted(clean, spokenWords(align(kTiming + "audio_short_2s.mp4", kTranscript)), 0.0, 2.0);
        // Joined clips: as the sound plays with its gaps filled (clip k from 3k s). Concatenating
        // the decoded samples instead would put the second clip's words 48 ms and the third's 96 ms
        // early.
        const std::vector<Word> presented = spokenWords(align(kTiming + "joined_presented.flac", kTiming + "joined.txt"));
        QCOMPARE(presented.size(), size_t(18));
        verifyShifted(presented, spokenWords(align(kTiming + "joined_gaps_48ms.mkv", kTiming + "joined.txt")), 0.0);
        // The third clip's first word sits at its own picture's time: GRID's 0.69 s after 6 s.
        QVERIFY2(std::abs(presented[12].start - 6.69) < 0.05, qPrintable(QString::number(presented[12].start)));
    }

    // A frame is labelled by the sound while it is on screen: where the variable-rate clip shows a
    // frame for 40 ms, its label is the clean clip's label of the frame shown at the same time.
    void frameLabelsFollowFrameTimes()
    {
        const QJsonObject clean = align(kTiming + "clean.mp4", kTranscript);
        const QJsonObject vfr = align(kTiming + "vfr.mp4", kTranscript);
        const QJsonArray cleanLabels = clean.value("frameLabels").toArray();
        const QJsonArray vfrLabels = vfr.value("frameLabels").toArray();
        QCOMPARE(cleanLabels.size(), 75);
        const MediaInfo info = MediaInfo::probe((kTiming + "vfr.mp4").toStdString());
        QCOMPARE(vfrLabels.size(), info.frameCount);
        int compared = 0;
        for (int i = 0; i < info.frameCount; ++i) {
            if (std::abs(info.frames.endTime(i) - info.frames.time(i) - 0.04) > 1e-4)
                continue;
            const int same = int(std::lround(info.frames.time(i) * 25));
            QCOMPARE(vfrLabels[i].toString(), cleanLabels[same].toString());
            ++compared;
        }
        QVERIFY(compared > 30);
    }

    void rendersKeepTheSourceFrames_data()
    {
        QTest::addColumn<QString>("file");
        QTest::newRow("sound 0.5 s late") << "audio_late_0.5s.mp4";
        QTest::newRow("variable frame rate") << "vfr.mp4";
        QTest::newRow("29.97 fps") << "ntsc_29.97fps.mp4";
        QTest::newRow("sound shorter") << "audio_short_2s.mp4";
        QTest::newRow("clean") << "clean.mp4";
    }
    void rendersKeepTheSourceFrames()
    {
        QFETCH(QString, file);
        verifyRendersKeepFrames(kTiming + file);
    }
};

QTEST_GUILESS_MAIN(TestMediaTimelineCli)
#include "tst_mediatimelinecli.moc"
