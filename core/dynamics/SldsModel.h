#pragma once
// SLDS with known labels and B = I (docs/models.md §3): a time-varying linear-Gaussian state space
//   x_1 ~ N(mu_{pi_1}, Sigma_{pi_1}),  x_t = A_{pi_t} x_{t-1} + nu_{pi_t} + w_t, w_t ~ N(0, Q_{pi_t}),
//   y_t = x_t + v_t, v_t ~ N(0, R_{pi_t}),
// trained by EM: Kalman filter (prediction-error log-likelihood, §3.2), RTS smoother with the
// lag-one cross-covariance (§3.3), closed-form M-step (§3.4), initialised from the DPDS.
// Default: everything diagonal, so the d dimensions decouple into scalar filters, and the M-step is
// the paper's plain maximum likelihood. Options: full A (and/or full Q, R, Sigma), a shared R, a
// bound on A for stable generation. Unseen phones keep their DPDS initialisation.
#include "dynamics/DpdsModel.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/LinearRecursion.h"

namespace lipsync {

struct SldsOptions
{
    bool fullA = false;
    bool fullNoise = false; // full Q, R and Sigma
    bool sharedR = false;
    double kappa = 2.0;       // MAP prior on Sigma_n as §4.5 (0: pure ML)
    int maxIterations = 200;  // §3.4 stopping
    double tolerance = 1e-7;
    // Off: A is the unconstrained ML of §3.4, as in the paper. On: every M-step keeps |a|
    // (diagonal A) or ||A||_2 (full A) <= aMax, so generation stays bounded over long dwell times
    // (the §4.9 stability argument); the constrained step is kept only where it does not lower
    // the expected complete-data log-likelihood, so EM stays monotone.
    bool boundA = false;
    double aMax = 0.999;
    int initIterations = 30;  // DPDS iterations of the initialisation
    int threads = 0;          // 0: all cores (QtConcurrent over dimensions), 1: serial
};

namespace slds {

// Per phone n: A_n, Q_n, R_n, Sigma_n (d x d; diagonal ones stored as diagonal matrices) and
// nu_n, mu_n (rows of P x d matrices).
struct Parameters
{
    std::vector<Eigen::MatrixXd> A, Q, R, Sigma;
    Eigen::MatrixXd nu, mu;
    int dimension() const { return int(mu.cols()); }
};

// Kalman filter + RTS smoother of one sequence (§3.2-3.3), matrix form.
struct Smoothed
{
    double logLikelihood = 0.0;
    std::vector<Eigen::VectorXd> mean;       // m_{t|T}
    std::vector<Eigen::MatrixXd> covariance; // P_{t|T}
    std::vector<Eigen::MatrixXd> cross;      // P_{t,t-1|T} for t >= 1 (index t), [0] unused
};
Smoothed smooth(const Parameters &p, const std::vector<int> &labels, const Eigen::MatrixXd &Y);
double kalmanLogLikelihood(const Parameters &p, const std::vector<int> &labels,
                           const Eigen::MatrixXd &Y);

} // namespace slds

class SldsModel : public DynamicModel
{
public:
    explicit SldsModel(SldsOptions options = {}) : m_options(options) {}
    std::string kind() const override { return modelKindId(ModelKind::Slds); }
    SldsOptions &options() { return m_options; }
    const SldsOptions &options() const { return m_options; }

    Eigen::MatrixXd generateMostLikely(const std::vector<int> &labels) const override;
    std::unique_ptr<StreamingGenerator> makeStreamer() const override;
    double logLikelihood(const std::vector<int> &labels,
                         const Eigen::MatrixXd &features) const override;
    QJsonObject parametersToJson() const override;
    void parametersFromJson(const QJsonObject &json, const std::string &file) override;

    const slds::Parameters &parameters() const { return m_params; }
    // Sets parameters directly (tests, sampling); marks the model trained.
    void setParameters(const slds::Parameters &parameters);
    // Log-likelihood (+ log prior of Sigma when kappa > 0) after each E-step; non-decreasing.
    const std::vector<double> &objectiveHistory() const { return m_history; }
    bool isDiagonal() const { return !m_options.fullA && !m_options.fullNoise; }
    // Use this DPDS (trained on the same sequences) as the initialisation of the next train()
    // instead of training one (§3.4 initialisation); the evaluation shares its fold's DPDS.
    void setInitialisation(std::shared_ptr<const DpdsModel> dpds) { m_initialisation = std::move(dpds); }
    LinearRecursion recursion() const;

protected:
    void fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback) override;

private:
    // One EM iteration; returns the E-step objective (before the M-step).
    double emDiagonal(const std::vector<LabelledSequence> &sequences, const FrameStatistics &st,
                      const Eigen::VectorXd &s0);
    double emMatrix(const std::vector<LabelledSequence> &sequences, const FrameStatistics &st,
                    const Eigen::VectorXd &s0);

    SldsOptions m_options;
    slds::Parameters m_params;
    std::vector<double> m_history;
    std::shared_ptr<const DpdsModel> m_initialisation;
};

} // namespace lipsync
