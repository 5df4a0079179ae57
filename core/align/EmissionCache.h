#pragma once
// Log emission densities log b_j(o_t) of one utterance, computed on first use: passes over the
// unrolled graph visit the same (frame, model state) many times through different phone
// instances and pruning leaves most pairs unvisited.
#include "align/AcousticModel.h"

#include <cmath>
#include <vector>

namespace lipsync {

class EmissionCache
{
public:
    EmissionCache(const AcousticModel &model, const Eigen::MatrixXf &features)
        : m_model(model), m_features(features), m_states(model.stateCount()),
          m_values(size_t(features.rows()) * size_t(m_states), NAN)
    {
        // Row-major copy so that a frame is contiguous for the Gaussian loops.
        m_rows = features;
    }

    float operator()(int t, int modelState)
    {
        float &v = m_values[size_t(t) * size_t(m_states) + size_t(modelState)];
        if (std::isnan(v))
            v = m_model.state(modelState).logLikelihood(frame(t));
        return v;
    }
    const float *frame(int t) const { return m_rows.data() + size_t(t) * size_t(m_rows.cols()); }
    int frames() const { return int(m_features.rows()); }

private:
    const AcousticModel &m_model;
    const Eigen::MatrixXf &m_features;
    int m_states;
    std::vector<float> m_values;
    Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m_rows;
};

inline double logAdd(double a, double b)
{
    if (a < b)
        std::swap(a, b);
    if (b == -INFINITY)
        return a;
    const double d = b - a;
    return d < -36.0 ? a : a + std::log1p(std::exp(d));
}

} // namespace lipsync
