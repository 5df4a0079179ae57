#pragma once
// Monophone acoustic model of the aligner: for each of the 41 phones (PhoneSet) a left-to-right
// HMM with 3 emitting states, each emitting through a diagonal-covariance Gaussian mixture over
// MFCC_0_D_A features (39 dimensions), the HTK "proto" topology: state k goes to itself with
// probability a_k or on to k+1 (the third state leaves the phone).
//
// Saved as a versioned text file ("lipsync-aligner 1"), which also records the feature
// configuration so alignment computes exactly the features the model was trained on; version 2
// adds the word-boundary correction learned against reference timings (BoundaryCorrection). A
// file is written with the lowest version that holds its content.
#include "align/BoundaryCorrection.h"
#include "audio/Mfcc.h"

#include <Eigen/Core>

#include <memory>
#include <string>
#include <vector>

namespace lipsync {

struct AudioBuffer;

// Row-major so that one component's D values are contiguous for the Gaussian loops.
using RowMatrixXf = Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
using RowMatrixXd = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// One emitting state: M weighted diagonal Gaussians.
struct GaussianMixture
{
    Eigen::VectorXf weights; // M, sum 1
    RowMatrixXf means;       // M x D
    RowMatrixXf variances;   // M x D

    int size() const { return int(weights.size()); }
    // Caches precisions and log constants; call after changing the parameters.
    void prepare();
    // log sum_m w_m N(x; mean_m, diag var_m).
    float logLikelihood(const float *x) const;
    // Per-component log(w_m N(x; ...)) into `out` (size M); returns their log-sum.
    float componentLogLikelihoods(const float *x, float *out) const;

    RowMatrixXf precisions; // 1 / variances
    Eigen::VectorXf logConstants; // log w_m - (D log 2 pi + sum log var_m) / 2
};

// Per-utterance feature normalisation (stored in the model file, since a model only fits the
// features it was trained on): none; cepstral mean normalisation of the static coefficients
// (HTK's TARGETKIND _Z); or mean and variance normalisation (CMVN: the static coefficients'
// mean removed, then every coefficient divided by its standard deviation over the utterance,
// HTK's HCompV -c/-k variance scaling per utterance), which evens out speakers and channels.
enum class CepstralNormalization { None = 0, Mean = 1, MeanAndVariance = 2 };

class AcousticModel
{
public:
    static constexpr int kFormatVersion = 2;
    static constexpr int kStatesPerPhone = 3;

    AcousticModel() = default;
    // A flat-start model (HCompV): every state one Gaussian with the global mean and variance.
    AcousticModel(const MfccOptions &features, CepstralNormalization normalization, const Eigen::VectorXf &mean,
                  const Eigen::VectorXf &variance, double selfLoop = 0.6);

    const MfccOptions &featureOptions() const { return m_features; }
    CepstralNormalization normalization() const { return m_normalization; }
    int dimension() const { return m_dimension; }
    int stateCount() const { return int(m_states.size()); }
    static int stateIndex(int phone, int position) { return phone * kStatesPerPhone + position; }

    GaussianMixture &state(int index) { return m_states[size_t(index)]; }
    const GaussianMixture &state(int index) const { return m_states[size_t(index)]; }
    // Probability that state `index` stays in itself for one more frame.
    double selfLoop(int index) const { return m_selfLoop[size_t(index)]; }
    void setSelfLoop(int index, double p) { m_selfLoop[size_t(index)] = p; }
    // Offsets subtracted from the word boundaries the model's Viterbi alignment places (empty
    // unless learned: `lipsync aligner calibrate`).
    const BoundaryCorrection &boundaryCorrection() const { return m_boundaries; }
    void setBoundaryCorrection(const BoundaryCorrection &c) { m_boundaries = c; }
    // Variance floor applied by re-estimation (HCompV -f 0.01: 1% of the global variance).
    const Eigen::VectorXf &varianceFloor() const { return m_varianceFloor; }
    void setVarianceFloor(const Eigen::VectorXf &floor) { m_varianceFloor = floor; }
    void prepare();

    // Features of an utterance as this model expects them: MFCC_0_D_A at the model's sample
    // rate, normalised per utterance as normalization() says. `audio` must be at featureOptions().sampleRate.
    Eigen::MatrixXf features(const AudioBuffer &audio) const;
    Eigen::MatrixXf features(const std::vector<float> &samples) const;

    // Throws lipsync::Error naming the file (and line for malformed content).
    void save(const std::string &path) const;
    // What save() writes: every number exactly (floats to 9 digits, self-loops to 17).
    std::string text() const;
    static AcousticModel load(const std::string &path);
    // The same from the file's text; `pathForErrors` only names the source in errors.
    static AcousticModel parse(const std::string &text, const std::string &pathForErrors = {});

private:
    MfccOptions m_features;
    CepstralNormalization m_normalization = CepstralNormalization::Mean;
    int m_dimension = 0;
    std::vector<GaussianMixture> m_states;
    std::vector<double> m_selfLoop;
    Eigen::VectorXf m_varianceFloor;
    BoundaryCorrection m_boundaries;
    std::shared_ptr<const Mfcc> m_mfcc; // shared by copies; compute() is thread-safe
};

} // namespace lipsync
