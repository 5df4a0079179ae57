#pragma once
// The common interface of the four dynamic models of the paper (docs/models.md §1-§5): train on
// labelled sequences, generate the most likely trajectory for a label sequence, stream it where
// the model allows, and score sequences by their log-likelihood. Parameters are (de)serialised to
// JSON; ModelFile.h wraps them in the versioned model file.
#include "align/AlignerChoice.h"
#include "dynamics/LabelledSequence.h"
#include "dynamics/ModelKind.h"
#include "dynamics/StreamingGenerator.h"

#include <QJsonObject>

#include <Eigen/Core>

#include <cmath>
#include <memory>
#include <optional>
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
    // P, the number of states the labels index: the 41 phones, or the tied context states when
    // this model is the inner model of a ContextDependentModel (§5.2). Set before train() or
    // parametersFromJson(); throws lipsync::Error for P < 1.
    int stateCount() const { return m_stateCount; }
    void setStateCount(int states);
    bool isTrained() const { return m_dimension > 0; }

    // A starting point learnt elsewhere (animation/MouthShapePrior::personShift, docs/models.md
    // §5.4): train() moves each phone's mean by shift.row(phone) (41 x d) once the parameters are
    // fitted, before the variance compensation is estimated. Empty: none. Only kinds for which
    // modelKindTakesPrior() holds have per-phone means to move; train() throws for the others.
    // `weight`: the prior's weight in frames that made the shift (MouthShapePrior), recorded only.
    void setMeanShift(Eigen::MatrixXd shift, double weight = 0.0)
    {
        m_meanShift = std::move(shift);
        m_priorWeight = weight;
    }
    // The shift train() applied (a model file records it: whether, and how far, the model started
    // from other speakers); empty when it started from its own data alone.
    const Eigen::MatrixXd &meanShift() const { return m_meanShift; }
    bool startedFromOtherSpeakers() const { return m_meanShift.size() > 0; }
    double priorWeight() const { return m_priorWeight; } // 0: not recorded
    // Moves each label's mean (static and, for Brand, the joint mean's static half) by
    // shift.row(label): stateCount() x d of a trained model. Throws lipsync::Error for another
    // shape, values that are not finite, or a kind without per-label means.
    virtual void shiftMeans(const Eigen::MatrixXd &shift);

    // The share by which training sequences' frame rates may differ and still be one rate.
    static constexpr double kFrameRateTolerance = 0.01;
    // Validates (validateSequences) and fits the parameters. Reports progress and the objective
    // per iteration, polls cancel (throws Canceled; the model is then left unchanged). Records the
    // sequences' frame rate; sequences whose rates differ by more than kFrameRateTolerance are an
    // Error (the dynamics are per frame).
    void train(const std::vector<LabelledSequence> &sequences, Feedback &feedback);
    // Frames per second of the features it was trained on, the rate it generates at (0: not
    // known, e.g. model files that record none).
    double frameRate() const { return m_frameRate; }
    void setFrameRate(double fps) { m_frameRate = fps > 0 && std::isfinite(fps) ? fps : 0.0; }
    // The aligner whose phones it was trained on, as the training project chose it
    // (align/ProjectAligner): new speech for this speaker is aligned the same way when nothing else
    // says how (`lipsync render`, `export animation`). Only its model and adapt are kept; nullopt:
    // not recorded (trained from feature files, or by a project that names no aligner).
    const std::optional<AlignerChoice> &trainingAligner() const { return m_trainingAligner; }
    void setTrainingAligner(std::optional<AlignerChoice> choice);

    // The trajectory for the labels: T x d — the model's most likely one, with the variance
    // compensation applied when the model was trained with it.
    Eigen::MatrixXd generate(const std::vector<int> &labels) const;
    // Most likely trajectory of the model itself (the paper's generation). Labels never seen in
    // training use the documented back-off statistics of each model.
    virtual Eigen::MatrixXd generateMostLikely(const std::vector<int> &labels) const = 0;
    // Frame-by-frame generation; equals generate() (exactly for the recursive models).
    std::unique_ptr<StreamingGenerator> streamer() const;
    // Frame-by-frame generation that does not wait long for a phone to end, what Live draws:
    // streamer(), except that a model over phones in context holds a frame a few labels at most
    // (ContextDependentModel::kPromptWait) and then guesses its right context and segment third
    // (ContextTree::predicted) instead of holding it until the next phone starts.
    std::unique_ptr<StreamingGenerator> promptStreamer() const;
    // The labels pushed one by one through streamer() (generate()'s frames for the recursive
    // models, Brand's fixed-lag approximation of them), or through promptStreamer().
    Eigen::MatrixXd generateStreamed(const std::vector<int> &labels, bool prompt = false) const;

    // Variance compensation (docs/models.md §5.1), as global-variance compensation and the
    // modulation-spectrum post-filter of HMM speech synthesis: the most likely trajectory of every
    // model is smoother than the recordings it was trained on. It is split into its slow part s
    // (the centred moving average over `window` frames, about a syllable), its detail f - s (f the
    // centred mean over `fastWindow` frames) and the fastest part y - f; the first two are scaled
    // to the spread the training features have in that band, the fastest is kept
    // as generated (in the training features it is mostly the tracker's frame-to-frame noise):
    //   y' = m + G (s - m) + H (f - s) + (y - f),
    // G the optimal-transport map (the symmetric positive definite matrix with minimal
    // displacement) that takes the covariance of the slow parts of the trajectories generated for
    // the training labels to the covariance of the training features' slow parts, both about the
    // training mean m, its eigenvalues bounded to [kMinCompensationGain, kMaxCompensationGain];
    // H likewise for the detail. Matching the whole scatter, not each dimension's spread,
    // keeps the parameters the models move together (more than the recordings do) from adding up
    // to more motion than recorded. Streaming holds window / 2 frames back. Models read from files
    // with a gain per dimension use them as diagonal matrices; without a fast window (fastWindow
    // 0) they scale all of y - s by H, without `H` (window 0) the whole trajectory by G. Off unless
    // asked for before train(); the paper's models are the ones without it.
    static constexpr double kMinCompensationGain = 0.5;
    static constexpr double kMaxCompensationGain = 3.0;
    static constexpr int kCompensationWindow = 7; // frames: 0.28 s at 25 frames/s
    static constexpr int kCompensationFastWindow = 3; // frames: periods under 0.12 s (above 8 Hz)
    void setVarianceCompensation(bool on) { m_compensate = on; }
    bool compensatesVariance() const { return m_gain.size() > 0; }
    const Eigen::VectorXd &compensationMean() const { return m_mean; }
    const Eigen::MatrixXd &compensationGain() const { return m_gain; }
    const Eigen::MatrixXd &compensationDetailGain() const { return m_detailGain; }
    int compensationWindow() const { return m_window; }
    int compensationFastWindow() const { return m_fastWindow; }
    // Restores a trained compensation (model files); empty arguments turn it off, an empty
    // `detailGain` with window 0 scales the whole trajectory by `gain`, fastWindow 0 scales all of
    // the detail. Throws lipsync::Error for gains that are not dimension() x dimension(),
    // symmetric and positive definite, a window that is not odd and > 1 or a fast window that is
    // not odd, > 1 and below the window.
    void setCompensation(const Eigen::VectorXd &mean, const Eigen::MatrixXd &gain,
                         const Eigen::MatrixXd &detailGain = {}, int window = 0, int fastWindow = 0);
    // The compensation applied to a trajectory (T x d); the identity without one.
    Eigen::MatrixXd compensate(const Eigen::MatrixXd &trajectory) const;
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
    virtual std::unique_ptr<StreamingGenerator> makeStreamer() const = 0;
    virtual std::unique_ptr<StreamingGenerator> makePromptStreamer() const { return makeStreamer(); }
    void checkTrained() const;
    void checkGenerationInput(const std::vector<int> &labels) const;
    void checkScoringInput(const std::vector<int> &labels, const Eigen::MatrixXd &features) const;
    // shiftMeans()'s checks: trained, `rows` x d, finite.
    void checkMeanShift(const Eigen::MatrixXd &shift, Eigen::Index rows) const;

    int m_dimension = 0;

private:
    // `inner` with the variance compensation the model was trained with, if any.
    std::unique_ptr<StreamingGenerator> compensated(std::unique_ptr<StreamingGenerator> inner) const;
    int m_stateCount = PhoneSet::kCount;
    double m_frameRate = 0.0;
    std::optional<AlignerChoice> m_trainingAligner;
    bool m_compensate = false;
    Eigen::MatrixXd m_meanShift; // setMeanShift()
    double m_priorWeight = 0.0;
    Eigen::VectorXd m_mean; // compensation: training mean m and gain G (empty: none)
    Eigen::MatrixXd m_gain;
    Eigen::MatrixXd m_detailGain; // H, empty with m_window 0
    int m_window = 0;
    int m_fastWindow = 0; // 0: the detail band reaches to the frame rate
};

} // namespace lipsync
