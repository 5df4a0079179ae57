#pragma once
// The background's own posture under generated speech: what of a face's shape the phones do not
// decide — head pose left in the shape after the similarity, the set of the jaw, an expression,
// the day's lighting in the texture — is taken from the frame drawn into, not from the model.
//
// A dynamic model trained on many clips generates, along those directions, the mean of all of
// them; the recording drawn into has its own value. Drawn as generated, every frame's lower face is
// warped from its own posture to the average one as well as to the generated mouth: a stretch
// of the recording's skin that says nothing about speech (on GRID s1 the first and third combined
// modes, 92 % of whose variance in silence lies between clips and under 7 % with the phone, move
// the mouth by about a pixel each). Synthesizing Obama (Suwajanakorn et al. 2017) likewise keeps
// the target video's pose and synthesises only the mouth.
//
// In whitened combined parameters w = Λ^{-1/2} c (Λ the combined PCA's variances) the speech
// subspace S is spanned by the model's phone targets (each phone's trajectory held alone; the
// leading directions of their spread, kSpeechShare of it) and by the inner lips' opening (the
// direction BilabialClosure closes along, so that no posture ever opens or closes the lips).
// With Q the projection onto its orthogonal complement and c̄ the mean phone target:
//   c' = c + Λ^{1/2} Q Λ^{-1/2} (p_t - c̄),
// p_t the background frame's slow posture: its tracked parameters smoothed over time
// (slowPosture), so the background's own articulation does not come through. The generated
// trajectory is kept whole; only its level outside S moves to the background's.
#include "aam/AamModel.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace lipsync {

class DynamicModel;

class PostureTransfer
{
public:
    // Share of the phone targets' spread (whitened) the speech subspace keeps [choice].
    static constexpr double kSpeechShare = 0.95;
    // Standard deviation in seconds of the Gaussian the background's posture is smoothed with
    // [choice: articulation runs at 3-10 Hz, a posture changes over seconds].
    static constexpr double kPostureSeconds = 0.5;

    // From phone targets (rows: one combined-parameter vector per phone) and the AAM's combined
    // variances; `opening` the inner-lip opening's gradient in c (BilabialClosure), or empty.
    // Throws lipsync::Error for sizes that do not agree or fewer than two targets.
    PostureTransfer(const Eigen::MatrixXd &phoneTargets, const Eigen::VectorXd &variances,
                    const Eigen::VectorXd &opening);
    // The phone targets of `model` (each of the 41 phones held alone for a third of a second),
    // with the AAM's variances and inner-lip opening. None when the model's dimension is not the
    // AAM's combined model's, or it cannot generate them (null). Shared: every frame drawn with
    // the model reads it.
    static std::shared_ptr<const PostureTransfer> forModel(const DynamicModel &model, const AamModel &aam);

    // c' for generated parameters and the background frame's slow posture.
    Eigen::VectorXd apply(const Eigen::VectorXd &generated, const Eigen::VectorXd &posture) const;
    // Directions of the speech subspace (its dimension).
    int speechDimension() const { return m_speechDimension; }

    // Tracked parameters (frames x d, non-finite rows skipped) smoothed with a Gaussian of
    // `seconds` over their timestamps; rows with no finite frame near them are NaN.
    static Eigen::MatrixXd slowPosture(const Eigen::MatrixXd &tracked, const std::vector<double> &times,
                                       double seconds = kPostureSeconds);

private:
    Eigen::MatrixXd m_outside; // Λ^{1/2} Q Λ^{-1/2}
    Eigen::VectorXd m_level;   // c̄
    int m_speechDimension = 0;
};

} // namespace lipsync
