#include "render/PostureTransfer.h"

#include "dynamics/DynamicModel.h"
#include "render/BilabialClosure.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <Eigen/QR>
#include <Eigen/SVD>

#include <cmath>
#include <optional>

namespace lipsync {

PostureTransfer::PostureTransfer(const Eigen::MatrixXd &phoneTargets, const Eigen::VectorXd &variances,
                                 const Eigen::VectorXd &opening)
{
    const Eigen::Index d = variances.size();
    if (phoneTargets.cols() != d || phoneTargets.rows() < 2 || (opening.size() != 0 && opening.size() != d))
        throw Error("posture transfer: " + std::to_string(phoneTargets.rows()) + " phone targets of "
                    + std::to_string(phoneTargets.cols()) + " parameters for a model of " + std::to_string(d));
    if (!phoneTargets.allFinite() || !(variances.array() > 0).all())
        throw Error("posture transfer: phone targets or variances that are not finite and positive");
    const Eigen::VectorXd root = variances.cwiseSqrt();
    m_level = phoneTargets.colwise().mean().transpose();
    // The targets' spread, whitened: its leading directions, kSpeechShare of it.
    const Eigen::MatrixXd spread
        = ((phoneTargets.rowwise() - m_level.transpose()).array().rowwise() / root.transpose().array()).matrix().transpose();
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(spread, Eigen::ComputeThinU);
    const Eigen::VectorXd energy = svd.singularValues().array().square();
    const double total = energy.sum();
    Eigen::Index keep = 0;
    for (double sum = 0; keep < energy.size() && total > 0 && sum < kSpeechShare * total; ++keep)
        sum += energy[keep];
    Eigen::MatrixXd basis(d, keep + (opening.size() ? 1 : 0));
    basis.leftCols(keep) = svd.matrixU().leftCols(keep);
    if (opening.size())
        basis.col(keep) = root.cwiseProduct(opening); // a^T c = (Λ^{1/2} a)^T w
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(basis);
    m_speechDimension = int(qr.rank());
    const Eigen::MatrixXd u = Eigen::MatrixXd(qr.householderQ()).leftCols(m_speechDimension);
    const Eigen::MatrixXd outside = Eigen::MatrixXd::Identity(d, d) - u * u.transpose();
    m_outside = root.asDiagonal() * outside * root.cwiseInverse().asDiagonal();
}

std::shared_ptr<const PostureTransfer> PostureTransfer::forModel(const DynamicModel &model, const AamModel &aam)
{
    const int d = aam.combinedModes();
    if (d == 0 || model.dimension() != d || aam.combinedVariances.size() != d)
        return nullptr;
    // Each phone alone for a third of a second: its target, free of its neighbours.
    const int frames = std::max(3, int(std::lround((model.frameRate() > 0 ? model.frameRate() : 25.0) / 3.0)));
    const std::optional<BilabialClosure> closure = BilabialClosure::forAam(aam);
    try {
        Eigen::MatrixXd targets(PhoneSet::kCount, d);
        for (int p = 0; p < PhoneSet::kCount; ++p)
            targets.row(p) = model.generate(std::vector<int>(size_t(frames), p)).row(frames / 2);
        return std::make_shared<const PostureTransfer>(targets, aam.combinedVariances,
                                                       closure ? closure->gradient() : Eigen::VectorXd());
    } catch (const Error &) {
        return nullptr;
    }
}

Eigen::VectorXd PostureTransfer::apply(const Eigen::VectorXd &generated, const Eigen::VectorXd &posture) const
{
    if (generated.size() != m_level.size() || posture.size() != m_level.size() || !posture.allFinite())
        return generated;
    return generated + m_outside * (posture - m_level);
}

Eigen::MatrixXd PostureTransfer::slowPosture(const Eigen::MatrixXd &tracked, const std::vector<double> &times,
                                             double seconds)
{
    const Eigen::Index n = std::min<Eigen::Index>(tracked.rows(), Eigen::Index(times.size()));
    Eigen::MatrixXd out = Eigen::MatrixXd::Constant(tracked.rows(), tracked.cols(), std::nan(""));
    const double reach = 3.0 * seconds;
    Eigen::Index first = 0;
    for (Eigen::Index t = 0; t < n; ++t) {
        while (first < n && times[size_t(first)] < times[size_t(t)] - reach)
            ++first;
        Eigen::VectorXd sum = Eigen::VectorXd::Zero(tracked.cols());
        double weight = 0;
        for (Eigen::Index s = first; s < n && times[size_t(s)] <= times[size_t(t)] + reach; ++s) {
            if (!tracked.row(s).allFinite())
                continue;
            const double z = (times[size_t(s)] - times[size_t(t)]) / seconds;
            const double w = std::exp(-0.5 * z * z);
            sum += w * tracked.row(s).transpose();
            weight += w;
        }
        if (weight > 0)
            out.row(t) = sum.transpose() / weight;
    }
    return out;
}

} // namespace lipsync
