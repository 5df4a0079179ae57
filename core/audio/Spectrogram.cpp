#include "audio/Spectrogram.h"

#include "audio/FftwPlanner.h"
#include "util/Error.h"

#include <fftw3.h>

#include <cmath>

namespace lipsync {

Spectrogram Spectrogram::compute(const std::vector<float> &samples, int sampleRate, const SpectrogramOptions &options)
{
    if (sampleRate <= 0 || options.windowSeconds <= 0 || options.shiftSeconds <= 0)
        throw Error("spectrogram: the sample rate, window and shift must be positive");
    Spectrogram out;
    out.m_sampleRate = sampleRate;
    out.m_shift = options.shiftSeconds;
    out.m_window = options.windowSeconds;
    const int window = std::max(2, int(std::lround(options.windowSeconds * sampleRate)));
    const int shift = std::max(1, int(std::lround(options.shiftSeconds * sampleRate)));
    int fft = 1;
    while (fft < window)
        fft *= 2;
    out.m_fftSize = fft;
    const int bins = fft / 2 + 1;
    const int frames = samples.size() < size_t(window) ? 0 : int((samples.size() - size_t(window)) / size_t(shift)) + 1;
    out.m_db.resize(frames, bins);
    if (frames == 0)
        return out;

    std::vector<double> hann(static_cast<size_t>(window));
    for (int i = 0; i < window; ++i)
        hann[size_t(i)] = 0.5 - 0.5 * std::cos(2.0 * M_PI * i / (window - 1));
    double *in = fftw_alloc_real(size_t(fft));
    fftw_complex *spectrum = fftw_alloc_complex(size_t(bins));
    fftw_plan plan;
    {
        const std::lock_guard lock(fftwPlannerMutex());
        plan = fftw_plan_dft_r2c_1d(fft, in, spectrum, FFTW_ESTIMATE);
    }
    const double floor = std::pow(10.0, options.floorDb / 10.0);
    for (int f = 0; f < frames; ++f) {
        const float *s = samples.data() + size_t(f) * size_t(shift);
        for (int i = 0; i < window; ++i)
            in[i] = s[i] * hann[size_t(i)];
        std::fill(in + window, in + fft, 0.0);
        fftw_execute(plan);
        for (int b = 0; b < bins; ++b) {
            const double power = spectrum[b][0] * spectrum[b][0] + spectrum[b][1] * spectrum[b][1];
            out.m_db(f, b) = float(10.0 * std::log10(power + floor));
        }
    }
    {
        const std::lock_guard lock(fftwPlannerMutex());
        fftw_destroy_plan(plan);
    }
    fftw_free(in);
    fftw_free(spectrum);
    return out;
}

} // namespace lipsync
