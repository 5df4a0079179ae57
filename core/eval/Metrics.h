#pragma once
// Per-sequence error metrics of docs/models.md §6.2 (AAM-parameter units, per-frame vector norms
// averaged over frames): L1 = mean_t sum_k |E|, RMS = sqrt(mean_t sum_k E^2),
// Linf = mean_t max_k |E|, with E = generated - real.
#include <Eigen/Core>

namespace lipsync {

struct SequenceErrors
{
    double l1 = 0.0;
    double rms = 0.0;
    double linf = 0.0;
};

// Throws lipsync::Error if the shapes differ or are empty.
SequenceErrors sequenceErrors(const Eigen::MatrixXd &generated, const Eigen::MatrixXd &real);

} // namespace lipsync
