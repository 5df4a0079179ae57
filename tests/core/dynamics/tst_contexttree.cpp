// Context-dependent states (docs/models.md §5.2): frame contexts, tree growth that finds a real
// context effect and ignores noise, the model file form and its bad input, and a model over the
// states that generates what the contexts imply.
#include "SyntheticDynamics.h"

#include "dynamics/ContextDependentModel.h"
#include "dynamics/HmmMeanModel.h"
#include "dynamics/ModelFile.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <functional>
#include <map>

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

    // Live cannot wait for the next phone: the prompt streamer takes each frame's context from the
    // tree's prediction (each phone's most frequent successor and median segment length in
    // training) and emits every frame as its label comes. A tree without a prediction (an older
    // model file) keeps waiting; a damaged prediction is refused.
    void promptStreamingGuessesTheContext()
    {
        std::mt19937 rng(17);
        const auto training = anticipation(rng, 40);
        // The prediction counted here, independently.
        std::map<int, std::map<int, int>> successors;
        std::map<int, std::vector<int>> lengths;
        for (const LabelledSequence &s : training)
            for (size_t start = 0, end = 0; start < s.labels.size(); start = end) {
                for (end = start; end < s.labels.size() && s.labels[end] == s.labels[start]; ++end) {
                }
                ++successors[s.labels[start]][end < s.labels.size() ? s.labels[end] : ph("sil")];
                lengths[s.labels[start]].push_back(int(end - start));
            }
        Feedback feedback;
        ContextDependentModel model(std::make_unique<HmmMeanModel>());
        model.train(training, feedback);
        const ContextTree &tree = model.tree();
        QVERIFY(tree.hasPrediction());
        for (const char *phone : {"AA", "B", "T", "IY"}) {
            const int p = ph(phone);
            std::vector<int> &l = lengths[p];
            std::sort(l.begin(), l.end());
            const int median = l[l.size() / 2];
            int next = -1, most = -1;
            for (const auto &[q, count] : successors[p])
                if (count > most) {
                    most = count;
                    next = q;
                }
            for (int i : {0, median / 2, median - 1, median, 3 * median}) {
                const PhoneContext c = tree.predicted(p, ph("sil"), i);
                QCOMPARE(c.right, next);
                QCOMPARE(c.position, segmentPosition(std::min(i, median - 1), median));
            }
        }
        // Each frame out at most kPromptWait labels after its own: with its true context when its
        // phone has ended by then, else with the guessed one, its segment at least as long as seen.
        const std::vector<int> labels = anticipation(rng, 1).front().labels;
        constexpr int K = ContextDependentModel::kPromptWait;
        std::vector<int> expected;
        const std::vector<PhoneContext> truth = frameContexts(labels);
        for (size_t t = 0, i = 0; t < labels.size(); ++t, ++i) {
            if (t > 0 && labels[t] != labels[t - 1])
                i = 0;
            size_t n = 0; // the segment's length
            while (t - i + n < labels.size() && labels[t - i + n] == labels[t])
                ++n;
            if (n >= i + K + 1) {
                PhoneContext c = tree.predicted(labels[t], truth[t].left, int(i));
                c.position = segmentPosition(int(i), std::max(tree.predictedLength(labels[t]), int(i) + K + 1));
                expected.push_back(tree.state(c));
            } else {
                expected.push_back(tree.state(truth[t]));
            }
        }
        auto prompt = model.promptStreamer();
        QCOMPARE(prompt->latency(), K);
        Eigen::VectorXd frame(2);
        int out = 0;
        for (size_t t = 0; t < labels.size(); ++t) {
            prompt->push(labels[t]);
            while (prompt->pop(frame))
                ++out;
            QVERIFY(int(t) + 1 - out <= K);
        }
        // With long silences some frames were guessed, and some guesses differ from the truth.
        QVERIFY(expected != tree.states(labels));
        QVERIFY((model.generateStreamed(labels, true) - model.inner().generate(expected)).cwiseAbs().maxCoeff() < 1e-12);
        QVERIFY(model.streamer()->latency() < 0); // the exact streamer still waits

        // The prediction travels in the model file; a model file without it waits for each phone
        // to end in Live too.
        QTemporaryDir dir;
        const std::string path = dir.filePath(QStringLiteral("context.model")).toStdString();
        saveModel(model, path, "aam-test");
        QVERIFY((loadModel(path)->generateStreamed(labels, true) - model.generateStreamed(labels, true)).cwiseAbs().maxCoeff()
                < 1e-12);
        QFile file(QString::fromStdString(path));
        QVERIFY(file.open(QIODevice::ReadOnly));
        QJsonObject o = QJsonDocument::fromJson(file.readAll()).object();
        file.close();
        QJsonObject context = o[QStringLiteral("context")].toObject();
        context.remove(QStringLiteral("next"));
        context.remove(QStringLiteral("length"));
        o[QStringLiteral("context")] = context;
        QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
        file.write(QJsonDocument(o).toJson());
        file.close();
        const auto older = loadModel(path);
        QVERIFY(older->promptStreamer()->latency() < 0);
        QVERIFY((older->generateStreamed(labels, true) - model.generate(labels)).cwiseAbs().maxCoeff() < 1e-12);
        for (const auto &edit : std::vector<std::function<void(QJsonObject &)>>{
                 [](QJsonObject &j) { j[QStringLiteral("next")] = QJsonArray{QStringLiteral("B")}; },
                 [](QJsonObject &j) {
                     QJsonArray next = j[QStringLiteral("next")].toArray();
                     next[0] = QStringLiteral("martian");
                     j[QStringLiteral("next")] = next;
                 },
                 [](QJsonObject &j) {
                     QJsonArray length = j[QStringLiteral("length")].toArray();
                     length[3] = 0;
                     j[QStringLiteral("length")] = length;
                 }}) {
            QJsonObject damaged = tree.toJson();
            edit(damaged);
            const std::string e = errorOf([&] { ContextTree::fromJson(damaged, "m.json"); });
            QVERIFY2(e.find("context.next/length") != std::string::npos && e.find("m.json") != std::string::npos,
                     e.c_str());
        }
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
