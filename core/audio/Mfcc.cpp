#include "audio/Mfcc.h"

#include "audio/FftwPlanner.h"
#include "util/Error.h"

#include <fftw3.h>

#include <algorithm>
#include <cmath>
#include <mutex>

namespace lipsync {

namespace {
double mel(double hz)
{
    return 1127.0 * std::log(1.0 + hz / 700.0);
}
} // namespace

Mfcc::Mfcc(const MfccOptions &options) : m_options(options)
{
    const MfccOptions &o = m_options;
    if (o.sampleRate < 4000 || o.sampleRate > 192000)
        throw Error("MFCC: unsupported sample rate " + std::to_string(o.sampleRate));
    if (o.melChannels < 2 || o.cepstra < 1 || o.cepstra >= o.melChannels)
        throw Error("MFCC: need 2 or more mel channels and fewer cepstra than channels");
    // Bounded before the conversions below (options come from aligner model files too).
    if (!(o.windowSeconds > 0 && o.windowSeconds <= 1.0 && o.shiftSeconds > 0 && o.shiftSeconds <= 1.0))
        throw Error("MFCC: window and shift must be between 0 and 1 s");
    if (o.melChannels > 1024)
        throw Error("MFCC: more than 1024 mel channels");
    m_window = int(std::lround(o.windowSeconds * o.sampleRate));
    m_shift = int(std::lround(o.shiftSeconds * o.sampleRate));
    if (m_window < 2 || m_shift < 1)
        throw Error("MFCC: window or shift too short");
    m_fftSize = 2;
    while (m_fftSize < m_window)
        m_fftSize *= 2;

    m_hamming.resize(size_t(m_window));
    for (int i = 0; i < m_window; ++i)
        m_hamming[size_t(i)] = float(0.54 - 0.46 * std::cos(2.0 * M_PI * i / (m_window - 1)));

    // HTK InitFBank: channel centres equally spaced in mel, bins 1..N/2-1 (0-based) each split
    // between the two channels around it.
    const int channels = o.melChannels;
    const int bins = m_fftSize / 2 + 1;
    const double nyquist = o.sampleRate / 2.0;
    const double lo = o.lowFrequency;
    const double hi = o.highFrequency > 0 ? std::min(o.highFrequency, nyquist) : nyquist;
    const double mlo = mel(lo), mhi = mel(hi);
    std::vector<double> centre(static_cast<size_t>(channels) + 2);
    for (int c = 0; c <= channels + 1; ++c)
        centre[size_t(c)] = mlo + (mhi - mlo) * c / (channels + 1);
    m_filters = Eigen::MatrixXf::Zero(channels, bins);
    const double binHz = double(o.sampleRate) / m_fftSize;
    for (int k = 1; k < m_fftSize / 2; ++k) {
        const double hz = k * binHz;
        if (hz < lo || hz > hi)
            continue;
        const double m = mel(hz);
        // Channel index (1-based, HTK's loChan) of the centre just below m.
        int chan = 0;
        while (chan <= channels && centre[size_t(chan) + 1] < m)
            ++chan;
        const double loWeight = (centre[size_t(chan) + 1] - m) / (centre[size_t(chan) + 1] - centre[size_t(chan)]);
        if (chan > 0)
            m_filters(chan - 1, k) += float(loWeight);
        if (chan < channels)
            m_filters(chan, k) += float(1.0 - loWeight);
    }

    // DCT rows c1..cN then c0 (HTK's MFCC_0 order), with the lifter on c1..cN.
    const int n = o.cepstra;
    m_dct.resize(n + 1, channels);
    const double norm = std::sqrt(2.0 / channels);
    for (int i = 1; i <= n; ++i) {
        const double lifter = o.lifter > 0 ? 1.0 + o.lifter / 2.0 * std::sin(M_PI * i / o.lifter) : 1.0;
        for (int j = 0; j < channels; ++j)
            m_dct(i - 1, j) = float(lifter * norm * std::cos(M_PI * i / channels * (j + 0.5)));
    }
    for (int j = 0; j < channels; ++j)
        m_dct(n, j) = float(norm);

    std::lock_guard lock(fftwPlannerMutex());
    double *in = fftw_alloc_real(size_t(m_fftSize));
    fftw_complex *out = fftw_alloc_complex(size_t(bins));
    m_plan = fftw_plan_dft_r2c_1d(m_fftSize, in, out, FFTW_ESTIMATE);
    fftw_free(in);
    fftw_free(out);
    if (!m_plan)
        throw Error("MFCC: FFTW could not plan a transform of size " + std::to_string(m_fftSize));
}

Mfcc::~Mfcc()
{
    std::lock_guard lock(fftwPlannerMutex());
    fftw_destroy_plan(static_cast<fftw_plan>(m_plan));
}

int Mfcc::dimension() const
{
    int d = staticDimension();
    if (m_options.deltas)
        d += staticDimension();
    if (m_options.deltas && m_options.accelerations)
        d += staticDimension();
    return d;
}

int Mfcc::frameCount(size_t samples) const
{
    if (samples < size_t(m_window))
        return 0;
    return int((samples - size_t(m_window)) / size_t(m_shift)) + 1;
}

Eigen::MatrixXf Mfcc::computeStatic(const std::vector<float> &samples) const
{
    const int frames = frameCount(samples.size());
    const int bins = m_fftSize / 2 + 1;
    Eigen::MatrixXf out(frames, staticDimension());
    double *in = fftw_alloc_real(size_t(m_fftSize));
    fftw_complex *spectrum = fftw_alloc_complex(size_t(bins));
    Eigen::VectorXf magnitude(bins);
    Eigen::VectorXf fbank(m_options.melChannels);
    const double k = m_options.preemphasis;
    const double scale = m_options.sampleScale;
    for (int f = 0; f < frames; ++f) {
        const float *s = samples.data() + size_t(f) * size_t(m_shift);
        // Pre-emphasis inside the frame (HTK PreEmphasise), then Hamming.
        in[0] = s[0] * scale * (1.0 - k) * m_hamming[0];
        for (int i = 1; i < m_window; ++i)
            in[i] = (s[i] - k * s[i - 1]) * scale * m_hamming[size_t(i)];
        std::fill(in + m_window, in + m_fftSize, 0.0);
        fftw_execute_dft_r2c(static_cast<fftw_plan>(m_plan), in, spectrum);
        for (int b = 0; b < bins; ++b)
            magnitude[b] = float(std::sqrt(spectrum[b][0] * spectrum[b][0] + spectrum[b][1] * spectrum[b][1]));
        fbank.noalias() = m_filters * magnitude;
        for (int c = 0; c < fbank.size(); ++c)
            fbank[c] = std::log(std::max(fbank[c], 1.0f));
        out.row(f).noalias() = (m_dct * fbank).transpose();
    }
    fftw_free(in);
    fftw_free(spectrum);
    return out;
}

Eigen::MatrixXf Mfcc::regressionDeltas(const Eigen::MatrixXf &features, int window)
{
    const int frames = int(features.rows());
    const int dim = int(features.cols());
    Eigen::MatrixXf out(frames, dim * 2);
    out.leftCols(dim) = features;
    double denominator = 0;
    for (int k = 1; k <= window; ++k)
        denominator += 2.0 * k * k;
    for (int t = 0; t < frames; ++t) {
        Eigen::VectorXf d = Eigen::VectorXf::Zero(dim);
        for (int k = 1; k <= window; ++k) {
            const int ahead = std::min(t + k, frames - 1);
            const int behind = std::max(t - k, 0);
            d += float(k) * (features.row(ahead) - features.row(behind)).transpose();
        }
        out.row(t).tail(dim) = (d / float(denominator)).transpose();
    }
    return out;
}

Eigen::MatrixXf Mfcc::compute(const std::vector<float> &samples) const
{
    Eigen::MatrixXf statics = computeStatic(samples);
    if (!m_options.deltas || statics.rows() == 0) {
        if (statics.rows() == 0)
            return Eigen::MatrixXf(0, dimension());
        return statics;
    }
    const int d = staticDimension();
    Eigen::MatrixXf withDeltas = regressionDeltas(statics, m_options.deltaWindow);
    if (!m_options.accelerations)
        return withDeltas;
    Eigen::MatrixXf acc = regressionDeltas(withDeltas.rightCols(d), m_options.deltaWindow);
    Eigen::MatrixXf out(statics.rows(), 3 * d);
    out << withDeltas, acc.rightCols(d);
    return out;
}

} // namespace lipsync
