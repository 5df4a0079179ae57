#pragma once
// Any of the four dynamic models over context-dependent states (docs/models.md §5.2): training
// grows a ContextTree on the phone-labelled sequences and trains the inner model on the tree's
// states; generation and scoring map the phone labels to states first. The inner model is one of
// the paper's four, unchanged, with P = the tree's state count instead of the 41 phones. Streaming
// holds each phone's frames until the next phone starts (its right context and its length); the
// prompt streamer (Live) holds a frame kPromptWait labels at most, then guesses both
// (ContextTree::predicted).
#include "dynamics/ContextTree.h"
#include "dynamics/DynamicModel.h"

#include <memory>

namespace lipsync {

class ContextDependentModel : public DynamicModel
{
public:
    ContextDependentModel(std::unique_ptr<DynamicModel> inner, ContextTreeOptions options = {});
    // Labels the prompt streamer holds a frame for at most, waiting for its phone to end: most
    // phones last fewer video frames (GRID s1's median phone: 2 frames at 25 fps).
    static constexpr int kPromptWait = 4;

    std::string kind() const override { return m_inner->kind(); }
    const DynamicModel &inner() const { return *m_inner; }
    const ContextTreeOptions &treeOptions() const { return m_options; }
    // For options of the inner kind (the SLDS's initialisation) set before train().
    DynamicModel &inner() { return *m_inner; }
    const ContextTree &tree() const { return m_tree; }
    // A trained tree (model files); sets the inner model's state count.
    void setTree(ContextTree tree);

    Eigen::MatrixXd generateMostLikely(const std::vector<int> &labels) const override;
    double logLikelihood(const std::vector<int> &labels, const Eigen::MatrixXd &features) const override;
    double trajectoryLogLikelihood(const std::vector<int> &labels,
                                   const Eigen::MatrixXd &features) const override;
    // `shift` per phone (41 x d): each state moves by its phone's row.
    void shiftMeans(const Eigen::MatrixXd &shift) override;
    QJsonObject parametersToJson() const override { return m_inner->parametersToJson(); }
    void parametersFromJson(const QJsonObject &json, const std::string &file) override;

protected:
    void fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback) override;
    std::unique_ptr<StreamingGenerator> makeStreamer() const override;
    std::unique_ptr<StreamingGenerator> makePromptStreamer() const override;

private:
    std::unique_ptr<DynamicModel> m_inner;
    ContextTreeOptions m_options;
    ContextTree m_tree;
};

} // namespace lipsync
