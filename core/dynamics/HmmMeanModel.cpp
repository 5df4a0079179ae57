#include "dynamics/HmmMeanModel.h"

#include "dynamics/GaussianMath.h"
#include "dynamics/JsonEigen.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

namespace lipsync {

void HmmMeanModel::fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    feedback.throwIfCanceled();
    const FrameStatistics st = computeFrameStatistics(sequences, stateCount());
    m_mean = st.mean;
    m_variance = st.variance;
    m_dimension = int(st.mean.cols());
    feedback.setProgress(1.0);
}

void HmmMeanModel::shiftMeans(const Eigen::MatrixXd &shift)
{
    checkMeanShift(shift, m_mean.rows());
    m_mean += shift;
}

LinearRecursion HmmMeanModel::recursion() const
{
    LinearRecursion r;
    r.mu = m_mean;
    r.nu = m_mean;
    r.a = Eigen::MatrixXd::Zero(m_mean.rows(), m_mean.cols());
    return r;
}

Eigen::MatrixXd HmmMeanModel::generateMostLikely(const std::vector<int> &labels) const
{
    checkGenerationInput(labels);
    Eigen::MatrixXd out(Eigen::Index(labels.size()), m_dimension);
    for (size_t t = 0; t < labels.size(); ++t)
        out.row(Eigen::Index(t)) = m_mean.row(labels[t]);
    return out;
}

std::unique_ptr<StreamingGenerator> HmmMeanModel::makeStreamer() const
{
    checkTrained();
    return recursion().streamer();
}

double HmmMeanModel::logLikelihood(const std::vector<int> &labels,
                                   const Eigen::MatrixXd &features) const
{
    checkScoringInput(labels, features);
    double ll = 0.0;
    for (size_t t = 0; t < labels.size(); ++t)
        ll += diagonalGaussianLogPdf(features.row(Eigen::Index(t)).transpose(),
                                     m_mean.row(labels[t]).transpose(),
                                     m_variance.row(labels[t]).transpose());
    return ll;
}

QJsonObject HmmMeanModel::parametersToJson() const
{
    QJsonObject o;
    o[QStringLiteral("mean")] = json::fromMatrix(m_mean);
    o[QStringLiteral("variance")] = json::fromMatrix(m_variance);
    return o;
}

void HmmMeanModel::parametersFromJson(const QJsonObject &o, const std::string &file)
{
    m_mean = json::toMatrix(o, "mean", stateCount(), -1, file);
    m_variance = json::toMatrix(o, "variance", stateCount(), m_mean.cols(), file);
    m_dimension = int(m_mean.cols());
}

} // namespace lipsync
