#pragma once
// The common interface of the four dynamic models of the paper (docs/models.md §1-§5): train on
// labelled sequences, generate the most likely trajectory for a label sequence, stream it where
// the model allows, and score sequences by their log-likelihood. Parameters are (de)serialised to
// JSON; ModelFile.h wraps them in the versioned model file.
#include "dynamics/LabelledSequence.h"
#include "dynamics/ModelKind.h"
#include "dynamics/StreamingGenerator.h"

#include <QJsonObject>

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class Feedback;

class DynamicModel
{
public:
    virtual ~DynamicModel() = default;

    // The kind's id (ModelKind.h).
    virtual std::string kind() const = 0;
    // Feature dimension d, 0 before training.
    int dimension() const { return m_dimension; }
    bool isTrained() const { return m_dimension > 0; }

    // Validates (validateSequences) and fits the parameters. Reports progress and the objective
    // per iteration, polls cancel (throws Canceled; the model is then left unchanged).
    void train(const std::vector<LabelledSequence> &sequences, Feedback &feedback);

    // Most likely trajectory for the labels: T x d. Labels never seen in training use the
    // documented back-off statistics of each model.
    virtual Eigen::MatrixXd generate(const std::vector<int> &labels) const = 0;
    // Frame-by-frame generation; equals generate() (exactly for the recursive models).
    virtual std::unique_ptr<StreamingGenerator> streamer() const = 0;
    // log p(features | labels) in nats, the model's own objective (for Brand: the density over
    // static + delta features [y; Δy], docs/models.md §2.1).
    virtual double logLikelihood(const std::vector<int> &labels,
                                 const Eigen::MatrixXd &features) const = 0;
    // log p(y_1..y_T | labels) in nats, a density over the face trajectory alone, so the four
    // models' values can be compared and ranked (§6.2). logLikelihood() for every model whose
    // likelihood is over y; Brand overrides it with its trajectory-HMM density (§2.2).
    virtual double trajectoryLogLikelihood(const std::vector<int> &labels,
                                           const Eigen::MatrixXd &features) const
    {
        return logLikelihood(labels, features);
    }

    // Parameters only (the model file adds kind, version, labels, AAM).
    virtual QJsonObject parametersToJson() const = 0;
    // Throws lipsync::Error naming `file` and the field for missing or malformed parameters.
    virtual void parametersFromJson(const QJsonObject &json, const std::string &file) = 0;

protected:
    virtual void fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback) = 0;
    void checkTrained() const;
    void checkGenerationInput(const std::vector<int> &labels) const;
    void checkScoringInput(const std::vector<int> &labels, const Eigen::MatrixXd &features) const;

    int m_dimension = 0;
};

} // namespace lipsync
