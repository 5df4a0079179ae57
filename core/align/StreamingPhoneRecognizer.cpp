#include "align/StreamingPhoneRecognizer.h"

#include "audio/Mfcc.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lipsync {

namespace {

constexpr int P = PhoneSet::kCount;
constexpr int E = AcousticModel::kStatesPerPhone;
constexpr int S = P * E;
// Consumed samples are dropped from the front of the buffer in batches of this many.
constexpr size_t kCompactSamples = 1 << 15;

// Frames of statics after a frame that its deltas and accelerations read.
int lookAhead(const MfccOptions &o)
{
    return o.deltas ? (o.accelerations ? 2 : 1) * o.deltaWindow : 0;
}

} // namespace

StreamingPhoneRecognizer::StreamingPhoneRecognizer(const AcousticModel &model, const PhoneBigram &bigram,
                                                   const PhoneRecognizerOptions &options)
    : m_model(model), m_bigram(bigram), m_options(options), m_mfcc(std::make_unique<Mfcc>(model.featureOptions())),
      m_window(m_mfcc->windowSamples()), m_shift(m_mfcc->shiftSamples()), m_logSelf(S), m_logNext(S)
{
    if (model.stateCount() != S)
        throw Error("phone recognition needs an aligner model of the 41 phones with 3 states each");
    if (model.normalization() == CepstralNormalization::MeanAndVariance)
        throw Error("live phone recognition needs an aligner model with cepstral mean normalisation (or none), "
                    "not mean and variance");
    if (m_options.lagFrames < 0 || !(m_options.meanSeconds > 0))
        throw Error("invalid phone recognition options (lag < 0 or mean window <= 0)");
    for (int s = 0; s < S; ++s) {
        m_logSelf[size_t(s)] = std::log(model.selfLoop(s));
        m_logNext[size_t(s)] = std::log(1.0 - model.selfLoop(s));
    }
    m_enter.resize(P, P);
    for (int p = 0; p < P; ++p)
        for (int q = 0; q < P; ++q)
            m_enter(p, q) = m_logNext[size_t(p * E + E - 1)] + m_options.languageWeight * m_bigram.logProbability(p, q)
                            + m_options.phoneInsertion;
    const int d = m_mfcc->staticDimension();
    m_silenceMean = Eigen::VectorXd::Zero(d);
    for (int k = 0; k < E; ++k) {
        const GaussianMixture &g = model.state(AcousticModel::stateIndex(PhoneSet::kSilence, k));
        m_silenceMean += (g.weights.transpose() * g.means.leftCols(d)).transpose().cast<double>() / E;
    }
    m_startSum = Eigen::VectorXd::Zero(d);
}

StreamingPhoneRecognizer::~StreamingPhoneRecognizer() = default;

double StreamingPhoneRecognizer::latencySeconds() const
{
    const MfccOptions &o = m_model.featureOptions();
    return (m_options.lagFrames + lookAhead(o)) * o.shiftSeconds + o.windowSeconds / 2;
}

void StreamingPhoneRecognizer::push(const float *samples, size_t count)
{
    m_samples.insert(m_samples.end(), samples, samples + count);
    size_t start = 0;
    std::vector<float> frame(static_cast<size_t>(m_window));
    const int look = lookAhead(m_model.featureOptions());
    while (m_samples.size() - start >= size_t(m_window)) {
        std::copy_n(m_samples.begin() + long(start), m_window, frame.begin());
        const Eigen::MatrixXf statics = m_mfcc->computeStatic(frame);
        addStaticFrame(statics.row(0).transpose());
        // Frame by frame, so that a long block keeps only the statics and back pointers in reach.
        while (m_featureFrames + look < m_staticFrames) {
            featuresOf(m_featureFrames++, false);
            decide(false);
        }
        start += size_t(m_shift);
        if (start >= kCompactSamples) {
            m_samples.erase(m_samples.begin(), m_samples.begin() + long(start));
            start = 0;
        }
    }
    m_samples.erase(m_samples.begin(), m_samples.begin() + long(start));
}

void StreamingPhoneRecognizer::finish()
{
    while (m_featureFrames < m_staticFrames)
        featuresOf(m_featureFrames++, true);
    decide(true);
}

void StreamingPhoneRecognizer::appendToTier(Tier &tier, int firstFrame, const std::vector<int> &phones,
                                            const MfccOptions &frames)
{
    for (size_t k = 0; k < phones.size(); ++k) {
        const double end = mfccFrameCentre(firstFrame + int(k), frames) + frames.shiftSeconds / 2;
        const std::string label = PhoneSet::label(phones[k]);
        if (!tier.intervals.empty() && tier.intervals.back().label == label)
            tier.intervals.back().end = end;
        else
            tier.intervals.push_back(Interval{tier.intervals.empty() ? 0.0 : tier.intervals.back().end, end, label, false});
    }
}

std::vector<int> StreamingPhoneRecognizer::takeDecided()
{
    return std::exchange(m_ready, {});
}

void StreamingPhoneRecognizer::addStaticFrame(const Eigen::VectorXf &statics)
{
    m_statics.push_back(statics);
    ++m_staticFrames;
    if (m_startFrames < m_options.silenceFrames) {
        m_startSum += statics.cast<double>();
        ++m_startFrames;
    }
    // Kept: the running mean's window and what the deltas of undecoded frames read.
    const long meanFrames = std::max(1L, std::lround(m_options.meanSeconds / m_model.featureOptions().shiftSeconds));
    const long keep = std::max(meanFrames, long(2 * lookAhead(m_model.featureOptions()) + 1)) + 1;
    while (long(m_statics.size()) > keep) {
        m_statics.pop_front();
        ++m_staticsFirst;
    }
}

