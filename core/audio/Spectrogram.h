#pragma once
// A short-time power spectrum for display (the timeline's spectrogram lane): frame j covers
// samples [j * shift, j * shift + window) like the MFCC front end (25 ms, 10 ms hop), Hann
// window, FFT of the next power of two (FFTW), power in dB: 10 log10(|X_k|^2 + floor) with
// samples in [-1, 1]. Rows are frames, columns the bins 0..N/2 (bin k is k * rate / N Hz).
#include <Eigen/Core>

#include <vector>

namespace lipsync {

struct SpectrogramOptions
{
    double windowSeconds = 0.025;
    double shiftSeconds = 0.010;
    double floorDb = -120.0; // power floor, so silence stays finite
};

class Spectrogram
{
public:
    Spectrogram() = default;
    // Throws lipsync::Error for a non-positive rate or window.
    static Spectrogram compute(const std::vector<float> &samples, int sampleRate, const SpectrogramOptions &options = {});

    bool isEmpty() const { return m_db.rows() == 0; }
    int frameCount() const { return int(m_db.rows()); }
    int binCount() const { return int(m_db.cols()); }
    int sampleRate() const { return m_sampleRate; }
    double shiftSeconds() const { return m_shift; }
    double windowSeconds() const { return m_window; }
    // Centre of frame j in seconds.
    double frameCentre(int frame) const { return frame * m_shift + m_window / 2.0; }
    double binFrequency(int bin) const { return m_fftSize > 0 ? double(bin) * m_sampleRate / m_fftSize : 0.0; }
    // frames x bins, dB.
    const Eigen::MatrixXf &powerDb() const { return m_db; }
    float maxDb() const { return isEmpty() ? 0.0f : m_db.maxCoeff(); }

private:
    Eigen::MatrixXf m_db;
    int m_sampleRate = 0;
    int m_fftSize = 0;
    double m_shift = 0.01;
    double m_window = 0.025;
};

} // namespace lipsync
