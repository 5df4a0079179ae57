// The forced-choice study design (paper section 4): every pair of methods twice per session with
// sides swapped, sides balanced per method, random but reproducible order, participants apart,
// and the JSON the studio stores in the project.
#include "project/ForcedChoiceStudy.h"

#include "util/Error.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <map>
#include <set>

using namespace lipsync;

namespace {

std::vector<std::string> utterancePool(int n)
{
    std::vector<std::string> pool;
    for (int i = 0; i < n; ++i)
        pool.push_back("utt" + std::to_string(i));
    return pool;
}

const std::vector<std::string> kPaperMethods{"real", "slds", "brand", "dpds"};

} // namespace

class TestStudyDesign : public QObject
{
    Q_OBJECT

private slots:
    void everyPairTwiceWithSidesSwapped_data()
    {
        QTest::addColumn<int>("methods");
        QTest::addColumn<int>("repeats");
        QTest::newRow("paper: 4 methods") << 4 << 1;
        QTest::newRow("5 methods") << 5 << 1;
        QTest::newRow("3 methods, 3 repeats") << 3 << 3;
    }
    void everyPairTwiceWithSidesSwapped()
    {
        QFETCH(int, methods);
        QFETCH(int, repeats);
        const std::vector<std::string> all{"real", "dpds", "slds", "brand", "hmm"};
        ForcedChoiceStudy study({all.begin(), all.begin() + methods}, utterancePool(80), 7, repeats);
        QCOMPARE(study.trialsPerSession(), methods * (methods - 1) * repeats);
        for (int p = 0; p < 6; ++p) {
            const StudySession &s = study.addParticipant("P" + std::to_string(p));
            QCOMPARE(int(s.trials.size()), study.trialsPerSession());
            std::map<std::pair<int, int>, int> ordered;
            std::vector<int> left(static_cast<size_t>(methods)), right(static_cast<size_t>(methods));
            for (const StudyTrial &t : s.trials) {
                QVERIFY(t.left != t.right);
                ++ordered[{t.left, t.right}];
                ++left[size_t(t.left)];
                ++right[size_t(t.right)];
                QVERIFY(!t.utterance.empty());
                QCOMPARE(t.choice, StudyChoice::Unanswered);
            }
            // Each unordered pair twice per repeat, once on each side.
            QCOMPARE(int(ordered.size()), methods * (methods - 1));
            for (const auto &[pair, count] : ordered)
                QCOMPARE(count, repeats);
            for (int m = 0; m < methods; ++m) {
                QCOMPARE(left[size_t(m)], (methods - 1) * repeats);
                QCOMPARE(right[size_t(m)], (methods - 1) * repeats);
            }
        }
    }

    void orderIsSeededAndPerParticipant()
    {
        auto design = [](std::uint64_t seed) {
            ForcedChoiceStudy study(kPaperMethods, utterancePool(80), seed);
            study.addParticipant("A");
            study.addParticipant("B");
            return study;
        };
        QVERIFY(design(42) == design(42));          // reproducible
        QVERIFY(!(design(42) == design(43)));       // the seed matters
        const ForcedChoiceStudy study = design(42);
        auto order = [](const StudySession &s) {
            std::vector<std::pair<int, int>> o;
            for (const StudyTrial &t : s.trials)
                o.push_back({t.left, t.right});
            return o;
        };
        QVERIFY(order(study.sessions()[0]) != order(study.sessions()[1])); // own order each
        QVERIFY(study.sessions()[0].seed != study.sessions()[1].seed);
        // Utterances are dealt without repetition while the pool lasts.
        std::set<std::string> seen;
        for (const StudyTrial &t : study.sessions()[0].trials)
            seen.insert(t.utterance);
        QCOMPARE(int(seen.size()), 12);
    }

