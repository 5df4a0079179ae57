#include "dynamics/ContextDependentModel.h"

#include "tasks/Feedback.h"
#include "util/Error.h"

namespace lipsync {

namespace {

// Phone labels in, the inner streamer's frames out once their phone has ended (its right context
// and its length known), or, with a `wait` of 0 or more, at most that many labels after their
// own: a frame whose phone runs longer (a pause, a long vowel) then takes the context
// ContextTree::predicted guesses, its segment at least as long as seen so far (Live).
class ContextStreamer : public StreamingGenerator
{
public:
    ContextStreamer(const ContextTree &tree, std::unique_ptr<StreamingGenerator> inner, int dimension, int wait)
        : m_tree(tree), m_inner(std::move(inner)), m_frame(dimension), m_wait(wait)
    {
    }
    // -1: variable, a frame waits for the next phone to start.
    int latency() const override { return m_wait < 0 || m_inner->latency() < 0 ? -1 : m_wait + m_inner->latency(); }
    void push(int label) override
    {
        checkStateLabel(label, PhoneSet::kCount);
        if (m_length > 0 && label != m_phone)
            endSegment(label);
        m_phone = label;
        ++m_length;
        // Frames that have waited long enough leave with the guess.
        for (; m_wait >= 0 && m_length - m_sent > m_wait; ++m_sent) {
            PhoneContext c = m_tree.predicted(m_phone, m_previous, m_sent);
            const int length = std::max(m_tree.predictedLength(m_phone), m_length);
            c.position = segmentPosition(m_sent, length);
            send(c);
        }
    }
    void finish() override
    {
        if (m_length > 0)
            endSegment(PhoneSet::kSilence);
        m_inner->finish();
        drain();
    }
    bool pop(Eigen::Ref<Eigen::VectorXd> frame) override { return m_ready.pop(frame); }

private:
    // The segment has ended before `next`: its frames still held go with their true context.
    void endSegment(int next)
    {
        for (; m_sent < m_length; ++m_sent)
            send({m_phone, m_previous, next, segmentPosition(m_sent, m_length)});
        m_previous = m_phone;
        m_length = m_sent = 0;
    }
    void send(const PhoneContext &context)
    {
        m_inner->push(m_tree.state(context));
        drain();
    }
    void drain()
    {
        while (m_inner->pop(m_frame))
            m_ready.push(m_frame);
    }

    ContextTree m_tree; // a copy: the streamer outlives a retrained model
    std::unique_ptr<StreamingGenerator> m_inner;
    Eigen::VectorXd m_frame;
    const int m_wait; // -1: until the phone ends
    ReadyFrames m_ready;
    int m_phone = -1, m_previous = PhoneSet::kSilence;
    int m_length = 0, m_sent = 0; // frames of the running segment pushed, and sent on
};

} // namespace

ContextDependentModel::ContextDependentModel(std::unique_ptr<DynamicModel> inner, ContextTreeOptions options)
    : m_inner(std::move(inner)), m_options(options)
{
    if (!m_inner)
        throw Error("a context-dependent model needs an inner model");
    m_inner->setStateCount(m_tree.stateCount());
}

void ContextDependentModel::setTree(ContextTree tree)
{
    m_inner->setStateCount(tree.stateCount());
    m_tree = std::move(tree);
}

void ContextDependentModel::fit(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    Feedback growing(feedback, 0.0, 0.05);
    growing.setStatus("growing the context trees");
    ContextTree tree = ContextTree::grow(sequences, m_options, growing);
    std::vector<LabelledSequence> states = sequences;
    for (LabelledSequence &s : states)
        s.labels = tree.states(s.labels);
    const int previous = m_inner->stateCount();
    m_inner->setStateCount(tree.stateCount());
    try {
        Feedback training(feedback, 0.05, 1.0);
        // The inner model's iterations are this model's own.
        training.onIteration = [&feedback](int iteration, double objective) {
            feedback.reportIteration(iteration, objective);
        };
        m_inner->train(states, training);
    } catch (...) {
        m_inner->setStateCount(previous);
        throw;
    }
    m_tree = std::move(tree);
    m_dimension = m_inner->dimension();
}

void ContextDependentModel::shiftMeans(const Eigen::MatrixXd &shift)
{
    checkMeanShift(shift, PhoneSet::kCount);
    Eigen::MatrixXd states(m_tree.stateCount(), shift.cols());
    for (int s = 0; s < m_tree.stateCount(); ++s)
        states.row(s) = shift.row(m_tree.phoneOf(s));
    m_inner->shiftMeans(states);
}

Eigen::MatrixXd ContextDependentModel::generateMostLikely(const std::vector<int> &labels) const
{
    checkGenerationInput(labels);
    return m_inner->generateMostLikely(m_tree.states(labels));
}

double ContextDependentModel::logLikelihood(const std::vector<int> &labels,
                                            const Eigen::MatrixXd &features) const
{
    checkScoringInput(labels, features);
    return m_inner->logLikelihood(m_tree.states(labels), features);
}

double ContextDependentModel::trajectoryLogLikelihood(const std::vector<int> &labels,
                                                      const Eigen::MatrixXd &features) const
{
    checkScoringInput(labels, features);
    return m_inner->trajectoryLogLikelihood(m_tree.states(labels), features);
}

void ContextDependentModel::parametersFromJson(const QJsonObject &json, const std::string &file)
{
    m_inner->parametersFromJson(json, file);
    m_dimension = m_inner->dimension();
}

std::unique_ptr<StreamingGenerator> ContextDependentModel::makeStreamer() const
{
    checkTrained();
    return std::make_unique<ContextStreamer>(m_tree, m_inner->streamer(), m_dimension, -1);
}

std::unique_ptr<StreamingGenerator> ContextDependentModel::makePromptStreamer() const
{
    checkTrained();
    if (!m_tree.hasPrediction())
        return makeStreamer();
    return std::make_unique<ContextStreamer>(m_tree, m_inner->streamer(), m_dimension, kPromptWait);
}

} // namespace lipsync
