#include "dynamics/DynamicModel.h"

#include "dynamics/GaussianMath.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>

namespace lipsync {

namespace {

// The slow part of frame t of a T-frame trajectory whose frames `frame(k)` returns: the mean of
// the `window` frames centred on it, frames beyond either end taken as the end frame (§5.1). One
// function for the whole-trajectory and the streaming forms, so both sum in the same order.
template<class Frame>
Eigen::VectorXd slowPart(const Frame &frame, Eigen::Index t, Eigen::Index T, int window)
{
    const int half = window / 2;
    Eigen::VectorXd sum = frame(std::clamp<Eigen::Index>(t - half, 0, T - 1));
    for (int k = -half + 1; k <= half; ++k)
        sum += frame(std::clamp<Eigen::Index>(t + k, 0, T - 1));
    return sum / double(window);
}

// One frame y with slow part s and fast-window mean f: y' = m + G (s - m) + H (f - s) + (y - f);
// without a fast window y' = m + G (s - m) + H (y - s); window 0: y' = m + G (y - m) (§5.1).
Eigen::VectorXd compensateFrame(const Eigen::VectorXd &y, const Eigen::VectorXd &slow, const Eigen::VectorXd &fast,
                                const Eigen::VectorXd &mean, const Eigen::MatrixXd &gain,
                                const Eigen::MatrixXd &detailGain)
{
    if (detailGain.size() == 0)
        return mean + gain * (y - mean);
    if (fast.size() == 0)
        return mean + gain * (slow - mean) + detailGain * (y - slow);
    return mean + gain * (slow - mean) + detailGain * (fast - slow) + (y - fast);
}

// The slow parts of every frame of `y` (T x d).
Eigen::MatrixXd slowParts(const Eigen::MatrixXd &y, int window)
{
    Eigen::MatrixXd s(y.rows(), y.cols());
    auto frame = [&](Eigen::Index k) -> Eigen::VectorXd { return y.row(k).transpose(); };
    for (Eigen::Index t = 0; t < y.rows(); ++t)
        s.row(t) = slowPart(frame, t, y.rows(), window).transpose();
    return s;
}

// The optimal-transport map between N(0, Rg) and N(0, Rr) (models.md §5.1), Rg the scatter of the
// generated trajectories' band about the training mean and Rr the recordings':
// A = Rg^(-1/2) (Rg^(1/2) Rr Rg^(1/2))^(1/2) Rg^(-1/2), the symmetric positive definite A with
// A Rg A = Rr; its eigenvalues bounded both ways, a scale of the trajectory, not a new one. Rg is
// regularised by a millionth of the mean variance, so that a direction the generated trajectories
// never leave m in (where any gain keeps them at m) does not make it singular.
Eigen::MatrixXd gainOf(const Eigen::MatrixXd &real, const Eigen::MatrixXd &generated)
{
    const Eigen::Index d = real.rows();
    const double floor = 1e-6 * std::max(generated.trace(), real.trace()) / double(std::max<Eigen::Index>(1, d)) + 1e-300;
    Eigen::MatrixXd regularised = generated;
    regularised.diagonal().array() += floor;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(regularised);
    const Eigen::VectorXd rootValues = eigen.eigenvalues().cwiseMax(floor).cwiseSqrt();
    const Eigen::MatrixXd root = eigen.eigenvectors() * rootValues.asDiagonal() * eigen.eigenvectors().transpose();
    const Eigen::MatrixXd inverseRoot
        = eigen.eigenvectors() * rootValues.cwiseInverse().asDiagonal() * eigen.eigenvectors().transpose();
    const Eigen::MatrixXd middle
        = symmetricMatrixFunction(root * real * root, [](double l) { return std::sqrt(std::max(l, 0.0)); });
    Eigen::MatrixXd a = inverseRoot * middle * inverseRoot;
    a = 0.5 * (a + a.transpose());
    return symmetricMatrixFunction(a, [](double l) {
        return std::clamp(l, DynamicModel::kMinCompensationGain, DynamicModel::kMaxCompensationGain);
    });
}

// The compensation applied to each frame another streamer emits. With a window, frame t leaves
// once the inner streamer has emitted frame t + window / 2 (or has finished).
class CompensatedStreamer : public StreamingGenerator
{
public:
    CompensatedStreamer(std::unique_ptr<StreamingGenerator> inner, Eigen::VectorXd mean, Eigen::MatrixXd gain,
                        Eigen::MatrixXd detailGain, int window, int fastWindow)
        : m_inner(std::move(inner)), m_mean(std::move(mean)), m_gain(std::move(gain)),
          m_detailGain(std::move(detailGain)), m_half(window / 2), m_window(window), m_fastWindow(fastWindow),
          m_frame(m_mean.size())
    {
    }
    int latency() const override { return m_inner->latency() < 0 ? -1 : m_inner->latency() + m_half; }
    void push(int label) override
    {
        m_inner->push(label);
        drain();
    }
    void finish() override
    {
        m_inner->finish();
        m_finished = true;
        drain();
    }
    bool pop(Eigen::Ref<Eigen::VectorXd> frame) override { return m_ready.pop(frame); }

private:
    // Takes the inner streamer's frames and releases every frame whose window is complete.
    void drain()
    {
        while (m_inner->pop(m_frame)) {
            m_frames.push_back(m_frame);
            ++m_received;
        }
        while (m_next < m_received && (m_next + m_half < m_received || m_finished)) {
            const Eigen::Index T = m_finished ? m_received : m_received + m_half + 1; // frames beyond are not needed
            auto frame = [&](Eigen::Index k) -> Eigen::VectorXd { return m_frames[size_t(k - m_first)]; };
            const Eigen::VectorXd slow = m_detailGain.size() ? slowPart(frame, m_next, T, m_window) : Eigen::VectorXd();
            const Eigen::VectorXd fast = m_detailGain.size() && m_fastWindow > 0
                                             ? slowPart(frame, m_next, T, m_fastWindow)
                                             : Eigen::VectorXd();
            m_ready.push(compensateFrame(frame(m_next), slow, fast, m_mean, m_gain, m_detailGain));
            ++m_next;
            // Frames before next - half are no longer in any window (frame 0 stays while it is
            // the clamped edge).
            while (m_first < m_next - m_half && m_first + 1 < m_received) {
                m_frames.pop_front();
                ++m_first;
            }
        }
    }

