// Transcripts from every accepted format, GRID .align round trip, plain text, subtitles.
#include "io/AtomicFile.h"
#include "io/GridAlign.h"
#include "io/HtkLabel.h"
#include "io/Subtitles.h"
#include "io/TextGrid.h"
#include "io/Transcript.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;

class TestTranscript : public QObject
{
    Q_OBJECT
private slots:
    void allFormatsGiveTheSameWords()
    {
        QTemporaryDir dir;
        const Tier words{"words", {{0, 0.35, "sil", false}, {0.35, 0.87, "set", false}, {0.87, 0.9, "sp", false},
                                   {0.9, 1.2, "white", false}, {1.2, 3.0, "sil", false}}};
        const std::string base = dir.path().toStdString() + "/u";
        writeGridAlign(base + ".align", words);
        writeHtkLabel(base + ".lab", words);
        writeTextGrid(base + ".TextGrid", makeTextGrid({words}));
        writePlainTranscript(base + ".txt", Transcript{{"set", "white"}, {}});
        for (const std::string ext : {".align", ".lab", ".TextGrid", ".txt"}) {
            const Transcript t = readTranscript(base + ext);
            QCOMPARE(t.text(), std::string("set white"));
            QCOMPARE(t.hasTiming(), ext != ".txt");
        }
        // GRID .align round trip keeps times in 1/25000 s.
        QVERIFY(readGridAlign(base + ".align") == words);
    }

    // SubRip and WebVTT as users get them: numbers and identifiers, CRLF, a BOM, markup,
    // entities, sound descriptions, dialogue dashes, settings after the times, NOTE blocks.
    void subtitlesGiveCueTimesAndSpokenWords()
    {
        const std::string srt = "\xEF\xBB\xBF" "1\r\n00:00:01,000 --> 00:00:02,500\r\n<i>Set white</i> with\r\np two now\r\n\r\n"
                                "2\r\n00:00:03,250 --> 00:00:04,000 X1:10 X2:20\r\n[Music]\r\n\r\n"
                                "3\r\n01:00:05.5 --> 01:00:07.25\r\n- Bin blue &amp; green.\r\n- (laughs) Again!\r\n";
        const Tier cues = parseTranscript(srt, "clip.srt").cues;
        QCOMPARE(cues.intervals.size(), size_t(2)); // the music-only cue has no speech
        QCOMPARE(cues.intervals[0].start, 1.0);
        QCOMPARE(cues.intervals[0].end, 2.5);
        QCOMPARE(cues.intervals[0].label, std::string("Set white with p two now"));
        QCOMPARE(cues.intervals[1].start, 3605.5);
        QCOMPARE(cues.intervals[1].end, 3607.25);
        QCOMPARE(cues.intervals[1].label, std::string("Bin blue & green. Again!"));

        const std::string vtt = "WEBVTT - a header\nKind: captions\n\nNOTE this is\na comment\n\n"
                                "intro\n00:01.000 --> 00:02.000 align:start position:10%\n<v Anna>lay red</v> "
                                "<00:01.500><c.loud>at</c>\n\n00:00:02.500 --> 00:00:03.000\n\u266A la la \u266A now {\\an8}\n";
        const Tier webvtt = parseTranscript(vtt, "clip.VTT").cues;
        QCOMPARE(webvtt.intervals.size(), size_t(2));
        QCOMPARE(webvtt.intervals[0].label, std::string("lay red at"));
        QCOMPARE(webvtt.intervals[0].start, 1.0);
        QCOMPARE(webvtt.intervals[1].label, std::string("now"));
        QCOMPARE(webvtt.intervals[1].end, 3.0);

        // As a transcript: the words of every cue, and the cues kept as anchors.
        QTemporaryDir dir;
        const std::string path = dir.path().toStdString() + "/clip.srt";
        writeFileAtomically(path, srt);
        const Transcript t = readTranscript(path);
        QCOMPARE(t.text(), std::string("Set white with p two now Bin blue & green. Again!"));
        QCOMPARE(t.cues.intervals.size(), size_t(2));
        QVERIFY(!t.hasTiming()); // cue times are not word times
    }

    void badSubtitles()
    {
        const auto error = [](const std::string &bytes, const std::string &path) -> std::string {
            try {
                parseTranscript(bytes, path);
            } catch (const Error &e) {
                return e.what();
            }
            return {};
        };
        std::string e = error("1\n00:00:01,000 --> 00:00:00,500\nhi\n", "a.srt");
        QVERIFY2(e.find("ends before it starts") != std::string::npos && e.find("a.srt") != std::string::npos
                     && e.find("line 2") != std::string::npos,
                 e.c_str());
        e = error("1\n00:00:01 --> 00:00:02,000\nhi\n", "a.srt");
        QVERIFY2(e.find("not a cue time line") != std::string::npos, e.c_str());
        e = error("1\njust text\nmore\n", "a.srt");
        QVERIFY2(e.find("without a time line") != std::string::npos, e.c_str());
        e = error("00:01.000 --> 00:02.000\nhi\n", "a.vtt");
        QVERIFY2(e.find("starts with WEBVTT") != std::string::npos, e.c_str());
        e = error("1\n00:00:01,000 --> 00:61:00,000\nhi\n", "a.srt");
        QVERIFY2(e.find("not a cue time line") != std::string::npos, e.c_str());
        // Only music: no words, an error naming the file.
        QTemporaryDir dir;
        const std::string path = dir.path().toStdString() + "/m.vtt";
        writeFileAtomically(path, "WEBVTT\n\n00:01.000 --> 00:02.000\n[Music]\n");
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(path));
    }

    void mfaStyleLabIsPlainText()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("m.lab");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("HE BEGAN A CONFUSED COMPLAINT\n");
        f.close();
        const Transcript t = readTranscript(path.toStdString());
        QCOMPARE(t.words.size(), size_t(5));
        QVERIFY(!t.hasTiming());
    }

    void badInput()
    {
        QTemporaryDir dir;
        const QString empty = dir.filePath("empty.txt");
        QFile f(empty);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("  \n");
        f.close();
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(empty.toStdString()));
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(dir.filePath("u.doc").toStdString()));
        QVERIFY_THROWS_EXCEPTION(Error, readTranscript(dir.filePath("missing.align").toStdString()));
    }
};

QTEST_GUILESS_MAIN(TestTranscript)
#include "tst_transcript.moc"
