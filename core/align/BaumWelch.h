#pragma once
// Embedded Baum-Welch re-estimation (HTK's HERest): the forward-backward pass over one whole
// utterance's unrolled HMM (UtteranceGraph) accumulates, for every model state, the expected
// frame counts, self-transition counts and per-mixture-component zeroth, first and second
// moments of the features. Forward probabilities are beam-pruned in the log domain.
#include "align/AcousticModel.h"
#include "align/UtteranceGraph.h"

#include <Eigen/Core>

#include <vector>

namespace lipsync {

struct StateAccumulator
{
    double occupancy = 0;  // sum_t gamma_t(j)
    double selfCount = 0;  // sum_t xi_t(j, j)
    Eigen::VectorXd componentOccupancy; // M
    RowMatrixXd sum;                    // M x D
    RowMatrixXd sumSquares;             // M x D
};

struct Accumulators
{
    std::vector<StateAccumulator> states;
    double logLikelihood = 0;
    long long frames = 0;
    int utterances = 0;

    explicit Accumulators(const AcousticModel &model);
    void add(const Accumulators &other);
};

// Forward probabilities take T x S doubles: utterances with more frames x graph states are not used.
constexpr double kMaxForwardCells = 1.5e8;

// Adds the expected statistics of one utterance. Returns its log-likelihood log p(O | graph),
// or -inf (nothing added) if no path fits (fewer frames than phones, or everything pruned).
double accumulateUtterance(const AcousticModel &model, const UtteranceGraph &graph,
                           const Eigen::MatrixXf &features, double beam, Accumulators &out);

} // namespace lipsync
