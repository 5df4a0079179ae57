#pragma once
// HTK-compatible mel-frequency cepstral coefficients (the paper's 13-dimensional MFCCs at 100 Hz,
// extended with deltas and accelerations for the aligner's HMMs).
//
// The defaults reproduce HTK's HCopy with TARGETKIND = MFCC_0_D_A, WINDOWSIZE = 250000.0,
// TARGETRATE = 100000.0, USEHAMMING = T, PREEMCOEF = 0.97, NUMCHANS = 26, NUMCEPS = 12,
// CEPLIFTER = 22, ENORMALISE = F, USEPOWER = F, DELTAWINDOW = ACCWINDOW = 2:
//   frame j covers samples [j*shift, j*shift + window); pre-emphasis inside the frame
//   (s'[0] = s[0](1-k), s'[i] = s[i] - k s[i-1]); Hamming window 0.54 - 0.46 cos(2 pi i/(N-1));
//   FFT of the next power of two; magnitude spectrum; 26 triangular filters equally spaced on
//   mel(f) = 1127 ln(1 + f/700) between 0 Hz and Nyquist, on FFT bins 1..N/2; log with a floor of
//   1.0 (HTK's sample scale, 16-bit integers: input in [-1, 1] is scaled by 32768); DCT-II
//   c_i = sqrt(2/M) sum_j log m_j cos(pi i (j - 1/2) / M) for i = 0..12; lifter
//   c_i *= 1 + L/2 sin(pi i / L) for i >= 1 (C0 is not liftered, as in HTK).
//   Deltas (HTK's regression formula, edges replicated):
//   d_t = sum_{k=1..K} k (c_{t+k} - c_{t-k}) / (2 sum_{k=1..K} k^2); accelerations: the same on d.
// Output row layout: c1..c12, c0, then their deltas, then accelerations (HTK order).
#include <Eigen/Core>

#include <vector>

namespace lipsync {

struct MfccOptions
{
    int sampleRate = 16000;
    double windowSeconds = 0.025;
    double shiftSeconds = 0.010;
    double preemphasis = 0.97;
    int melChannels = 26;
    int cepstra = 12;        // c1..c12; c0 is appended
    int lifter = 22;         // 0 disables liftering
    double lowFrequency = 0.0;
    double highFrequency = 0.0; // 0 = Nyquist
    bool deltas = true;
    bool accelerations = true;
    int deltaWindow = 2;
    double sampleScale = 32768.0; // HTK works on 16-bit sample values

    bool operator==(const MfccOptions &) const = default;
};

class Mfcc
{
public:
    explicit Mfcc(const MfccOptions &options = {});
    ~Mfcc();
    Mfcc(const Mfcc &) = delete;
    Mfcc &operator=(const Mfcc &) = delete;

    const MfccOptions &options() const { return m_options; }
    int windowSamples() const { return m_window; }
    int shiftSamples() const { return m_shift; }
    int fftSize() const { return m_fftSize; }
    // c1..c12 + c0 (13 by default).
    int staticDimension() const { return m_options.cepstra + 1; }
    int dimension() const;
    // HTK's frame count: floor((samples - window) / shift) + 1, or 0 when shorter than a window.
    int frameCount(size_t samples) const;

    // One row per frame, `dimension()` columns. Samples in [-1, 1] at options().sampleRate.
    // Thread-safe (each call has its own FFT buffers).
    Eigen::MatrixXf compute(const std::vector<float> &samples) const;
    // Statics only (no deltas), `staticDimension()` columns.
    Eigen::MatrixXf computeStatic(const std::vector<float> &samples) const;

    // Appends HTK regression deltas of `features` (window K) as new columns.
    static Eigen::MatrixXf regressionDeltas(const Eigen::MatrixXf &features, int window);

    // Filter bank weights: melChannels rows x (fftSize/2 + 1) columns (for tests and plots).
    const Eigen::MatrixXf &filterBank() const { return m_filters; }

private:
    MfccOptions m_options;
    int m_window = 0;
    int m_shift = 0;
    int m_fftSize = 0;
    std::vector<float> m_hamming;
    Eigen::MatrixXf m_filters;   // channels x bins
    Eigen::MatrixXf m_dct;       // (cepstra + 1) x channels, rows c1..c12, c0, liftered
    void *m_plan = nullptr;      // fftwf_plan (executed with new-array execute, thread-safe)
};

// Seconds of the centre of 100 Hz frame j (docs/models.md §0): j * shift + window / 2.
inline double mfccFrameCentre(int j, const MfccOptions &o = {})
{
    return j * o.shiftSeconds + o.windowSeconds / 2.0;
}

} // namespace lipsync
