#pragma once
// Phone recognition as the sound comes in, without a transcript (docs/pipeline.md, "Live"): the
// aligner's monophone HMMs (AcousticModel) in a phone loop whose phone-to-phone transitions are
// weighted by a PhoneBigram, decoded by a fixed-lag Viterbi.
//
// Features are the model's own (MFCC_0_D_A, Mfcc), computed frame by frame as samples arrive:
// a 100 Hz frame's deltas and accelerations need the statics of the 4 frames after it, so a
// frame's features exist 4 frames (+ half a window) after its centre. The per-utterance cepstral
// mean normalisation the model was trained with becomes a running one: the mean of the statics
// over the last `meanSeconds`. At the start, when those are a few frames of (usually) silence, it
// leans on a prior: the first `silenceFrames` are taken to be silence, so the utterance mean is
// their mean less the silence model's own (normalised) mean; the prior counts as `priorFrames`
// frames, a weight that fades to nothing once `meanSeconds` of sound have come in.
//
// Fixed-lag Viterbi: after frame t the best partial path is traced back `lagFrames` frames and
// the phone it holds at frame t - lag is decided; a decision is never revised (the path found
// later may disagree with it; the lag trades latency for agreement with the full Viterbi path,
// which an infinite lag gives). Memory is the lag's back pointers and the mean's window, for
// any length of sound.
#include "align/AcousticModel.h"
#include "align/PhoneBigram.h"
#include "align/PhoneStream.h"
#include "annotation/Tier.h"

#include <Eigen/Core>

#include <deque>
#include <memory>
#include <vector>

namespace lipsync {

struct PhoneRecognizerOptions
{
    int lagFrames = 6;              // 100 Hz frames between a frame's features and its decision
    double languageWeight = 2.0;    // scale of the bigram's log-probabilities
    double phoneInsertion = -4.0;   // log weight of entering a phone (fewer, longer phones when negative)
    double meanSeconds = 3.0;       // window of the running cepstral mean
    int silenceFrames = 10;         // the first frames, taken as silence for the mean's prior
    double priorFrames = 100.0;     // the prior's weight at the start, in frames
};

class StreamingPhoneRecognizer : public PhoneStream
{
public:
    // Throws lipsync::Error for a model whose states are not the 41 phones x 3.
    StreamingPhoneRecognizer(const AcousticModel &model, const PhoneBigram &bigram,
                             const PhoneRecognizerOptions &options = {});
    ~StreamingPhoneRecognizer() override;

    // Feeds mono samples at the model's sample rate ([-1, 1]).
    void push(const float *samples, size_t count) override;
    // No more sound: every frame left is decided (traced back from the best final state).
    void finish() override;
    // The phones decided since the last call, one per 100 Hz audio frame, in order (PhoneSet
    // indices); frame j of the sound is the j-th label handed out overall.
    std::vector<int> takeDecided() override;
    int decidedFrames() const override { return m_decided; }
    // Appends decided phones to a phone tier: audio frame j (the first of them `firstFrame`) spans
    // its centre +- half a shift, runs of one phone are one interval, the tier starts at 0.
    static void appendToTier(Tier &tier, int firstFrame, const std::vector<int> &phones, const MfccOptions &frames);

    // Sound a decision waits for after its frame's centre: the lag and the features' look-ahead.
    double latencySeconds() const override;
    const MfccOptions &frameOptions() const override { return m_model.featureOptions(); }

    // The features of the frames so far, as the decoder saw them (for tests): with a fixed mean
    // set by useFixedMean they equal AcousticModel::features() of the whole sound with that mean.
    const std::vector<Eigen::VectorXf> &featureHistory() const { return m_history; }
    void keepFeatureHistory(bool on) { m_keepHistory = on; }
    void useFixedMean(const Eigen::VectorXf &mean) { m_fixedMean = mean; }

private:
    void addStaticFrame(const Eigen::VectorXf &statics);
    void featuresOf(long frame, bool atEnd);
    void decode(const Eigen::VectorXf &features);
    void decide(bool all);

    const AcousticModel &m_model;
    PhoneBigram m_bigram;
    PhoneRecognizerOptions m_options;
    std::unique_ptr<Mfcc> m_mfcc;
    int m_window = 0, m_shift = 0;

    std::vector<float> m_samples; // not yet consumed by a frame
    long m_staticFrames = 0;      // statics computed so far
    std::deque<Eigen::VectorXf> m_statics; // the last ones (for deltas and the running mean)
    long m_staticsFirst = 0;      // frame index of m_statics.front()
    long m_featureFrames = 0;     // frames whose features have been decoded

    Eigen::VectorXd m_delta;      // Viterbi scores of the 123 states, best = 0
    std::deque<std::vector<short>> m_back; // back pointers of the undecided frames
    Eigen::MatrixXd m_enter;      // log weight of phone p's last state -> phone q's first
    std::vector<double> m_logSelf, m_logNext;
    int m_decided = 0;
    std::vector<int> m_ready;

    bool m_keepHistory = false;
    std::vector<Eigen::VectorXf> m_history;
    Eigen::VectorXf m_fixedMean;
    Eigen::VectorXd m_silenceMean;  // the silence phone's statics mean, normalised
    Eigen::VectorXd m_startSum;     // statics of the first silenceFrames
    int m_startFrames = 0;
};

} // namespace lipsync