    // The shuffle is uniform: over many sessions each ordered pair is first equally often
    // (1/12 for four methods); 2400 sessions, 200 expected, a 5-sigma band is +-70.
    void orderIsUniform()
    {
        ForcedChoiceStudy study(kPaperMethods, utterancePool(3), 1);
        std::map<std::pair<int, int>, int> first;
        std::map<std::string, int> utterances;
        for (int p = 0; p < 2400; ++p) {
            const StudySession &s = study.addParticipant(std::to_string(p));
            ++first[{s.trials[0].left, s.trials[0].right}];
            for (const StudyTrial &t : s.trials)
                ++utterances[t.utterance];
        }
        QCOMPARE(int(first.size()), 12);
        for (const auto &[pair, count] : first)
            QVERIFY2(std::abs(count - 200) < 70, qPrintable(QString::number(count)));
        // 12 trials over 3 utterances: each utterance exactly 4 times per session.
        for (const auto &[u, count] : utterances)
            QCOMPARE(count, 2400 * 4);
    }

    void participantsAreKeptApart()
    {
        ForcedChoiceStudy study(kPaperMethods, utterancePool(10), 3);
        study.addParticipant("P1");
        study.addParticipant("P2");
        QVERIFY_THROWS_EXCEPTION(Error, study.addParticipant("P1"));
        QVERIFY_THROWS_EXCEPTION(Error, study.addParticipant(""));
        study.answer(0, 0, StudyChoice::Left, 2.5);
        study.answer(0, 1, StudyChoice::Undecided);
        QCOMPARE(study.sessions()[0].answered(), 2);
        QCOMPARE(study.sessions()[0].nextTrial(), 2);
        QCOMPARE(study.sessions()[1].answered(), 0);
        QCOMPARE(study.sessions()[1].nextTrial(), 0);
        QVERIFY_THROWS_EXCEPTION(Error, study.answer(2, 0, StudyChoice::Left));
        QVERIFY_THROWS_EXCEPTION(Error, study.answer(1, 12, StudyChoice::Left));
    }

    void invalidDesignsAreRejected()
    {
        QVERIFY_THROWS_EXCEPTION(Error, ForcedChoiceStudy({"real"}, {"u"}, 1));
        QVERIFY_THROWS_EXCEPTION(Error, ForcedChoiceStudy({"real", "real"}, {"u"}, 1));
        QVERIFY_THROWS_EXCEPTION(Error, ForcedChoiceStudy({"real", "dpds"}, {}, 1));
        QVERIFY_THROWS_EXCEPTION(Error, ForcedChoiceStudy({"real", "dpds"}, {"u"}, 1, 0));
    }

    void jsonRoundTrip()
    {
        ForcedChoiceStudy study(kPaperMethods, utterancePool(20), 0xfedcba9876543210ull, 2);
        study.addParticipant("P1");
        study.addParticipant("P2");
        study.answer(0, 0, StudyChoice::Left, 3.25);
        study.answer(0, 5, StudyChoice::Right);
        study.answer(1, 3, StudyChoice::Undecided, 1.0);
        const QJsonObject json = study.toJson();
        QCOMPARE(json.value("format").toString(), QString("lipsync-forced-choice-study"));
        QCOMPARE(json.value("seed").toString(), QString("18364758544493064720"));
        const ForcedChoiceStudy back = ForcedChoiceStudy::fromJson(json, "study.json");
        QVERIFY(back == study);
        // The hold-out flag survives; a file without it reads as not held out.
        study.setHoldsOutUtterances(true);
        QVERIFY(ForcedChoiceStudy::fromJson(study.toJson(), "study.json").holdsOutUtterances());
        QJsonObject older = study.toJson();
        older.remove("holdOutUtterances");
        QVERIFY(!ForcedChoiceStudy::fromJson(older, "study.json").holdsOutUtterances());

        QTemporaryDir dir;
        const std::string path = dir.filePath("study.json").toStdString();
        study.save(path);
        QVERIFY(ForcedChoiceStudy::load(path) == study);
    }

