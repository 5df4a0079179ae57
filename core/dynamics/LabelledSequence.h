#pragma once
// Training and test data of the dynamic models (docs/models.md §0): one utterance = an integer
// label per video frame and the T x d matrix of face features y_t. Labels index the model's P
// states: the 41 phones (PhoneSet), or the tied context states of a ContextTree (§5.2).
#include "util/PhoneSet.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lipsync {

struct LabelledSequence
{
    std::string name;        // used in error messages ("bbaf2n")
    std::vector<int> labels; // one per frame
    Eigen::MatrixXd features; // frames x d
    double frameRate = 0.0;   // frames per second (0: not known)
    int frameCount() const { return int(labels.size()); }
};

// Checks what every model relies on and throws lipsync::Error naming the sequence: at least one
// sequence, the same d > 0 everywhere, as many labels as feature rows, at least one frame, labels
// in 0..P-1, finite features. Sequences of one frame are valid (they only inform the t = 1 terms).
void validateSequences(const std::vector<LabelledSequence> &sequences, int states = PhoneSet::kCount);
// Label checks for generation: non-empty, every label in 0..P-1.
void validateLabels(const std::vector<int> &labels, const std::string &what = "labels",
                    int states = PhoneSet::kCount);
// One label of a streamer: throws lipsync::Error unless it is in 0..states-1.
void checkStateLabel(int label, int states);

// Fewest frames a state's variance is estimated from (docs/models.md §0, "Rare phones"): from
// fewer, the estimate can sit near the floor by chance and make every later frame of that phone
// improbable beyond measure, so the global variance stands in, as for an unseen phone. With 10
// frames an estimate under 1 % of the true variance has odds of about 3e-8 per dimension.
constexpr int kMinimumVarianceFrames = 10;

// Per-state frame statistics shared by the models' closed-form estimates and back-offs.
struct FrameStatistics
{
    Eigen::MatrixXd mean;       // P x d: m_n (§1), the global mean for unseen states
    Eigen::MatrixXd variance;   // P x d: c_n (§1) floored; the global variance for states with fewer
                                // than kMinimumVarianceFrames frames (unseen ones included)
    Eigen::VectorXi count;      // N_n
    Eigen::VectorXi startCount; // N^(1)_n
    Eigen::VectorXi transitionCount; // N^{>=2}_n
    Eigen::VectorXd globalMean;     // d
    Eigen::VectorXd globalVariance; // d
    Eigen::VectorXd floor;          // eps_k = 1e-6 Var(y_k) (docs/models.md §0), at least 1e-12
    long long frames = 0;
};
FrameStatistics computeFrameStatistics(const std::vector<LabelledSequence> &sequences,
                                       int states = PhoneSet::kCount);

} // namespace lipsync
