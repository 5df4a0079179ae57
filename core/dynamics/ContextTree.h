#pragma once
// Context-dependent states tied by decision trees (docs/models.md §5.2), as HMM speech synthesis
// ties triphone states: a frame's context is its phone, the phones of the segments before and
// after it, and which third of its segment it lies in. One binary tree per phone splits that
// phone's frames by questions about the context (is the left phone bilabial? is this the last
// third?), greedily by the gain in diagonal-Gaussian log-likelihood of the face features, and
// stops by the minimum-description-length criterion: a split must gain more than
// d log N nats (the cost of the 2d parameters of one more Gaussian over N training frames) and
// leave both halves at least minOccupancy frames. The leaves are the states the dynamic models are
// trained on; a tree answers for every context, so contexts never seen in training still map to
// a state, and a phone never seen keeps a single state (the models' back-off).
#include "dynamics/LabelledSequence.h"

#include <QJsonObject>

#include <algorithm>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;

// A frame's context: phone indices (PhoneSet) of its own, the previous and the next segment
// (silence at either end of the utterance), and its position in its segment (0, 1, 2: thirds).
struct PhoneContext
{
    int phone = 0;
    int left = 0;
    int right = 0;
    int position = 0;
};

// The part of its segment frame i (0-based) of a segment of `length` frames lies in: 0, 1 or 2,
// the thirds.
constexpr int kSegmentPositions = 3;
constexpr int segmentPosition(int i, int length) { return kSegmentPositions * i / length; }

// The contexts of every frame of a label sequence (segments are runs of equal labels).
std::vector<PhoneContext> frameContexts(const std::vector<int> &labels);

struct ContextTreeOptions
{
    // Smallest number of training frames a state may have.
    int minOccupancy = 50;
    // Scale of the MDL threshold d log N (1: the criterion itself).
    double mdlWeight = 1.0;
};

class ContextTree
{
public:
    // One state per phone (no splits): the plain phone models.
    ContextTree();

    // Grows the trees on labelled sequences (phone labels, validated by the caller). Polls cancel.
    static ContextTree grow(const std::vector<LabelledSequence> &sequences,
                            const ContextTreeOptions &options, Feedback &feedback);

    int stateCount() const { return m_stateCount; }
    int state(const PhoneContext &context) const;
    // The state of every frame of a phone label sequence.
    std::vector<int> states(const std::vector<int> &phoneLabels) const;
    // A frame's most likely context while its segment is still running (Live, which cannot wait
    // long for the next phone): frame i of a segment of `phone` after `left`, the right context
    // the phone's most frequent successor in training and the third from its median segment
    // length there (the last third once the segment has run longer). Trees of model files
    // written without it have none (silence next, 1-frame segments).
    bool hasPrediction() const { return !m_next.empty(); }
    PhoneContext predicted(int phone, int left, int i) const;
    int predictedLength(int phone) const { return m_length.empty() ? 1 : std::max(1, m_length[size_t(phone)]); }

    // The phone whose tree holds `state` (each phone's states are its own tree's leaves).
    int phoneOf(int state) const;

    // "AA: L-bilabial, not pos-last" — the questions answered on the way to a state.
    std::string describe(int state) const;

    // {"states": K, "trees": [{"phone": "AA", "nodes": [{"ask": "L-bilabial", "yes": 1, "no": 2},
    //  {"state": 0}, ...]}, ...], "next": ["B", ...], "length": [7, ...]}, one tree, successor and
    //  median length per phone in PhoneSet order.
    QJsonObject toJson() const;
    // Throws lipsync::Error naming `file` for unknown questions, broken node links or states.
    static ContextTree fromJson(const QJsonObject &json, const std::string &file);

    // The question names a tree may ask, in a fixed order.
    static const std::vector<std::string> &questionNames();

private:
    struct Node
    {
        int question = -1; // -1: a leaf
        int yes = -1, no = -1;
        int state = -1;
    };
    std::vector<std::vector<Node>> m_trees; // per phone; node 0 is the root
    int m_stateCount = 0;
    std::vector<int> m_next, m_length;      // per phone (predicted()); empty: no prediction
};

} // namespace lipsync
