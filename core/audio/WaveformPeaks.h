#pragma once
// A min/max peak pyramid over mono PCM, so a waveform view can draw any zoom level in time
// proportional to its width rather than to the number of samples it covers (the idea of
// Aegisub's per-zoom cached waveform blocks, kept here as plain data).
//
// Level 0 holds the min/max of each block of baseBlockSize() samples; every further level halves
// the number of blocks (each entry covers two entries of the level below). peak() combines the
// coarsest blocks that fit a range with the raw samples at its ragged ends, so its answer is
// exactly the min/max of the samples — never an approximation.
#include <cstdint>
#include <vector>

namespace lipsync {

struct Peak
{
    float min = 0.0f;
    float max = 0.0f;
    bool operator==(const Peak &) const = default;
};

class WaveformPeaks
{
public:
    WaveformPeaks() = default;
    // `baseBlockSize` samples per level-0 block (at least 1).
    WaveformPeaks(std::vector<float> samples, int sampleRate, int baseBlockSize = 16);

    bool isEmpty() const { return m_samples.empty(); }
    int sampleRate() const { return m_sampleRate; }
    std::int64_t sampleCount() const { return std::int64_t(m_samples.size()); }
    double duration() const;
    const std::vector<float> &samples() const { return m_samples; }

    int baseBlockSize() const { return m_baseBlock; }
    int levelCount() const { return int(m_levels.size()); }
    // Samples covered by one entry of `level` (baseBlockSize() << level).
    std::int64_t blockSize(int level) const { return std::int64_t(m_baseBlock) << level; }
    // Entry i of a level covers samples [i * blockSize(level), (i + 1) * blockSize(level)),
    // the last entry possibly fewer.
    const std::vector<Peak> &level(int level) const { return m_levels[std::size_t(level)]; }

    // Min and max of samples [first, last), clamped to the signal; {0, 0} for an empty range.
    Peak peak(std::int64_t first, std::int64_t last) const;
    // The same for a time range in seconds.
    Peak peakInTime(double start, double end) const;

private:
    std::vector<float> m_samples;
    int m_sampleRate = 0;
    int m_baseBlock = 16;
    std::vector<std::vector<Peak>> m_levels;
};

} // namespace lipsync
