// HTK .lab and .mlf round trips and bad input.
#include "io/HtkLabel.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

using namespace lipsync;

namespace {
const std::string kData = LIPSYNC_TEST_DATA "/speech/";
Tier sample()
{
    return Tier{"labels", {{0.0, 0.35, "sil", false}, {0.35, 0.87, "set", false}, {0.87, 1.0325, "white", false}}};
}
} // namespace

class TestHtkLabel : public QObject
{
    Q_OBJECT
private slots:
    void labRoundTrip()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("a.lab").toStdString();
        writeHtkLabel(path, sample());
        QCOMPARE(QString::fromStdString(formatHtkLabel(sample())).split('\n')[1], QStringLiteral("3500000 8700000 set"));
        bool timed = false;
        const Tier back = readHtkLabel(path, &timed);
        QVERIFY(timed);
        QVERIFY(back == sample());
    }

    void labExtras()
    {
        // Scores after the label are ignored; untimed labels; CRLF.
        const Tier scored = parseHtkLabel("0 100000 sil -12.5\r\n100000 300000 a -40.0 extra\r\n");
        QCOMPARE(scored.intervals.size(), size_t(2));
        QCOMPARE(scored.intervals[1].end, 0.03);
        bool timed = true;
        const Tier untimed = parseHtkLabel("sil\nhello\nsil\n", {}, &timed);
        QVERIFY(!timed);
        QCOMPARE(untimed.intervals[1].label, std::string("hello"));
    }

    void secondsAndComments()
    {
        // The .lab of wavesurfer / Audacity exports: times in seconds, '#' comment lines.
        bool timed = false;
        const Tier t = parseHtkLabel("# start end phone\n0 0.05 sil\n0.05 0.13 B\n\n0.13 2e-1 IH1\n", {}, &timed);
        QVERIFY(timed);
        QCOMPARE(t.intervals.size(), size_t(3));
        QCOMPARE(t.intervals[1].start, 0.05);
        QCOMPARE(t.intervals[2].end, 0.2);
        // The first timed line decides the unit: seconds inside a 100 ns file are an error.
        try {
            parseHtkLabel("0 500000 sil\n0.05 0.13 B\n", "mixed.lab");
            QFAIL("no error");
        } catch (const Error &e) {
            QCOMPARE(e.field(), std::string("line 2"));
        }
    }

    void mlfRoundTrip()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("all.mlf").toStdString();
        std::map<std::string, Tier> entries{{"*/bbaf2n.lab", sample()}, {"*/x.lab", Tier{"labels", {{0, 0.5, "sil", false}}}}};
        writeHtkMlf(path, entries);
        QVERIFY(readHtkMlf(path) == entries);
    }

    void badInput()
    {
        try {
            readHtkLabel(kData + "bad_time.lab");
            QFAIL("no error");
        } catch (const Error &e) {
            QCOMPARE(e.field(), std::string("line 2"));
            QVERIFY(e.file().find("bad_time.lab") != std::string::npos);
        }
        try {
            readHtkMlf(kData + "unterminated.mlf");
            QFAIL("no error");
        } catch (const Error &e) {
            QCOMPARE(e.field(), std::string("line 2"));
        }
        QVERIFY_THROWS_EXCEPTION(Error, parseHtkLabel("500 100 a\n"));
        QVERIFY_THROWS_EXCEPTION(Error, parseHtkLabel("0 100 a\n50 200 b\n"));
        QVERIFY_THROWS_EXCEPTION(Error, parseHtkLabel(""));
        QVERIFY_THROWS_EXCEPTION(Error, parseHtkMlf("\"*/a.lab\"\n0 1 a\n.\n"));
    }
};

QTEST_GUILESS_MAIN(TestHtkLabel)
#include "tst_htklabel.moc"
