#include "dynamics/ContextTree.h"

#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonArray>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <string_view>

namespace lipsync {

namespace {

constexpr int kPhones = PhoneSet::kCount;
constexpr int kPositions = kSegmentPositions;

// Phone classes by what the lips, jaw and tongue do (the left and right questions ask each of
// them, and each single phone).
struct PhoneClass
{
    const char *name;
    std::vector<std::string_view> phones;
};

const std::vector<PhoneClass> &phoneClasses()
{
    static const std::vector<PhoneClass> classes = {
        {"silence", {"sil", "br"}},
        {"vowel", {"AA", "AE", "AH", "AO", "AW", "AY", "EH", "ER", "EY", "IH", "IY", "OW", "OY", "UH", "UW"}},
        {"consonant", {"B", "CH", "D", "DH", "F", "G", "HH", "JH", "K", "L", "M", "N", "NG", "P", "R", "S",
                       "SH", "T", "TH", "V", "W", "Y", "Z", "ZH"}},
        {"bilabial", {"P", "B", "M"}},
        {"labiodental", {"F", "V"}},
        {"labial", {"P", "B", "M", "F", "V", "W"}},
        {"dental", {"TH", "DH"}},
        {"alveolar", {"T", "D", "N", "S", "Z", "L"}},
        {"postalveolar", {"SH", "ZH", "CH", "JH"}},
        {"velar", {"K", "G", "NG"}},
        {"stop", {"P", "B", "T", "D", "K", "G"}},
        {"nasal", {"M", "N", "NG"}},
        {"fricative", {"F", "V", "TH", "DH", "S", "Z", "SH", "ZH", "HH"}},
        {"approximant", {"L", "R", "W", "Y", "ER"}},
        {"rounded", {"UW", "UH", "OW", "AO", "OY", "W", "ER"}},
        {"open", {"AA", "AE", "AH", "AO", "AW", "AY"}},
        {"front", {"IY", "IH", "EH", "EY", "AE", "Y"}},
        {"spread", {"IY", "IH", "EY", "Y"}},
        {"diphthong", {"AW", "AY", "EY", "OW", "OY"}},
    };
    return classes;
}

enum class Side { Left, Right, Position };

struct Question
{
    std::string name;
    Side side;
    std::array<bool, kPhones> members{}; // Left/Right: phones; Position: the first kPositions entries
    bool asks(const PhoneContext &c) const
    {
        switch (side) {
        case Side::Left:
            return members[size_t(c.left)];
        case Side::Right:
            return members[size_t(c.right)];
        case Side::Position:
            return members[size_t(c.position)];
        }
        return false;
    }
};

const std::vector<Question> &questions()
{
    static const std::vector<Question> all = [] {
        std::vector<Question> q;
        const char *positions[kPositions] = {"pos-first", "pos-middle", "pos-last"};
        for (int i = 0; i < kPositions; ++i) {
            Question position{positions[i], Side::Position, {}};
            position.members[size_t(i)] = true;
            q.push_back(position);
        }
        for (Side side : {Side::Left, Side::Right}) {
            const std::string prefix = side == Side::Left ? "L-" : "R-";
            for (const PhoneClass &c : phoneClasses()) {
                Question question{prefix + c.name, side, {}};
                for (std::string_view phone : c.phones)
                    question.members[size_t(PhoneSet::index(phone))] = true;
                q.push_back(question);
            }
            for (int phone = 0; phone < kPhones; ++phone) {
                Question question{prefix + PhoneSet::label(phone), side, {}};
                question.members[size_t(phone)] = true;
                q.push_back(question);
            }
        }
        return q;
    }();
    return all;
}

// Sufficient statistics of a set of frames under one diagonal Gaussian.
struct Moments
{
    double n = 0.0;
    Eigen::VectorXd sum, squares;
    explicit Moments(Eigen::Index d = 0) : sum(Eigen::VectorXd::Zero(d)), squares(Eigen::VectorXd::Zero(d)) {}
    void add(const Moments &o)
    {
        n += o.n;
        sum += o.sum;
        squares += o.squares;
    }
    // max_theta log p(frames | theta) up to the -n d (log 2 pi + 1) / 2 every split conserves.
    double logLikelihood(const Eigen::VectorXd &floor) const
    {
        if (n <= 0.0)
            return 0.0;
        const Eigen::ArrayXd mean = sum.array() / n;
        const Eigen::ArrayXd variance = (squares.array() / n - mean.square()).max(floor.array());
        return -0.5 * n * variance.log().sum();
    }
};

// The distinct (left, right, position) contexts of one phone's frames with their moments.
struct ContextMoments
{
    PhoneContext context;
    Moments moments;
};

class Grower
{
public:
    Grower(const std::vector<ContextMoments> &contexts, const Eigen::VectorXd &floor, double threshold,
           int minOccupancy)
        : m_contexts(contexts), m_floor(floor), m_threshold(threshold), m_minOccupancy(minOccupancy)
    {
    }

