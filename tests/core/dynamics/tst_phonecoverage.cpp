// PhoneCoverage: the frames of each speech phone in a model's training footage, the phones
// never seen and those too rare for a variance of their own, the speech's length, and the plain
// advice when the footage is too short for the options (phones in context without states), and
// for a trained model what it did (its context states, whether it started from other speakers).
#include "dynamics/PhoneCoverage.h"

#include "dynamics/ModelFile.h"
#include "tasks/Feedback.h"

#include <QJsonArray>
#include <QTest>

using namespace lipsync;

namespace {

LabelledSequence sequence(const std::vector<std::pair<const char *, int>> &runs, double fps = 25.0)
{
    LabelledSequence s;
    s.frameRate = fps;
    for (const auto &[phone, frames] : runs)
        for (int i = 0; i < frames; ++i)
            s.labels.push_back(PhoneSet::index(phone));
    s.features = Eigen::MatrixXd::Zero(Eigen::Index(s.labels.size()), 2);
    return s;
}

} // namespace

class TestPhoneCoverage : public QObject
{
    Q_OBJECT
private slots:
    void countsUnseenAndRarePhones()
    {
        const PhoneCoverage c = PhoneCoverage::of({sequence({{"sil", 20}, {"B", 12}, {"AA", 3}, {"sil", 10}}),
                                                   sequence({{"AA", 4}, {"T", 25}, {"br", 5}})});
        QCOMPARE(c.frames[size_t(PhoneSet::index("AA"))], 7LL);
        QCOMPARE(c.frames[size_t(PhoneSet::kSilence)], 30LL);
        QCOMPARE(int(c.unseen.size()), PhoneCoverage::kSpeechPhones - 3); // B, AA and T seen
        QCOMPARE(c.rare, std::vector<std::string>{"AA"}); // 7 < 10 frames
        QVERIFY(std::abs(c.speechSeconds - (12 + 7 + 25) / 25.0) < 1e-12); // silence and breath left out
        const std::string advice = c.advice();
        QVERIFY2(advice.find("36 of 39 phones never occur") != std::string::npos, advice.c_str());
        QVERIFY2(advice.find("1 have fewer than 10 frames (AA)") != std::string::npos, advice.c_str());
        QVERIFY2(advice.find("guesses their face from the average") != std::string::npos, advice.c_str());
        QVERIFY2(advice.find("other speakers") == std::string::npos, advice.c_str()); // a kind without the prior
        PhoneCoverage withPrior = c;
        withPrior.takesPrior = true; // HMM-mean or Brand: the prior is offered ...
        QVERIFY2(withPrior.advice().find("Starting from other speakers' mouths") != std::string::npos,
                 withPrior.advice().c_str());
        withPrior.prior = true; // ... and once taken, the unseen phones are the prior's
        QVERIFY2(withPrior.advice().find("their face comes from other speakers' mouths") != std::string::npos
                     && withPrior.advice().find("Starting from") == std::string::npos,
                 withPrior.advice().c_str());
        QVERIFY(withPrior.toJson().value("prior").toBool());
        const QJsonObject json = c.toJson();
        QVERIFY(!json.value("prior").toBool());
        QCOMPARE(json.value("unseen").toArray().size(), 36);
        QCOMPARE(json.value("rare").toArray().first().toString(), QStringLiteral("AA"));
    }

    void saysWhenPhonesInContextMadeNoStates()
    {
        std::vector<std::pair<const char *, int>> all;
        for (int n = 0; n < PhoneSet::kCount; ++n)
            all.push_back({PhoneSet::labels()[size_t(n)].data(), 12});
        // The labels' storage outlives the call: PhoneSet's static table.
        PhoneCoverage c = PhoneCoverage::of({sequence(all)});
        QVERIFY(c.unseen.empty() && c.rare.empty());
        QVERIFY(c.advice().empty()); // every phone covered, no context asked for
        c.contextStates = PhoneSet::kCount; // one state per phone: no split
        QVERIFY(c.advice().find("made no context states") != std::string::npos);
        c.contextStates = 120;
        QVERIFY(c.advice().empty());
    }

    // For a trained model the coverage reads what the model did: its context states, whether its
    // kind takes a prior and whether it started from one.
    void readsWhatTheModelDid()
    {
        std::vector<std::pair<const char *, int>> all;
        for (int n = 0; n < PhoneSet::kCount; ++n)
            all.push_back({PhoneSet::labels()[size_t(n)].data(), 12});
        std::vector<LabelledSequence> data{sequence(all)};
        data.front().features = Eigen::MatrixXd::Random(data.front().features.rows(), 2);
        Feedback feedback;
        ModelOptions options;
        options.meanShift = Eigen::MatrixXd::Zero(PhoneSet::kCount, 2);
        options.meanShift(0, 0) = 0.5;
        auto shifted = createDynamicModel("hmm", options);
        shifted->train(data, feedback);
        PhoneCoverage c = PhoneCoverage::of(data, *shifted);
        QVERIFY(c.takesPrior && c.prior);
        QCOMPARE(c.contextStates, 0);
        QCOMPARE(c.frames, PhoneCoverage::of(data).frames);
        ModelOptions inContext;
        inContext.contextStates = true;
        auto context = createDynamicModel("brand", inContext);
        context->train(data, feedback);
        c = PhoneCoverage::of(data, *context);
        QVERIFY(c.takesPrior && !c.prior);
        QVERIFY(c.contextStates >= PhoneSet::kCount);
        // Asked for and weighed at nothing, the prior is not offered again.
        PhoneCoverage few = PhoneCoverage::of({sequence({{"AA", 3}})}, *context);
        QVERIFY(few.advice().find("Starting from other speakers") != std::string::npos);
        few.priorTried = true;
        QVERIFY(few.advice().find("Starting from other speakers") == std::string::npos);
        c = PhoneCoverage::of(data, *createDynamicModel("slds"));
        QVERIFY(!c.takesPrior && !c.prior);
    }
};

QTEST_GUILESS_MAIN(TestPhoneCoverage)
#include "tst_phonecoverage.moc"
