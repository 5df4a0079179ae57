#include "dynamics/DynamicModel.h"

#include "tasks/Feedback.h"
#include "util/Error.h"

#include <cmath>

namespace lipsync {

namespace {

// The compensation y' = m + g (y - m) applied to each frame another streamer emits.
class CompensatedStreamer : public StreamingGenerator
{
public:
    CompensatedStreamer(std::unique_ptr<StreamingGenerator> inner, Eigen::VectorXd mean, Eigen::VectorXd gain)
        : m_inner(std::move(inner)), m_mean(std::move(mean)), m_gain(std::move(gain))
    {
    }
    int latency() const override { return m_inner->latency(); }
    void push(int label) override { m_inner->push(label); }
    void finish() override { m_inner->finish(); }
    bool pop(Eigen::Ref<Eigen::VectorXd> frame) override
    {
        if (!m_inner->pop(frame))
            return false;
        frame = m_mean + m_gain.cwiseProduct(frame - m_mean);
        return true;
    }

private:
    std::unique_ptr<StreamingGenerator> m_inner;
    Eigen::VectorXd m_mean, m_gain;
};

} // namespace

void DynamicModel::train(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    validateSequences(sequences, m_stateCount);
    fit(sequences, feedback);
    m_mean.resize(0);
    m_gain.resize(0);
    if (!m_compensate)
        return;
    // Both spreads about the training mean, pooled over every training frame (§5.1).
    const Eigen::Index d = m_dimension;
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
    double frames = 0.0;
    for (const LabelledSequence &s : sequences) {
        mean += s.features.colwise().sum().transpose();
        frames += double(s.features.rows());
    }
    mean /= frames;
    Eigen::VectorXd real = Eigen::VectorXd::Zero(d), generated = Eigen::VectorXd::Zero(d);
    for (const LabelledSequence &s : sequences) {
        feedback.throwIfCanceled();
        real += (s.features.rowwise() - mean.transpose()).colwise().squaredNorm().transpose();
        generated += (generateMostLikely(s.labels).rowwise() - mean.transpose()).colwise().squaredNorm().transpose();
    }
    Eigen::VectorXd gain(d);
    for (Eigen::Index k = 0; k < d; ++k)
        gain[k] = generated[k] > 0.0 ? std::sqrt(real[k] / generated[k]) : 1.0;
    // A scale of the trajectory, not a new one: bounded both ways.
    m_gain = gain.cwiseMax(kMinCompensationGain).cwiseMin(kMaxCompensationGain);
    m_mean = mean;
}

Eigen::MatrixXd DynamicModel::generate(const std::vector<int> &labels) const
{
    Eigen::MatrixXd y = generateMostLikely(labels);
    if (m_gain.size() == 0)
        return y;
    y = ((y.rowwise() - m_mean.transpose()).array().rowwise() * m_gain.transpose().array()).matrix();
    return y.rowwise() + m_mean.transpose();
}

std::unique_ptr<StreamingGenerator> DynamicModel::streamer() const
{
    std::unique_ptr<StreamingGenerator> inner = makeStreamer();
    if (m_gain.size() == 0)
        return inner;
    return std::make_unique<CompensatedStreamer>(std::move(inner), m_mean, m_gain);
}

void DynamicModel::setCompensation(const Eigen::VectorXd &mean, const Eigen::VectorXd &gain)
{
    if (mean.size() == 0 && gain.size() == 0) {
        m_mean.resize(0);
        m_gain.resize(0);
        return;
    }
    if (mean.size() != m_dimension || gain.size() != m_dimension)
        throw Error("the variance compensation has " + std::to_string(gain.size()) + " gains for "
                    + std::to_string(m_dimension) + " dimensions");
    if (!mean.allFinite() || !gain.allFinite() || (gain.array() <= 0.0).any())
        throw Error("the variance compensation's gains must be positive and finite");
    m_mean = mean;
    m_gain = gain;
}

void DynamicModel::setStateCount(int states)
{
    if (states < 1)
        throw Error("a model needs at least one state, not " + std::to_string(states));
    m_stateCount = states;
}

void DynamicModel::checkTrained() const
{
    if (!isTrained())
        throw Error("the " + kind() + " model has not been trained");
}

void DynamicModel::checkGenerationInput(const std::vector<int> &labels) const
{
    checkTrained();
    validateLabels(labels, "labels", m_stateCount);
}

void DynamicModel::checkScoringInput(const std::vector<int> &labels,
                                     const Eigen::MatrixXd &features) const
{
    checkGenerationInput(labels);
    if (features.cols() != m_dimension)
        throw Error("features have " + std::to_string(features.cols()) + " dimensions, the model "
                    + std::to_string(m_dimension));
    if (Eigen::Index(labels.size()) != features.rows())
        throw Error(std::to_string(labels.size()) + " frame labels but "
                    + std::to_string(features.rows()) + " feature rows");
    if (!features.allFinite())
        throw Error("features contain NaN or infinite values");
}

} // namespace lipsync
