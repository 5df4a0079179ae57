#pragma once
// Brand's Voice Puppetry as the paper uses it (docs/models.md §2): per phone a Gaussian over static
// and delta features o_t = [y_t; y_t - y_{t-1}], frame 1 static only; generation is the MLPG
// maximiser (§2.2): d tridiagonal solves (diagonal covariances, the default) or one
// block-tridiagonal solve (full 2d x 2d covariances). Streaming uses the fixed-lag truncation of §5
// (diagonal only). Unseen phones back off to the global static and delta statistics.
#include "dynamics/BrandSolver.h"
#include "dynamics/DynamicModel.h"

namespace lipsync {

struct BrandOptions
{
    bool fullCovariance = false;
    // Fixed lag L of the streamer (§5); 0 = the smallest L with rho^L <= 1e-3 (at most 500).
    int lag = 0;
};

class BrandModel : public DynamicModel
{
public:
    explicit BrandModel(BrandOptions options = {}) : m_options(options) {}
    std::string kind() const override { return modelKindId(ModelKind::Brand); }
    const BrandOptions &options() const { return m_options; }

    Eigen::MatrixXd generateMostLikely(const std::vector<int> &labels) const override;
    std::unique_ptr<StreamingGenerator> makeStreamer() const override;
    // §2.1: the density over static + delta features (not comparable with the other models).
    double logLikelihood(const std::vector<int> &labels,
                         const Eigen::MatrixXd &features) const override;
    // §2.2: the normalised trajectory density N(Y; Yhat, H^-1), a true density over y (the one
    // the evaluation compares with the other models).
    double trajectoryLogLikelihood(const std::vector<int> &labels,
                                   const Eigen::MatrixXd &features) const override;

    // The MLPG system as d x d blocks (any covariance), and its solutions by block LDL^T and by
    // the dense reference built from explicit W and Lambda (small T only).
    brand::BlockTridiagonalSystem blockSystem(const std::vector<int> &labels) const;
    Eigen::MatrixXd generateBlock(const std::vector<int> &labels) const;
    void denseReferenceSystem(const std::vector<int> &labels, Eigen::MatrixXd &H,
                              Eigen::VectorXd &b) const;
    Eigen::MatrixXd generateDenseReference(const std::vector<int> &labels) const;
    // The tridiagonal system of dimension k (diagonal covariances).
    brand::TridiagonalSystem tridiagonalSystem(const std::vector<int> &labels, int k) const;
    // rho = q_max / (q_max + p_min) of §2.2 and the streamer's lag.
    double contraction() const;
    int streamingLag() const;

    QJsonObject parametersToJson() const override;
    void parametersFromJson(const QJsonObject &json, const std::string &file) override;

    // Diagonal parameters (P x d); with full covariances, their diagonals.
    Eigen::MatrixXd staticMean, staticVariance, deltaMean, deltaVariance;
    // Full covariance: per phone the 2d mean [m^y; m^Delta] and the 2d x 2d covariance.
    Eigen::MatrixXd jointMean;
    std::vector<Eigen::MatrixXd> jointCovariance;

protected:
    void fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback) override;

private:
    void fitFull(const std::vector<LabelledSequence> &sequences, const Eigen::VectorXd &floor);
    // Precision of o_t (t >= 2) and of y_1, per phone.
    Eigen::MatrixXd jointPrecision(int n) const;
    Eigen::MatrixXd staticPrecision(int n) const;
    BrandOptions m_options;
};

} // namespace lipsync
