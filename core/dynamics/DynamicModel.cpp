#include "dynamics/DynamicModel.h"

#include "util/Error.h"

#include <cmath>

namespace lipsync {

void DynamicModel::train(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    validateSequences(sequences);
    fit(sequences, feedback);
}

void DynamicModel::checkTrained() const
{
    if (!isTrained())
        throw Error("the " + kind() + " model has not been trained");
}

void DynamicModel::checkGenerationInput(const std::vector<int> &labels) const
{
    checkTrained();
    validateLabels(labels);
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
