#include "eval/Metrics.h"

#include "util/Error.h"

#include <cmath>

namespace lipsync {

SequenceErrors sequenceErrors(const Eigen::MatrixXd &generated, const Eigen::MatrixXd &real)
{
    if (generated.rows() != real.rows() || generated.cols() != real.cols() || real.size() == 0)
        throw Error("generated and real features differ in shape or are empty");
    const Eigen::ArrayXXd E = (generated - real).array().abs();
    const double T = double(E.rows());
    SequenceErrors out;
    out.l1 = E.rowwise().sum().sum() / T;
    out.rms = std::sqrt(E.square().rowwise().sum().sum() / T);
    out.linf = E.rowwise().maxCoeff().sum() / T;
    return out;
}

} // namespace lipsync