    // Appends the subtree of `members` (indices into the contexts) to `nodes`; returns its index.
    int grow(const std::vector<int> &members, std::vector<std::pair<int, int>> &nodes, std::vector<int> &questionOf)
    {
        const Eigen::Index d = m_floor.size();
        Moments all(d);
        for (int i : members)
            all.add(m_contexts[size_t(i)].moments);
        const double parent = all.logLikelihood(m_floor);
        int best = -1;
        double bestGain = m_threshold;
        const std::vector<Question> &qs = questions();
        for (size_t q = 0; q < qs.size(); ++q) {
            Moments yes(d);
            for (int i : members)
                if (qs[q].asks(m_contexts[size_t(i)].context))
                    yes.add(m_contexts[size_t(i)].moments);
            if (yes.n < m_minOccupancy || all.n - yes.n < m_minOccupancy)
                continue;
            Moments no(d);
            no.n = all.n - yes.n;
            no.sum = all.sum - yes.sum;
            no.squares = all.squares - yes.squares;
            const double gain = yes.logLikelihood(m_floor) + no.logLikelihood(m_floor) - parent;
            if (gain > bestGain) {
                bestGain = gain;
                best = int(q);
            }
        }
        const int index = int(nodes.size());
        nodes.push_back({-1, -1});
        questionOf.push_back(best);
        if (best < 0)
            return index;
        std::vector<int> yesMembers, noMembers;
        for (int i : members)
            (qs[size_t(best)].asks(m_contexts[size_t(i)].context) ? yesMembers : noMembers).push_back(i);
        const int yesNode = grow(yesMembers, nodes, questionOf);
        const int noNode = grow(noMembers, nodes, questionOf);
        nodes[size_t(index)] = {yesNode, noNode};
        return index;
    }

private:
    const std::vector<ContextMoments> &m_contexts;
    const Eigen::VectorXd &m_floor;
    double m_threshold;
    int m_minOccupancy;
};

int questionIndex(const std::string &name)
{
    const std::vector<Question> &qs = questions();
    for (size_t q = 0; q < qs.size(); ++q)
        if (qs[q].name == name)
            return int(q);
    return -1;
}

} // namespace

std::vector<PhoneContext> frameContexts(const std::vector<int> &labels)
{
    std::vector<PhoneContext> contexts(labels.size());
    int previous = PhoneSet::kSilence;
    for (size_t start = 0; start < labels.size();) {
        size_t end = start;
        while (end < labels.size() && labels[end] == labels[start])
            ++end;
        const int next = end < labels.size() ? labels[end] : PhoneSet::kSilence;
        const size_t length = end - start;
        for (size_t t = start; t < end; ++t)
            contexts[t] = {labels[start], previous, next, segmentPosition(int(t - start), int(length))};
        previous = labels[start];
        start = end;
    }
    return contexts;
}

ContextTree::ContextTree()
    : m_trees(size_t(kPhones), std::vector<Node>(1))
{
    for (int p = 0; p < kPhones; ++p)
        m_trees[size_t(p)][0].state = p;
    m_stateCount = kPhones;
}

ContextTree ContextTree::grow(const std::vector<LabelledSequence> &sequences,
                              const ContextTreeOptions &options, Feedback &feedback)
{
    const Eigen::Index d = sequences.front().features.cols();
    // Moments per phone and distinct context; the global variance for the floor (§0: 1e-6 Var).
    std::vector<std::vector<ContextMoments>> perPhone(static_cast<size_t>(kPhones));
    std::vector<std::map<int, size_t>> index(static_cast<size_t>(kPhones));
    Moments global(d);
    for (const LabelledSequence &s : sequences) {
        const std::vector<PhoneContext> contexts = frameContexts(s.labels);
        for (size_t t = 0; t < contexts.size(); ++t) {
            const PhoneContext &c = contexts[t];
            const int key = (c.left * kPhones + c.right) * kPositions + c.position;
            auto [it, added] = index[size_t(c.phone)].try_emplace(key, perPhone[size_t(c.phone)].size());
            if (added)
                perPhone[size_t(c.phone)].push_back({c, Moments(d)});
            Moments &m = perPhone[size_t(c.phone)][it->second].moments;
            const Eigen::VectorXd y = s.features.row(Eigen::Index(t)).transpose();
            m.n += 1.0;
            m.sum += y;
            m.squares += y.cwiseAbs2();
            global.n += 1.0;
            global.sum += y;
            global.squares += y.cwiseAbs2();
        }
    }
    const Eigen::VectorXd globalVariance = (global.squares / global.n - (global.sum / global.n).cwiseAbs2()).cwiseMax(0.0);
    const Eigen::VectorXd floor = (1e-6 * globalVariance).cwiseMax(1e-12);
    const double threshold = options.mdlWeight * double(d) * std::log(std::max(global.n, 2.0));

    ContextTree tree;
    tree.m_stateCount = 0;
    for (int p = 0; p < kPhones; ++p) {
        feedback.throwIfCanceled();
        std::vector<int> members(perPhone[size_t(p)].size());
        for (size_t i = 0; i < members.size(); ++i)
            members[i] = int(i);
        std::vector<std::pair<int, int>> links;
        std::vector<int> questionOf;
        Grower(perPhone[size_t(p)], floor, threshold, std::max(1, options.minOccupancy)).grow(members, links, questionOf);
        std::vector<Node> &nodes = tree.m_trees[size_t(p)];
        nodes.assign(links.size(), Node{});
        for (size_t i = 0; i < links.size(); ++i) {
            nodes[i].question = questionOf[i];
            nodes[i].yes = links[i].first;
            nodes[i].no = links[i].second;
            if (questionOf[i] < 0)
                nodes[i].state = tree.m_stateCount++;
        }
        feedback.setProgress(double(p + 1) / kPhones);
    }
    // The prediction: successors counted and segment lengths gathered per phone; a phone never
    // seen is followed by silence and lasts the median segment.
    std::vector<std::vector<int>> successors(size_t(kPhones), std::vector<int>(size_t(kPhones), 0));
    std::vector<std::vector<int>> lengths(static_cast<size_t>(kPhones));
    std::vector<int> all;
    for (const LabelledSequence &s : sequences)
        for (size_t start = 0; start < s.labels.size();) {
            size_t end = start;
            while (end < s.labels.size() && s.labels[end] == s.labels[start])
                ++end;
            const int phone = s.labels[start];
            ++successors[size_t(phone)][size_t(end < s.labels.size() ? s.labels[end] : PhoneSet::kSilence)];
            lengths[size_t(phone)].push_back(int(end - start));
            all.push_back(int(end - start));
            start = end;
        }
    auto median = [](std::vector<int> v) {
        std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
        return v[v.size() / 2];
    };
    const int typical = all.empty() ? 1 : median(all);
    tree.m_next.assign(size_t(kPhones), PhoneSet::kSilence);
    tree.m_length.assign(size_t(kPhones), typical);
    for (int p = 0; p < kPhones; ++p) {
        const std::vector<int> &counts = successors[size_t(p)];
        if (lengths[size_t(p)].empty())
            continue;
        tree.m_next[size_t(p)] = int(std::max_element(counts.begin(), counts.end()) - counts.begin());
        tree.m_length[size_t(p)] = median(lengths[size_t(p)]);
    }
    return tree;
}

PhoneContext ContextTree::predicted(int phone, int left, int i) const
{
    const int length = predictedLength(phone);
    const int next = m_next.empty() ? int(PhoneSet::kSilence) : m_next[size_t(phone)];
    return {phone, left, next, segmentPosition(std::min(i, length - 1), length)};
}

int ContextTree::state(const PhoneContext &context) const
{
    const std::vector<Node> &nodes = m_trees[size_t(context.phone)];
    const std::vector<Question> &qs = questions();
    int i = 0;
    while (nodes[size_t(i)].question >= 0)
        i = qs[size_t(nodes[size_t(i)].question)].asks(context) ? nodes[size_t(i)].yes : nodes[size_t(i)].no;
    return nodes[size_t(i)].state;
}

int ContextTree::phoneOf(int state) const
{
    for (size_t p = 0; p < m_trees.size(); ++p)
        for (const Node &node : m_trees[p])
            if (node.question < 0 && node.state == state)
                return int(p);
    throw Error("no context state " + std::to_string(state) + " in the trees");
}

std::vector<int> ContextTree::states(const std::vector<int> &phoneLabels) const
{
    const std::vector<PhoneContext> contexts = frameContexts(phoneLabels);
    std::vector<int> out(contexts.size());
    for (size_t t = 0; t < contexts.size(); ++t)
        out[t] = state(contexts[t]);
    return out;
}

std::string ContextTree::describe(int state) const
{
    const std::vector<Question> &qs = questions();
    for (int p = 0; p < kPhones; ++p) {
        const std::vector<Node> &nodes = m_trees[size_t(p)];
        // Depth-first with the path of answers.
        std::vector<std::pair<int, std::string>> stack{{0, std::string()}};
        while (!stack.empty()) {
            auto [i, path] = stack.back();
            stack.pop_back();
            const Node &n = nodes[size_t(i)];
            if (n.question < 0) {
                if (n.state == state)
                    return PhoneSet::label(p) + (path.empty() ? std::string() : ": " + path);
                continue;
            }
            const std::string sep = path.empty() ? std::string() : ", ";
            stack.push_back({n.yes, path + sep + qs[size_t(n.question)].name});
            stack.push_back({n.no, path + sep + "not " + qs[size_t(n.question)].name});
        }
    }
    throw Error("no context state " + std::to_string(state));
}

const std::vector<std::string> &ContextTree::questionNames()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const Question &q : questions())
            n.push_back(q.name);
        return n;
    }();
    return names;
}