void StreamingPhoneRecognizer::featuresOf(long f, bool atEnd)
{
    const MfccOptions &o = m_model.featureOptions();
    const int look = lookAhead(o);
    const int d = m_mfcc->staticDimension();
    const long last = m_staticFrames - 1;
    // The statics the deltas of f read, clipped to the sound: the edges of the whole sound are
    // where Mfcc::compute replicates, so inside them the result is the same as offline.
    const long from = std::max(std::max(0L, m_staticsFirst), f - look);
    const long to = atEnd ? last : std::min(last, f + look);
    Eigen::MatrixXf block(to - from + 1, d);
    for (long r = from; r <= to; ++r)
        block.row(r - from) = m_statics[size_t(r - m_staticsFirst)].transpose();
    Eigen::VectorXf features(m_model.dimension());
    const long row = f - from;
    features.head(d) = block.row(row).transpose();
    if (o.deltas) {
        const Eigen::MatrixXf withDeltas = Mfcc::regressionDeltas(block, o.deltaWindow);
        features.segment(d, d) = withDeltas.row(row).rightCols(d).transpose();
        if (o.accelerations)
            features.segment(2 * d, d) =
                Mfcc::regressionDeltas(withDeltas.rightCols(d), o.deltaWindow).row(row).rightCols(d).transpose();
    }
    if (m_model.normalization() != CepstralNormalization::None) {
        if (m_fixedMean.size() == d) {
            features.head(d) -= m_fixedMean;
        } else {
            // The running mean: the statics of the window ending at the newest frame f's
            // features read, whatever the block sizes were.
            const long meanFrames = std::lround(m_options.meanSeconds / o.shiftSeconds);
            const long end = std::min(last, f + look);
            const long begin = std::max(m_staticsFirst, end - meanFrames + 1);
            Eigen::VectorXd sum = Eigen::VectorXd::Zero(d);
            for (long r = begin; r <= end; ++r)
                sum += m_statics[size_t(r - m_staticsFirst)].cast<double>();
            double count = double(end - begin + 1);
            // The prior from the first frames and the silence model, fading over the first window.
            const double weight = m_options.priorFrames * std::max(0.0, 1.0 - double(end + 1) / double(meanFrames));
            if (weight > 0 && m_startFrames > 0) {
                sum += weight * (m_startSum / m_startFrames - m_silenceMean);
                count += weight;
            }
            features.head(d) -= (sum / count).cast<float>();
        }
    }
    if (m_keepHistory)
        m_history.push_back(features);
    decode(features);
}

void StreamingPhoneRecognizer::decode(const Eigen::VectorXf &features)
{
    Eigen::VectorXd next(S);
    std::vector<short> back(size_t(S), -1);
    const bool first = m_delta.size() == 0;
    if (first) {
        next.setConstant(-INFINITY);
        for (int q = 0; q < P; ++q)
            next(q * E) = m_options.languageWeight * m_bigram.logProbability(PhoneSet::kSilence, q)
                          + m_options.phoneInsertion;
    } else {
        // The best way into each phone's first state from any phone's last.
        Eigen::VectorXd enter(P);
        std::vector<short> from(size_t(P), 0);
        for (int q = 0; q < P; ++q) {
            double best = -INFINITY;
            for (int p = 0; p < P; ++p) {
                const double v = m_delta(p * E + E - 1) + m_enter(p, q);
                if (v > best) {
                    best = v;
                    from[size_t(q)] = short(p * E + E - 1);
                }
            }
            enter(q) = best;
        }
        for (int s = 0; s < S; ++s) {
            double best = m_delta(s) + m_logSelf[size_t(s)];
            short predecessor = short(s);
            const double in = s % E == 0 ? enter(s / E) : m_delta(s - 1) + m_logNext[size_t(s - 1)];
            if (in > best) {
                best = in;
                predecessor = s % E == 0 ? from[size_t(s / E)] : short(s - 1);
            }
            next(s) = best;
            back[size_t(s)] = predecessor;
        }
    }
    for (int s = 0; s < S; ++s)
        if (next(s) > -INFINITY)
            next(s) += m_model.state(s).logLikelihood(features.data());
    next.array() -= next.maxCoeff(); // scores relative to the best, so they never drift
    m_delta = std::move(next);
    m_back.push_back(std::move(back));
}

void StreamingPhoneRecognizer::decide(bool all)
{
    if (m_back.empty())
        return;
    const size_t keep = all ? 0 : size_t(m_options.lagFrames);
    if (m_back.size() <= keep)
        return;
    // The best path's states at the undecided frames, traced back from the best state now.
    int s = 0;
    m_delta.maxCoeff(&s);
    std::vector<int> states(m_back.size());
    for (size_t i = m_back.size(); i-- > 0;) {
        states[i] = s;
        if (i > 0)
            s = m_back[i][size_t(s)];
    }
    const size_t count = m_back.size() - keep;
    for (size_t i = 0; i < count; ++i) {
        m_ready.push_back(states[i] / E);
        m_back.pop_front();
        ++m_decided;
    }
}

} // namespace lipsync