    // The default draw: a fifth of the candidates, at least one, always one left to train on;
    // seeded and in the pool's order.
    void heldOutDraw()
    {
        QCOMPARE(ForcedChoiceStudy::defaultHeldOutCount(400), 80);
        QCOMPARE(ForcedChoiceStudy::defaultHeldOutCount(10), 2);
        QCOMPARE(ForcedChoiceStudy::defaultHeldOutCount(3), 1);
        QCOMPARE(ForcedChoiceStudy::defaultHeldOutCount(2), 1);
        const std::vector<std::string> pool = utterancePool(20);
        const std::vector<std::string> a = ForcedChoiceStudy::drawUtterances(pool, 4, 7);
        QCOMPARE(a.size(), size_t(4));
        QVERIFY(a == ForcedChoiceStudy::drawUtterances(pool, 4, 7));
        QVERIFY(a != ForcedChoiceStudy::drawUtterances(pool, 4, 8));
        QVERIFY(std::is_sorted(a.begin(), a.end(), [&](const std::string &x, const std::string &y) {
            return std::find(pool.begin(), pool.end(), x) < std::find(pool.begin(), pool.end(), y);
        }));
    }

    void badJsonNamesFileAndField_data()
    {
        QTest::addColumn<QString>("field");
        QTest::addColumn<QJsonValue>("value");
        QTest::addColumn<QString>("expected");
        QTest::newRow("format") << "format" << QJsonValue("other") << "study.json: format:";
        QTest::newRow("version") << "version" << QJsonValue(99) << "study.json: version:";
        QTest::newRow("methods") << "methods" << QJsonValue(QJsonArray{"real"}) << "study.json: methods:";
        QTest::newRow("seed") << "seed" << QJsonValue(12) << "study.json: seed:";
        QTest::newRow("holdOutUtterances") << "holdOutUtterances" << QJsonValue("yes") << "study.json: holdOutUtterances:";
        QTest::newRow("left") << "left" << QJsonValue("nonsense")
                              << "study.json: sessions[0].trials[1].left: unknown method \"nonsense\"";
        QTest::newRow("choice") << "choice" << QJsonValue("maybe")
                                << "study.json: sessions[0].trials[1].choice:";
    }
    void badJsonNamesFileAndField()
    {
        QFETCH(QString, field);
        QFETCH(QJsonValue, value);
        QFETCH(QString, expected);
        ForcedChoiceStudy study(kPaperMethods, utterancePool(5), 1);
        study.addParticipant("P1");
        QJsonObject json = study.toJson();
        if (field == "left" || field == "choice") {
            QJsonArray sessions = json["sessions"].toArray();
            QJsonObject session = sessions[0].toObject();
            QJsonArray trials = session["trials"].toArray();
            QJsonObject trial = trials[1].toObject();
            trial[field] = value;
            trials[1] = trial;
            session["trials"] = trials;
            sessions[0] = session;
            json["sessions"] = sessions;
        } else {
            json[field] = value;
        }
        try {
            ForcedChoiceStudy::fromJson(json, "study.json");
            QFAIL("expected lipsync::Error");
        } catch (const Error &e) {
            QVERIFY2(QString(e.what()).startsWith(expected), e.what());
        }
    }

    void unreadableFilesAreClearErrors()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.json");
        QFile file(path);
        QVERIFY(file.open(QIODevice::WriteOnly));
        file.write("{ not json");
        file.close();
        try {
            ForcedChoiceStudy::load(path.toStdString());
            QFAIL("expected lipsync::Error");
        } catch (const Error &e) {
            QCOMPARE(e.file(), path.toStdString());
        }
        QVERIFY_THROWS_EXCEPTION(Error, ForcedChoiceStudy::load(dir.filePath("missing.json").toStdString()));
        ForcedChoiceStudy study(kPaperMethods, utterancePool(5), 1);
        QVERIFY_THROWS_EXCEPTION(Error, study.save(dir.filePath("no/such/dir/s.json").toStdString()));
    }
};

QTEST_GUILESS_MAIN(TestStudyDesign)
#include "tst_studydesign.moc"
