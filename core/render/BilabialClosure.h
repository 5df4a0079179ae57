#pragma once
// Lip closure on /p b m/: the articulatory constraint of procedural lip-sync (Edwards, Landreth,
// Fiume & Singh, "JALI", SIGGRAPH 2016: bilabials always close the lips), applied to a generated
// trajectory of AAM combined parameters c (docs/models.md §5.3).
//
// Every model's most likely trajectory is a smoothed average over contexts, so on a bilabial the
// lips come close together without meeting — the render then shows a slit where the recording
// shows closed lips. The inner-lip opening of the AAM's shape is linear in c,
//   o(c) = a^T c + o_0   (inner_lip_bottom - inner_lip_top along the mean face's vertical, in
//                         eye-corner distances of the mean shape),
// so the frame is moved to the most probable c with o(c) = 0 under the AAM's own prior
// c ~ N(c_t, diag(λ)) — the smallest change in Mahalanobis distance that closes the lips, which
// also moves the jaw, cheeks and the lip texture the way closing lips move them in the training
// images:
//   c_t' = c_t - w_t max(0, o(c_t)) Λa / (a^T Λ a).
// w_t is the share of frame t inside a bilabial phone (1 for the frame most inside it), so the
// lips close and release within the phone's own frames. Frames already closed are unchanged.
#include "aam/AamModel.h"
#include "annotation/FrameClock.h"
#include "annotation/Tier.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace lipsync {

class BilabialClosure
{
public:
    // Throws lipsync::Error for an AAM without what closing needs: the 23-point scheme's
    // inner-lip points, a combined model, and modes that move the inner lips.
    explicit BilabialClosure(const AamModel &aam);
    // The closure for `aam`, or none for an AAM the constructor refuses: renders with such AAMs
    // are drawn as generated.
    static std::optional<BilabialClosure> forAam(const AamModel &aam);

    // o(c): the inner-lip opening of the shape of combined parameters c.
    double opening(const Eigen::VectorXd &c) const;
    // a: the opening's gradient in c.
    const Eigen::VectorXd &gradient() const { return m_gradient; }

    // w_t for the frames of `frames` from a phone tier (frame t shows [time(t), endTime(t))).
    static std::vector<double> weights(const Tier &phones, const FrameClock &frames);
    // w_t from per-frame phone labels (PhoneSet indices): 1 on bilabial frames.
    static std::vector<double> weights(const std::vector<int> &labels);

    // The trajectory (T x nc) with the bilabial frames closed; rows beyond weights.size() and
    // non-finite rows are unchanged.
    Eigen::MatrixXd apply(const Eigen::MatrixXd &trajectory, const std::vector<double> &weights) const;

    // What a renderer draws for a generated trajectory shown at `frames`: closed on the /p b m/
    // of `phones` when forAam() has a closure for the AAM, else unchanged.
    static Eigen::MatrixXd closeOnPhones(const AamModel &aam, const Eigen::MatrixXd &trajectory, const Tier &phones,
                                         const FrameClock &frames);

private:
    Eigen::VectorXd m_gradient; // a
    double m_offset = 0.0;      // o_0
    Eigen::VectorXd m_step;     // Λa / (a^T Λ a): the change of c per unit of opening
};

} // namespace lipsync
