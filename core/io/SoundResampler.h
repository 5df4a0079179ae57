#pragma once
// Sound that arrives in blocks (a microphone's: interleaved float, any channel count and rate) to
// mono float at one rate, by libswresample, its filter state carried from block to block so the
// blocks join without a seam. The channels are averaged, as AudioDecoder mixes files down.
#include <memory>
#include <vector>

namespace lipsync {

class SoundResampler
{
public:
    // Throws lipsync::Error for rates or a channel count <= 0, or when libswresample refuses.
    SoundResampler(int inputRate, int channels, int outputRate);
    ~SoundResampler();
    SoundResampler(const SoundResampler &) = delete;
    SoundResampler &operator=(const SoundResampler &) = delete;

    // `frames` frames of `channels` interleaved samples; returns the output the resampler has
    // ready (its filter holds a few samples back until the next block or flush()).
    std::vector<float> push(const float *interleaved, size_t frames);
    // The samples held back, at the end of the sound.
    std::vector<float> flush();

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

} // namespace lipsync
