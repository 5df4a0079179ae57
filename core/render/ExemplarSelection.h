#pragma once
// The person's own recorded frames in place of generated ones: unit selection over frames, as
// Video Rewrite (Bregler, Covell & Slaney 1997) and trainable videorealistic speech (Ezzat,
// Geiger & Poggio 2002) keep to real mouths. A model's most likely trajectory is an average over
// contexts: its single frames are mouths no one made, which a viewer (and the realism report's
// machine observer) tells apart from recorded ones. Here every generated frame y_t is replaced by
// a recorded frame x_k of the training sequences, chosen by dynamic programming (Viterbi) to stay
// near the generated trajectory and to move as it moves:
//   cost = Σ_t |z(y_t) - z(x_{k_t})|²                                 (target)
//        + λ Σ_t |(z(x_{k_t}) - z(x_{k_t-1})) - (z(y_t) - z(y_t-1))|²  (join; 0 between frames
//          that follow each other in a recording, which are taken as they were)
//        + μ · the number of such cuts,
// with z(c) = c / σ the parameters scaled by their spread over the recorded frames. Each frame's
// candidates are its K nearest recorded frames and the successors of the previous frame's
// candidates (so runs of recorded frames can play on), 3K at most: time O(T N d + T K² d),
// memory O(N d + T K) for a trajectory of T frames and N recorded frames.
#include <Eigen/Core>

#include <vector>

namespace lipsync {

class ExemplarSelection
{
public:
    struct Options
    {
        int candidates = 16;     // K nearest recorded frames per generated frame
        double join = 1.0;       // λ
        double cut = 0.5;        // μ, in the same units as the target cost
    };

    // `recordings`: the recorded feature trajectories (frames x d, one per sequence) to choose
    // from. Throws lipsync::Error when they hold no frames or differ in dimension.
    ExemplarSelection(const std::vector<Eigen::MatrixXd> &recordings, const Options &options);

    // The recorded frames chosen for `generated` (T x d), as a T x d trajectory.
    Eigen::MatrixXd select(const Eigen::MatrixXd &generated) const;
    // The chosen frames' indices into the concatenation of the recordings (for tests).
    std::vector<int> choose(const Eigen::MatrixXd &generated) const;

private:
    Options m_options;
    Eigen::MatrixXd m_frames;  // N x d, every recorded frame, scaled
    Eigen::VectorXd m_scale;   // σ per dimension
    Eigen::VectorXd m_norms;   // |z(x_k)|² per frame
    std::vector<int> m_next;   // the frame after k in its recording, -1 at a recording's end
};

} // namespace lipsync
