#include "audio/WaveformPeaks.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync {

namespace {

Peak merged(const Peak &a, const Peak &b)
{
    return {std::min(a.min, b.min), std::max(a.max, b.max)};
}

} // namespace

WaveformPeaks::WaveformPeaks(std::vector<float> samples, int sampleRate, int baseBlockSize)
    : m_samples(std::move(samples)), m_sampleRate(sampleRate), m_baseBlock(std::max(1, baseBlockSize))
{
    if (m_samples.empty())
        return;
    const std::size_t n = m_samples.size();
    const std::size_t base = std::size_t(m_baseBlock);
    std::vector<Peak> level0((n + base - 1) / base);
    for (std::size_t b = 0; b < level0.size(); ++b) {
        const auto first = m_samples.begin() + std::ptrdiff_t(b * base);
        const auto last = m_samples.begin() + std::ptrdiff_t(std::min(n, (b + 1) * base));
        const auto [lo, hi] = std::minmax_element(first, last);
        level0[b] = {*lo, *hi};
    }
    m_levels.push_back(std::move(level0));
    // Stop once a level has a single entry: coarser levels would repeat it.
    while (m_levels.back().size() > 1) {
        const std::vector<Peak> &below = m_levels.back();
        std::vector<Peak> next((below.size() + 1) / 2);
        for (std::size_t i = 0; i < next.size(); ++i)
            next[i] = 2 * i + 1 < below.size() ? merged(below[2 * i], below[2 * i + 1]) : below[2 * i];
        m_levels.push_back(std::move(next));
    }
}

double WaveformPeaks::duration() const
{
    return m_sampleRate > 0 ? double(m_samples.size()) / m_sampleRate : 0.0;
}

Peak WaveformPeaks::peak(std::int64_t first, std::int64_t last) const
{
    first = std::max<std::int64_t>(first, 0);
    last = std::min<std::int64_t>(last, sampleCount());
    if (first >= last)
        return {};
    Peak result{std::numeric_limits<float>::max(), std::numeric_limits<float>::lowest()};
    std::int64_t pos = first;
    while (pos < last) {
        // The coarsest block that starts at pos and ends within the range.
        int chosen = -1;
        for (int l = levelCount() - 1; l >= 0; --l) {
            const std::int64_t size = blockSize(l);
            // The last block of a level may be short; it fits if the range reaches the end.
            if (pos % size == 0 && std::min(pos + size, sampleCount()) <= last) {
                chosen = l;
                break;
            }
        }
        if (chosen < 0) {
            const float v = m_samples[std::size_t(pos)];
            result = merged(result, {v, v});
            ++pos;
        } else {
            const std::int64_t size = blockSize(chosen);
            result = merged(result, m_levels[std::size_t(chosen)][std::size_t(pos / size)]);
            pos += size;
        }
    }
    return result;
}

Peak WaveformPeaks::peakInTime(double start, double end) const
{
    if (m_sampleRate <= 0)
        return {};
    return peak(std::int64_t(std::floor(start * m_sampleRate)), std::int64_t(std::ceil(end * m_sampleRate)));
}

} // namespace lipsync
