// Phone set, CMU dictionary lookup (Debian pocketsphinx-en-us), espeak-ng fallback mapped to
// ARPAbet, project overrides, unknown words named in the error.
#include "align/EspeakPhonemizer.h"
#include "align/Lexicon.h"
#include "util/PhoneSet.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

#include <fstream>

using namespace lipsync;

namespace {
Pronunciation p(const char *phones)
{
    return PronunciationDictionary::parse(phones);
}
} // namespace

class TestLexicon : public QObject
{
    Q_OBJECT
private slots:
    void phoneSet()
    {
        QCOMPARE(PhoneSet::kCount, 41);
        QCOMPARE(PhoneSet::index("AH0"), PhoneSet::index("ah"));
        QCOMPARE(PhoneSet::index("sp"), PhoneSet::kSilence);
        QCOMPARE(PhoneSet::index(""), PhoneSet::kSilence);
        QCOMPARE(PhoneSet::index("spn"), PhoneSet::kBreath);
        QCOMPARE(PhoneSet::index("QQ"), -1);
        for (int i = 0; i < PhoneSet::kCount; ++i)
            QCOMPARE(PhoneSet::index(PhoneSet::label(i)), i);
    }

    void cmuDictionary()
    {
        const PronunciationDictionary &cmu = PronunciationDictionary::cmu();
        QVERIFY(cmu.size() > 100000);
        const auto *hello = cmu.find("Hello,");
        QVERIFY(hello);
        QCOMPARE(PronunciationDictionary::toString(hello->front()), std::string("HH AH L OW"));
        const auto *the = cmu.find("the");
        QVERIFY(the && the->size() == 2); // "the" and "the(2)"
        QCOMPARE(the->at(1), p("DH IY"));
        QVERIFY(cmu.find("blorfingtonia") == nullptr);
    }

    void readsVariantsAndRejectsBadPhones()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("d.dict").toStdString();
        {
            std::ofstream f(path);
            f << "tomato T AH0 M EY1 T OW2\ntomato(2) T AH0 M AA1 T OW2\n";
        }
        const PronunciationDictionary d = PronunciationDictionary::read(path);
        QCOMPARE(d.find("TOMATO")->size(), size_t(2));
        {
            std::ofstream f(path);
            f << "ok OW K EY\nbad B XX D\n";
        }
        try {
            PronunciationDictionary::read(path);
            QFAIL("no error");
        } catch (const Error &e) {
            QCOMPARE(e.field(), std::string("line 2"));
            QVERIFY(std::string(e.what()).find("XX") != std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(Error, PronunciationDictionary::read(dir.filePath("none.dict").toStdString()));
    }

    void espeakMapping()
    {
        QCOMPARE(EspeakPhonemizer::toArpabet("h_@_l_'oU"), p("HH AH L OW"));
        QCOMPARE(EspeakPhonemizer::toArpabet("w_'I_z_3_d"), p("W IH Z ER D"));
        QCOMPARE(EspeakPhonemizer::toArpabet("m_'E_Z_3 r_'I_N"), p("M EH ZH ER R IH NG"));
        // A real espeak-ng call for a word no dictionary has.
        const auto word = EspeakPhonemizer::pronounce("blorfington");
        QVERIFY(word.has_value());
        QVERIFY(word->size() >= 7);
        QCOMPARE(word->front(), PhoneSet::index("B"));
        QCOMPARE(word->back(), PhoneSet::index("N"));
    }

    void lexiconPrecedence()
    {
        const Lexicon lexicon(&PronunciationDictionary::cmu(), {{"Hello", {p("HH EH L OW")}}});
        Lexicon::Source source{};
        QCOMPARE(lexicon.pronounce("hello", &source).front(), p("HH EH L OW"));
        QCOMPARE(source, Lexicon::Source::Override);
        QCOMPARE(lexicon.pronounce("world", &source).front(), p("W ER L D"));
        QCOMPARE(source, Lexicon::Source::Dictionary);
        QVERIFY(!lexicon.pronounce("zorbulax", &source).empty());
        QCOMPARE(source, Lexicon::Source::Espeak);
        QCOMPARE(lexicon.pronounce("<VOCNOISE>", &source).front(), Pronunciation{PhoneSet::kBreath});
        QCOMPARE(Lexicon::splitWords("Hello, world!  [adif] -- ok"),
                 (std::vector<std::string>{"Hello,", "world!", "[adif]", "ok"}));
    }

    void unknownWordsAreNamed()
    {
        const Lexicon noFallback(nullptr, {{"known", {p("N OW N")}}}, false);
        try {
            noFallback.pronounceAll({"known", "zorbulax", "quibble"});
            QFAIL("no error");
        } catch (const Error &e) {
            const std::string what = e.what();
            QVERIFY(what.find("zorbulax") != std::string::npos);
            QVERIFY(what.find("quibble") != std::string::npos);
        }
    }
};

QTEST_GUILESS_MAIN(TestLexicon)
#include "tst_lexicon.moc"
