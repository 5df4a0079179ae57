// Context-dependent states (docs/models.md §5.2): frame contexts, tree growth that finds a real
// context effect and ignores noise, the model file form and its bad input, and a model over the
// states that generates what the contexts imply.
#include "SyntheticDynamics.h"

#include "dynamics/ContextDependentModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/ModelFile.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QJsonArray>
#include <QTest>

using namespace lipsync;
using namespace lipsync::test;

namespace {

int ph(const char *label) { return PhoneSet::index(label); }

// Labels cycling through AA, B, IY and AA, T, IY with silences; the first dimension of an AA frame
// is +2 before B and -2 before T (an anticipated lip closure), the second dimension of every
// frame is noise that no context explains.
std::vector<LabelledSequence> anticipation(std::mt19937 &rng, int sequences)
{
    std::normal_distribution<double> noise(0.0, 0.3);
    std::uniform_int_distribution<int> run(2, 5), coin(0, 1);
    std::vector<LabelledSequence> data;
    for (int s = 0; s < sequences; ++s) {
        LabelledSequence seq;
        seq.name = "seq" + std::to_string(s);
        std::vector<int> phones = {ph("sil")};
        for (int w = 0; w < 6; ++w)
            for (int p : {ph("AA"), coin(rng) ? ph("B") : ph("T"), ph("IY")})
                phones.push_back(p);
        phones.push_back(ph("sil"));
        for (int p : phones)
            for (int i = run(rng); i > 0; --i)
                seq.labels.push_back(p);
        const std::vector<PhoneContext> contexts = frameContexts(seq.labels);
        seq.features.resize(Eigen::Index(seq.labels.size()), 2);
        for (size_t t = 0; t < contexts.size(); ++t) {
            double mean = 0.0;
            if (contexts[t].phone == ph("AA"))
                mean = contexts[t].right == ph("B") ? 2.0 : -2.0;
            seq.features(Eigen::Index(t), 0) = mean + noise(rng);
            seq.features(Eigen::Index(t), 1) = noise(rng);
        }
        data.push_back(std::move(seq));
    }
    return data;
}

} // namespace

class TestContextTree : public QObject
{
    Q_OBJECT
private slots:
    void contextsOfFrames()
    {
        const std::vector<int> labels = {ph("sil"), ph("B"), ph("B"), ph("B"), ph("AA"), ph("AA"), ph("M")};
        const std::vector<PhoneContext> c = frameContexts(labels);
        QCOMPARE(int(c.size()), 7);
        QCOMPARE(c[0].left, ph("sil")); // before the utterance: silence
        QCOMPARE(c[0].right, ph("B"));
        for (int t : {1, 2, 3}) {
            QCOMPARE(c[size_t(t)].phone, ph("B"));
            QCOMPARE(c[size_t(t)].left, ph("sil"));
            QCOMPARE(c[size_t(t)].right, ph("AA"));
            QCOMPARE(c[size_t(t)].position, t - 1); // thirds of a three-frame segment
        }
        QCOMPARE(c[4].position, 0);
        QCOMPARE(c[5].position, 1); // frame 1 of 2: 3 * 1 / 2 = 1
        QCOMPARE(c[6].right, ph("sil")); // after the utterance: silence
        QCOMPARE(c[6].left, ph("AA"));
    }

    // The plain tree is the plain phone model: one state per phone, state = phone.
    void plainTreeIsThePhones()
    {
        const ContextTree tree;
        QCOMPARE(tree.stateCount(), PhoneSet::kCount);
        std::mt19937 rng(1);
        const std::vector<int> labels = randomLabels(rng, 200, {0, 5, 17, 30});
        QCOMPARE(tree.states(labels), labels);
        QCOMPARE(tree.describe(ph("M")), std::string("M"));
        // 19 classes and 41 phones on either side, 3 positions (docs/models.md §5.2).
        QCOMPARE(int(ContextTree::questionNames().size()), 2 * (19 + PhoneSet::kCount) + 3);
    }

    // AA splits by its right neighbour and nothing else does: the noise dimension and the other
    // phones carry no context effect, and the MDL threshold keeps them single states.
    void growsTheSplitTheDataHas()
    {
        std::mt19937 rng(7);
        const auto data = anticipation(rng, 40);
        Feedback feedback;
        const ContextTree tree = ContextTree::grow(data, {}, feedback);
        QCOMPARE(tree.stateCount(), PhoneSet::kCount + 1);
        const int beforeB = tree.state({ph("AA"), ph("IY"), ph("B"), 1});
        const int beforeT = tree.state({ph("AA"), ph("IY"), ph("T"), 1});
        QVERIFY(beforeB != beforeT);
        // Contexts never seen in training still get a state: AA before M asks the same question.
        const int beforeM = tree.state({ph("AA"), ph("sil"), ph("M"), 0});
        QVERIFY(beforeM == beforeB || beforeM == beforeT);
        const std::string path = tree.describe(beforeB);
        QVERIFY2(path.rfind("AA: ", 0) == 0 && path.find("R-") != std::string::npos, path.c_str());
        // A larger minimum occupancy than AA's frames forbids the split.
        ContextTreeOptions strict;
        strict.minOccupancy = 100000;
        QCOMPARE(ContextTree::grow(data, strict, feedback).stateCount(), PhoneSet::kCount);
    }

