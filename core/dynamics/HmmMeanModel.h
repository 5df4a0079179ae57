#pragma once
// HMM-mean baseline (docs/models.md §1): one diagonal Gaussian per phone, frames independent given
// the labels; generation emits the phone means. Unseen phones use the global mean and variance.
#include "dynamics/DynamicModel.h"
#include "dynamics/LinearRecursion.h"

namespace lipsync {

class HmmMeanModel : public DynamicModel
{
public:
    std::string kind() const override { return modelKindId(ModelKind::HmmMean); }
    Eigen::MatrixXd generateMostLikely(const std::vector<int> &labels) const override;
    std::unique_ptr<StreamingGenerator> makeStreamer() const override;
    double logLikelihood(const std::vector<int> &labels,
                         const Eigen::MatrixXd &features) const override;
    QJsonObject parametersToJson() const override;
    void parametersFromJson(const QJsonObject &json, const std::string &file) override;

    const Eigen::MatrixXd &means() const { return m_mean; }         // P x d
    void shiftMeans(const Eigen::MatrixXd &shift) override;
    const Eigen::MatrixXd &variances() const { return m_variance; } // P x d

protected:
    void fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback) override;

private:
    LinearRecursion recursion() const;
    Eigen::MatrixXd m_mean;
    Eigen::MatrixXd m_variance;
};

} // namespace lipsync
