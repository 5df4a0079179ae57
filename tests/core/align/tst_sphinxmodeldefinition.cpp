// SphinxModelDefinition: the binary mdef of a CMU Sphinx model.
//  - tests/data/sphinx/tiny.mdef, converted by Debian's pocketsphinx_mdef_convert from the text
//    form beside it: CI phones, fillers, triphone lookup and senone sequences as in the text.
//  - The installed en-us model (pocketsphinx-en-us; skipped when absent): its counts and two
//    triphones' senones as `pocketsphinx_mdef_convert -text` lists them.
//  - Bad input (text mdef, truncated, corrupt counts and ids): lipsync::Error naming the file.
#include "align/SphinxAligner.h"
#include "align/SphinxModelDefinition.h"
#include "util/Error.h"

#include <QTest>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

using namespace lipsync;
using Position = SphinxModelDefinition::Position;

namespace {

const std::string kTiny = LIPSYNC_TEST_DATA "/sphinx/tiny.mdef";

std::string bytesOf(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<int> senones(const SphinxModelDefinition &m, int phone)
{
    const uint16_t *s = m.senones(phone);
    return std::vector<int>(s, s + m.statesPerPhone());
}

void expectError(const std::string &bytes, const char *what)
{
    try {
        SphinxModelDefinition::parse(bytes, "bad.mdef");
        QFAIL(qPrintable(QStringLiteral("accepted: %1").arg(what)));
    } catch (const Error &e) {
        QCOMPARE(e.file(), std::string("bad.mdef"));
        QVERIFY2(!e.reason().empty(), what);
    }
}

} // namespace

class TestSphinxModelDefinition : public QObject
{
    Q_OBJECT

private slots:
    void readsTheTinyModel()
    {
        const SphinxModelDefinition m = SphinxModelDefinition::read(kTiny);
        QCOMPARE(m.ciPhoneCount(), 3);
        QCOMPARE(m.phoneCount(), 5);
        QCOMPARE(m.senoneCount(), 12);
        QCOMPARE(m.statesPerPhone(), 3);
        const int nsn = m.ciPhone("+NSN+"), aa = m.ciPhone("AA"), sil = m.ciPhone("SIL");
        QCOMPARE(aa, 1);
        QCOMPARE(m.silence(), sil);
        QCOMPARE(m.ciPhone("ZH"), -1);
        QVERIFY(m.isFiller(nsn));
        QVERIFY(m.isFiller(sil));
        QVERIFY(!m.isFiller(aa));
        QCOMPARE(senones(m, aa), (std::vector<int>{3, 4, 5}));
        // "AA AA SIL b ... 9 4 11" and "AA SIL SIL s ... 9 10 11" (tiny-mdef.txt).
        const int begin = m.triphone(aa, aa, sil, Position::Begin);
        const int single = m.triphone(aa, sil, sil, Position::Single);
        QVERIFY(begin >= 3 && single >= 3 && begin != single);
        QCOMPARE(senones(m, begin), (std::vector<int>{9, 4, 11}));
        QCOMPARE(senones(m, single), (std::vector<int>{9, 10, 11}));
        QCOMPARE(m.triphone(aa, aa, sil, Position::End), -1);
        QCOMPARE(m.triphone(aa, sil, aa, Position::Single), -1);
    }

    void readsTheInstalledEnglishModel()
    {
        if (!SphinxAligner::available())
            QSKIP("the CMU Sphinx en-us model (Debian pocketsphinx-en-us) is not installed");
        const SphinxModelDefinition m =
            SphinxModelDefinition::read(SphinxAligner::resolveModelDir({}) + "/mdef");
        QCOMPARE(m.ciPhoneCount(), 42);
        QCOMPARE(m.phoneCount(), 42 + 137053);
        QCOMPARE(m.senoneCount(), 5126);
        QCOMPARE(m.ciName(m.silence()), std::string("SIL"));
        const int aa = m.ciPhone("AA"), ah = m.ciPhone("AH"), zh = m.ciPhone("ZH"), w = m.ciPhone("W");
        QCOMPARE(senones(m, aa), (std::vector<int>{6, 7, 8}));
        // "AA AA AH s n/a 2 158 165 210" and "ZH ZH W b n/a 41 5119 5121 5124".
        QCOMPARE(senones(m, m.triphone(aa, aa, ah, Position::Single)), (std::vector<int>{158, 165, 210}));
        QCOMPARE(senones(m, m.triphone(zh, zh, w, Position::Begin)), (std::vector<int>{5119, 5121, 5124}));
    }

    void badInputIsNamed()
    {
        const std::string good = bytesOf(kTiny);
        QVERIFY(good.size() > 100);
        expectError(bytesOf(LIPSYNC_TEST_DATA "/sphinx/tiny-mdef.txt"), "a text mdef");
        expectError({}, "empty");
        expectError("BMDF", "magic only");
        for (size_t cut : {size_t(12), good.size() / 2, good.size() - 1})
            expectError(good.substr(0, cut), "truncated");
        // The counts follow the header: corrupt the CI phone count and the last senone id.
        const size_t counts = 12 + size_t(uint8_t(good[8])) + (size_t(uint8_t(good[9])) << 8);
        std::string bad = good;
        bad[counts] = 0;
        expectError(bad, "no CI phones");
        bad = good;
        bad[bad.size() - 1] = char(0x7f);
        expectError(bad, "a senone out of range");
        try {
            SphinxModelDefinition::read("/nonexistent/mdef");
            QFAIL("a missing file was read");
        } catch (const Error &e) {
            QCOMPARE(e.file(), std::string("/nonexistent/mdef"));
        }
    }
};

QTEST_GUILESS_MAIN(TestSphinxModelDefinition)
#include "tst_sphinxmodeldefinition.moc"