    // HMM-mean over the tied states generates the context's mean, which the phone model cannot.
    void contextModelGeneratesTheContextMeans()
    {
        std::mt19937 rng(11);
        const auto training = anticipation(rng, 40);
        const auto test = anticipation(rng, 5);
        Feedback feedback;
        ContextDependentModel context(std::make_unique<HmmMeanModel>());
        context.train(training, feedback);
        HmmMeanModel plain;
        plain.train(training, feedback);
        QCOMPARE(context.kind(), std::string("hmm"));
        QCOMPARE(context.inner().stateCount(), PhoneSet::kCount + 1);
        double contextError = 0.0, plainError = 0.0;
        for (const LabelledSequence &s : test) {
            contextError += (context.generate(s.labels) - s.features).col(0).cwiseAbs().mean();
            plainError += (plain.generate(s.labels) - s.features).col(0).cwiseAbs().mean();
            QVERIFY(context.logLikelihood(s.labels, s.features) > plain.logLikelihood(s.labels, s.features));
        }
        QVERIFY2(contextError < 0.5 * plainError,
                 qPrintable(QStringLiteral("%1 vs %2").arg(contextError).arg(plainError)));
        // Labels are phones, checked as phones.
        QVERIFY_THROWS_EXCEPTION(Error, context.generate({PhoneSet::kCount}));
    }

    void jsonRoundTripAndBadTrees()
    {
        std::mt19937 rng(3);
        Feedback feedback;
        const ContextTree tree = ContextTree::grow(anticipation(rng, 40), {}, feedback);
        const ContextTree read = ContextTree::fromJson(tree.toJson(), "m.json");
        QCOMPARE(read.stateCount(), tree.stateCount());
        const std::vector<int> labels = anticipation(rng, 1).front().labels;
        QCOMPARE(read.states(labels), tree.states(labels));
        QCOMPARE(read.toJson(), tree.toJson());

        const auto broken = [&](const std::function<void(QJsonObject &)> &edit) {
            QJsonObject json = tree.toJson();
            edit(json);
            return errorOf([&] { ContextTree::fromJson(json, "m.json"); });
        };
        // The AA tree (index 0) is the one with a question.
        const auto editAA = [](QJsonObject &json, const std::function<void(QJsonArray &)> &edit) {
            QJsonArray trees = json[QStringLiteral("trees")].toArray();
            QJsonObject aa = trees[0].toObject();
            QJsonArray nodes = aa[QStringLiteral("nodes")].toArray();
            edit(nodes);
            aa[QStringLiteral("nodes")] = nodes;
            trees[0] = aa;
            json[QStringLiteral("trees")] = trees;
        };
        std::string e = broken([&](QJsonObject &json) {
            editAA(json, [](QJsonArray &nodes) {
                QJsonObject root = nodes[0].toObject();
                root[QStringLiteral("ask")] = QStringLiteral("L-martian");
                nodes[0] = root;
            });
        });
        QVERIFY2(e.find("unknown question 'L-martian'") != std::string::npos && e.find("m.json") != std::string::npos,
                 e.c_str());
        e = broken([&](QJsonObject &json) {
            editAA(json, [](QJsonArray &nodes) {
                QJsonObject root = nodes[0].toObject();
                root[QStringLiteral("yes")] = 0; // a cycle
                nodes[0] = root;
            });
        });
        QVERIFY2(e.find("follow their parent") != std::string::npos, e.c_str());
        e = broken([&](QJsonObject &json) {
            editAA(json, [](QJsonArray &nodes) { nodes[1] = QJsonObject{{QStringLiteral("state"), 5}}; });
        });
        QVERIFY2(e.find("used twice") != std::string::npos, e.c_str());
        e = broken([](QJsonObject &json) { json[QStringLiteral("states")] = 3; });
        QVERIFY2(e.find("at least 41") != std::string::npos, e.c_str());
        e = broken([](QJsonObject &json) { json[QStringLiteral("trees")] = QJsonArray(); });
        QVERIFY2(e.find("one tree per phone") != std::string::npos, e.c_str());
    }

    // Training canceled inside the inner model leaves the context model untrained and its inner
    // model at the states it had.
    void cancelLeavesTheModelUnchanged()
    {
        std::mt19937 rng(5);
        const auto data = anticipation(rng, 20);
        ContextDependentModel model(createDynamicModel(ModelKind::Dpds));
        Feedback feedback;
        feedback.cancel();
        QVERIFY_THROWS_EXCEPTION(Canceled, model.train(data, feedback));
        QVERIFY(!model.isTrained());
        QCOMPARE(model.inner().stateCount(), PhoneSet::kCount);
        QCOMPARE(model.tree().stateCount(), PhoneSet::kCount);
    }
};

QTEST_GUILESS_MAIN(TestContextTree)
#include "tst_contexttree.moc"
