#pragma once
// Catmull-Rom (cubic convolution, a = -0.5; Keys, "Cubic convolution interpolation for digital
// image processing", IEEE TASSP 1981) interpolation of interleaved multi-channel images. Used
// where texture is resampled for display: each bilinear resampling of a face blurs it, and the
// mouth's fine structure (teeth, lip edges) is what a viewer looks at.
#include <algorithm>

namespace lipsync {

// Weights of the four samples around a point at fraction t in [0, 1) between the middle two.
inline void catmullRomWeights(float t, float w[4])
{
    const float t2 = t * t, t3 = t2 * t;
    w[0] = 0.5f * (-t3 + 2.f * t2 - t);
    w[1] = 0.5f * (3.f * t3 - 5.f * t2 + 2.f);
    w[2] = 0.5f * (-3.f * t3 + 4.f * t2 + t);
    w[3] = 0.5f * (t3 - t2);
}

// The value of `channels`-channel image `data` (width x height, rows `stride` elements apart)
// at (ix + fx, iy + fy), samples beyond the edge clamped to it, into out[channels].
template <int channels, class T>
inline void sampleCatmullRom(const T *data, int width, int height, int stride, int ix, int iy, float fx, float fy,
                             float *out)
{
    float wx[4], wy[4];
    catmullRomWeights(fx, wx);
    catmullRomWeights(fy, wy);
    for (int ch = 0; ch < channels; ++ch)
        out[ch] = 0.f;
    for (int j = 0; j < 4; ++j) {
        const T *row = data + std::clamp(iy - 1 + j, 0, height - 1) * stride;
        for (int i = 0; i < 4; ++i) {
            const T *p = row + channels * std::clamp(ix - 1 + i, 0, width - 1);
            const float w = wx[i] * wy[j];
            for (int ch = 0; ch < channels; ++ch)
                out[ch] += w * float(p[ch]);
        }
    }
}

} // namespace lipsync