QJsonObject ContextTree::toJson() const
{
    QJsonArray trees;
    const std::vector<Question> &qs = questions();
    for (int p = 0; p < kPhones; ++p) {
        QJsonArray nodes;
        for (const Node &n : m_trees[size_t(p)]) {
            if (n.question < 0)
                nodes.append(QJsonObject{{QStringLiteral("state"), n.state}});
            else
                nodes.append(QJsonObject{{QStringLiteral("ask"), QString::fromStdString(qs[size_t(n.question)].name)},
                                         {QStringLiteral("yes"), n.yes},
                                         {QStringLiteral("no"), n.no}});
        }
        trees.append(QJsonObject{{QStringLiteral("phone"), QString::fromStdString(PhoneSet::label(p))},
                                 {QStringLiteral("nodes"), nodes}});
    }
    QJsonObject o{{QStringLiteral("states"), m_stateCount}, {QStringLiteral("trees"), trees}};
    if (hasPrediction()) {
        QJsonArray next, length;
        for (int p = 0; p < kPhones; ++p) {
            next.append(QString::fromStdString(PhoneSet::label(m_next[size_t(p)])));
            length.append(m_length[size_t(p)]);
        }
        o[QStringLiteral("next")] = next;
        o[QStringLiteral("length")] = length;
    }
    return o;
}