    std::unique_ptr<StreamingGenerator> m_inner;
    Eigen::VectorXd m_mean;
    Eigen::MatrixXd m_gain, m_detailGain;
    const int m_half, m_window, m_fastWindow;
    Eigen::VectorXd m_frame;
    std::deque<Eigen::VectorXd> m_frames; // inner frames m_first .. m_received - 1
    Eigen::Index m_first = 0, m_received = 0, m_next = 0;
    bool m_finished = false;
    ReadyFrames m_ready;
};

} // namespace

void DynamicModel::shiftMeans(const Eigen::MatrixXd &)
{
    throw Error("a " + kind() + " model has no per-phone means to start from a prior");
}

void DynamicModel::checkMeanShift(const Eigen::MatrixXd &shift, Eigen::Index rows) const
{
    checkTrained();
    if (shift.rows() != rows || shift.cols() != m_dimension || !shift.allFinite())
        throw Error("a shift of the means of " + std::to_string(shift.rows()) + " x " + std::to_string(shift.cols())
                    + (shift.allFinite() ? "" : " with values that are not finite") + " for a model of "
                    + std::to_string(rows) + " x " + std::to_string(m_dimension));
}

void DynamicModel::train(const std::vector<LabelledSequence> &sequences, Feedback &feedback)
{
    validateSequences(sequences, m_stateCount);
    // One rate for the dynamics, which are per frame: rates within kFrameRateTolerance of the
    // first are that rate (NTSC's 30000/1001 and a container's rounded 29.97, or 29.97 and 30:
    // a pace 0.1 % apart, where speakers' own pace varies by tens of percent), recorded as their
    // mean over the frames.
    double first = 0.0, frameSum = 0.0, offsetSum = 0.0;
    for (const LabelledSequence &s : sequences) {
        if (s.frameRate <= 0)
            continue;
        if (first > 0 && std::abs(s.frameRate - first) > kFrameRateTolerance * first) {
            char rates[96];
            std::snprintf(rates, sizeof rates, "%.7g and %.7g frames/s", first, s.frameRate);
            throw Error(std::string("the training sequences have different frame rates (") + rates + ", " + s.name
                        + "): a model's dynamics are per frame, so train it on one rate");
        }
        first = first > 0 ? first : s.frameRate;
        frameSum += double(s.features.rows());
        offsetSum += double(s.features.rows()) * (s.frameRate - first);
    }
    const double rate = frameSum > 0 ? first + offsetSum / frameSum : first; // exactly `first` when all agree
    fit(sequences, feedback);
    if (startedFromOtherSpeakers())
        shiftMeans(m_meanShift);
    m_frameRate = rate;
    m_mean.resize(0);
    m_gain.resize(0, 0);
    m_detailGain.resize(0, 0);
    m_window = 0;
    m_fastWindow = 0;
    if (!m_compensate)
        return;
    // The scatter of both bands, about the training mean, pooled over every training frame (§5.1).
    const Eigen::Index d = m_dimension;
    Eigen::VectorXd mean = Eigen::VectorXd::Zero(d);
    double frames = 0.0;
    for (const LabelledSequence &s : sequences) {
        mean += s.features.colwise().sum().transpose();
        frames += double(s.features.rows());
    }
    mean /= frames;
    const int window = kCompensationWindow, fastWindow = kCompensationFastWindow;
    Eigen::MatrixXd realSlow = Eigen::MatrixXd::Zero(d, d), generatedSlow = realSlow, realDetail = realSlow,
                    generatedDetail = realSlow;
    auto scatter = [](Eigen::MatrixXd &sum, const Eigen::MatrixXd &x) {
        sum.selfadjointView<Eigen::Lower>().rankUpdate(x.transpose()); // sum += x^T x, lower half
    };
    for (const LabelledSequence &s : sequences) {
        feedback.throwIfCanceled();
        const Eigen::MatrixXd generated = generateMostLikely(s.labels);
        const Eigen::MatrixXd real = s.features;
        const Eigen::MatrixXd sr = slowParts(real, window), sg = slowParts(generated, window);
        scatter(realSlow, sr.rowwise() - mean.transpose());
        scatter(generatedSlow, sg.rowwise() - mean.transpose());
        scatter(realDetail, slowParts(real, fastWindow) - sr);
        scatter(generatedDetail, slowParts(generated, fastWindow) - sg);
    }
    for (Eigen::MatrixXd *m : {&realSlow, &generatedSlow, &realDetail, &generatedDetail})
        *m = m->selfadjointView<Eigen::Lower>();
    m_mean = mean;
    m_gain = gainOf(realSlow, generatedSlow);
    m_detailGain = gainOf(realDetail, generatedDetail);
    m_window = window;
    m_fastWindow = fastWindow;
}

Eigen::MatrixXd DynamicModel::compensate(const Eigen::MatrixXd &y) const
{
    if (m_gain.size() == 0)
        return y;
    const Eigen::MatrixXd slow = m_window > 0 ? slowParts(y, m_window) : Eigen::MatrixXd();
    const Eigen::MatrixXd fast = m_fastWindow > 0 ? slowParts(y, m_fastWindow) : Eigen::MatrixXd();
    auto row = [](const Eigen::MatrixXd &m, Eigen::Index t) {
        return m.size() ? Eigen::VectorXd(m.row(t).transpose()) : Eigen::VectorXd();
    };
    Eigen::MatrixXd out(y.rows(), y.cols());
    for (Eigen::Index t = 0; t < y.rows(); ++t)
        out.row(t) = compensateFrame(y.row(t).transpose(), row(slow, t), row(fast, t), m_mean, m_gain, m_detailGain)
                         .transpose();
    return out;
}

Eigen::MatrixXd DynamicModel::generate(const std::vector<int> &labels) const
{
    return compensate(generateMostLikely(labels));
}

std::unique_ptr<StreamingGenerator> DynamicModel::streamer() const
{
    return compensated(makeStreamer());
}

std::unique_ptr<StreamingGenerator> DynamicModel::promptStreamer() const
{
    return compensated(makePromptStreamer());
}

std::unique_ptr<StreamingGenerator> DynamicModel::compensated(std::unique_ptr<StreamingGenerator> inner) const
{
    if (m_gain.size() == 0)
        return inner;
    return std::make_unique<CompensatedStreamer>(std::move(inner), m_mean, m_gain, m_detailGain, m_window,
                                                 m_fastWindow);
}

Eigen::MatrixXd DynamicModel::generateStreamed(const std::vector<int> &labels, bool prompt) const
{
    const std::unique_ptr<StreamingGenerator> stream = prompt ? promptStreamer() : streamer();
    Eigen::MatrixXd Y(Eigen::Index(labels.size()), m_dimension);
    Eigen::VectorXd frame(m_dimension);
    Eigen::Index next = 0;
    for (int label : labels) {
        stream->push(label);
        while (stream->pop(frame))
            Y.row(next++) = frame.transpose();
    }
    stream->finish();
    while (stream->pop(frame))
        Y.row(next++) = frame.transpose();
    return Y;
}

void DynamicModel::setCompensation(const Eigen::VectorXd &mean, const Eigen::MatrixXd &gain,
                                   const Eigen::MatrixXd &detailGain, int window, int fastWindow)
{
    if (mean.size() == 0 && gain.size() == 0) {
        m_mean.resize(0);
        m_gain.resize(0, 0);
        m_detailGain.resize(0, 0);
        m_window = 0;
        m_fastWindow = 0;
        return;
    }
    if ((detailGain.size() == 0) != (window == 0) || (window != 0 && (window < 3 || window % 2 == 0)))
        throw Error("the variance compensation's window must be an odd number of frames from 3, with a detail "
                    "gain for each dimension (or neither)");
    if (fastWindow != 0 && (window == 0 || fastWindow < 3 || fastWindow % 2 == 0 || fastWindow >= window))
        throw Error("the variance compensation's fast window must be an odd number of frames from 3, shorter "
                    "than its window");
    // A gain is a scale: d x d, symmetric and positive definite.
    auto requireScale = [this](const Eigen::MatrixXd &g, const char *name) {
        if (g.rows() != m_dimension || g.cols() != m_dimension || !g.allFinite()
            || (g - g.transpose()).cwiseAbs().maxCoeff() > 1e-9 * (1.0 + g.cwiseAbs().maxCoeff())
            || Eigen::LLT<Eigen::MatrixXd>(g).info() != Eigen::Success)
            throw Error(std::string("the variance compensation's ") + name + " must be a symmetric positive definite "
                        + std::to_string(m_dimension) + " x " + std::to_string(m_dimension) + " matrix");
    };
    if (detailGain.size() != 0)
        requireScale(detailGain, "detail gain");
    if (mean.size() != m_dimension || !mean.allFinite())
        throw Error("the variance compensation's mean has " + std::to_string(mean.size()) + " values for "
                    + std::to_string(m_dimension) + " dimensions");
    requireScale(gain, "gain");
    m_mean = mean;
    m_gain = gain;
    m_detailGain = detailGain;
    m_window = window;
    m_fastWindow = fastWindow;
}

void DynamicModel::setStateCount(int states)
{
    if (states < 1)
        throw Error("a model needs at least one state, not " + std::to_string(states));
    m_stateCount = states;
}

void DynamicModel::setTrainingAligner(std::optional<AlignerChoice> choice)
{
    if (choice) // what aligns the speaker, not how one run measured it
        *choice = AlignerChoice{choice->model, choice->adapt};
    m_trainingAligner = std::move(choice);
}

void DynamicModel::checkTrained() const
{
    if (!isTrained())
        throw Error("the " + kind() + " model has not been trained");
}

void DynamicModel::checkGenerationInput(const std::vector<int> &labels) const
{
    checkTrained();
    validateLabels(labels, "labels", m_stateCount);
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
