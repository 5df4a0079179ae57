#pragma once
// DPDS, the paper's model (docs/models.md §4): a deterministic switched linear recursion
//   x_1 = mu_{pi_1},  x_t = a_{pi_t} o x_{t-1} + nu_{pi_t},
// observed with noise Sigma_{pi_1} at t = 1 and R (shared, diagonal) at t >= 2 (eq. 1).
// Each dimension is fitted independently (§4.2): exact weighted ML of mu, nu given a (§4.4),
// closed-form variances with the MAP prior on sigma^2 (§4.5), and a by variable projection +
// Levenberg-Marquardt (§4.8) or the paper's gradient ascent, |a| <= a_max (§4.9), in the joint
// iteration of §4.10. Unseen phones keep a = 0.5 and the ridge-prior mu = m, nu = (1 - a) m.
#include "dynamics/DynamicModel.h"
#include "dynamics/LinearRecursion.h"

namespace lipsync {

struct DpdsOptions
{
    enum class Optimizer { LevenbergMarquardt, GradientAscent };
    Optimizer optimizer = Optimizer::LevenbergMarquardt;
    // Paper mode (§4.4, §4.10): unit weights in the mu/nu solve, only r re-estimated in the loop,
    // sigma^2 computed once at the end.
    bool paperMode = false;
    double aMax = 0.999;             // §4.9 [choice]
    bool nonNegativeA = false;       // optional a in [0, a_max] (forbids oscillation)
    bool autoregressiveInit = true;  // §4.9 AR(1) initialisation; false: a = initialA everywhere
    double initialA = 0.5;
    double kappa = 2.0;              // §4.5 prior strength
    bool prior = true;               // §4.5 [choice]; false: the paper's plain ML variances
    int maxIterations = 100;         // outer iterations of §4.10
    double tolerance = 1e-9;         // relative objective increase that stops the loop
    int threads = 0;                 // 0: all cores (QtConcurrent), 1: serial
};

class DpdsModel : public DynamicModel
{
public:
    explicit DpdsModel(DpdsOptions options = {}) : m_options(options) {}
    std::string kind() const override { return modelKindId(ModelKind::Dpds); }
    DpdsOptions &options() { return m_options; }
    const DpdsOptions &options() const { return m_options; }

    Eigen::MatrixXd generateMostLikely(const std::vector<int> &labels) const override;
    std::unique_ptr<StreamingGenerator> makeStreamer() const override;
    double logLikelihood(const std::vector<int> &labels,
                         const Eigen::MatrixXd &features) const override;
    QJsonObject parametersToJson() const override;
    void parametersFromJson(const QJsonObject &json, const std::string &file) override;

    LinearRecursion recursion() const;

    // Parameters (P x d, except r: d).
    Eigen::MatrixXd a, mu, nu, sigma2;
    Eigen::VectorXd r;

    // Training record: outer iterations run (max over dimensions), the objective
    // sum_k (L_k + log p(sigma^2_k) - ridge) after each, and whether every step kept it
    // non-decreasing (exact mode, relative tolerance 1e-12).
    int iterations() const { return m_iterations; }
    const std::vector<double> &objectiveHistory() const { return m_history; }
    bool monotone() const { return m_monotone; }

protected:
    void fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback) override;

private:
    DpdsOptions m_options;
    int m_iterations = 0;
    std::vector<double> m_history;
    bool m_monotone = true;
};

} // namespace lipsync
