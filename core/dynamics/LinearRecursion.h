#pragma once
// The generator shared by HMM-mean, SLDS and DPDS (docs/models.md §3.5, §4.12, §5):
//   y_1 = mu_{pi_1},  y_t = A_{pi_t} y_{t-1} + nu_{pi_t},
// with A_n diagonal (a P x d matrix of coefficients) or full (P matrices d x d). HMM-mean is the
// case a = 0, nu = mu = m. The batch generator and the streamer run the same step function, so
// streaming is bit-identical to batch generation.
#include "dynamics/StreamingGenerator.h"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace lipsync {

struct LinearRecursion
{
    Eigen::MatrixXd mu;  // P x d
    Eigen::MatrixXd nu;  // P x d
    Eigen::MatrixXd a;   // P x d (diagonal A_n), used when full is empty
    std::vector<Eigen::MatrixXd> full; // P matrices d x d, or empty

    int dimension() const { return int(mu.cols()); }
    void first(int label, Eigen::Ref<Eigen::VectorXd> y) const { y = mu.row(label).transpose(); }
    void step(int label, const Eigen::VectorXd &previous, Eigen::Ref<Eigen::VectorXd> y) const;

    // Labels are assumed valid (0..P-1, non-empty).
    Eigen::MatrixXd generate(const std::vector<int> &labels) const;
    std::unique_ptr<StreamingGenerator> streamer() const;
};

} // namespace lipsync