ContextTree ContextTree::fromJson(const QJsonObject &json, const std::string &file)
{
    ContextTree tree;
    const QJsonValue states = json.value(QStringLiteral("states"));
    if (!states.isDouble() || states.toInt() < kPhones)
        throw Error("expected at least " + std::to_string(kPhones) + " states", file, "context.states");
    tree.m_stateCount = states.toInt();
    const QJsonArray trees = json.value(QStringLiteral("trees")).toArray();
    if (trees.size() != kPhones)
        throw Error("expected one tree per phone (" + std::to_string(kPhones) + ")", file, "context.trees");
    std::vector<int> seen(size_t(tree.m_stateCount), 0);
    for (int p = 0; p < kPhones; ++p) {
        const QJsonObject t = trees[p].toObject();
        const std::string where = "context.trees[" + std::to_string(p) + "]";
        if (t.value(QStringLiteral("phone")).toString().toStdString() != PhoneSet::label(p))
            throw Error("expected the tree of " + PhoneSet::label(p), file, where);
        const QJsonArray nodes = t.value(QStringLiteral("nodes")).toArray();
        if (nodes.isEmpty())
            throw Error("no nodes", file, where);
        std::vector<Node> &out = tree.m_trees[size_t(p)];
        out.assign(size_t(nodes.size()), Node{});
        for (qsizetype i = 0; i < nodes.size(); ++i) {
            const QJsonObject n = nodes[i].toObject();
            const std::string at = where + ".nodes[" + std::to_string(i) + "]";
            Node &node = out[size_t(i)];
            if (n.contains(QStringLiteral("state"))) {
                node.state = n.value(QStringLiteral("state")).toInt(-1);
                if (node.state < 0 || node.state >= tree.m_stateCount || seen[size_t(node.state)]++)
                    throw Error("state missing, out of range or used twice", file, at);
                continue;
            }
            const std::string ask = n.value(QStringLiteral("ask")).toString().toStdString();
            node.question = questionIndex(ask);
            if (node.question < 0)
                throw Error("unknown question '" + ask + "'", file, at);
            // Children after their parent: the tree has no cycles and every walk ends in a leaf.
            node.yes = n.value(QStringLiteral("yes")).toInt(-1);
            node.no = n.value(QStringLiteral("no")).toInt(-1);
            if (node.yes <= i || node.no <= i || node.yes >= nodes.size() || node.no >= nodes.size())
                throw Error("child nodes must follow their parent inside the tree", file, at);
        }
    }
    for (size_t s = 0; s < seen.size(); ++s)
        if (!seen[s])
            throw Error("state " + std::to_string(s) + " is no tree's leaf", file, "context.states");
    if (json.contains(QStringLiteral("next")) || json.contains(QStringLiteral("length"))) {
        const QJsonArray next = json.value(QStringLiteral("next")).toArray();
        const QJsonArray length = json.value(QStringLiteral("length")).toArray();
        if (next.size() != kPhones || length.size() != kPhones)
            throw Error("expected a successor and a length per phone (" + std::to_string(kPhones) + " each)", file,
                        "context.next/length");
        for (int p = 0; p < kPhones; ++p) {
            const int phone = PhoneSet::index(next[p].toString().toStdString());
            const int frames = length[p].toInt(0);
            if (phone < 0 || frames < 1)
                throw Error("expected a phone label and a length of 1 frame or more", file,
                            "context.next/length[" + std::to_string(p) + "]");
            tree.m_next.push_back(phone);
            tree.m_length.push_back(frames);
        }
    }
    return tree;
}

} // namespace lipsync
