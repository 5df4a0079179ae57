#pragma once
// Photometric normalisation of sampled textures (Cootes et al. 2001, §4: g = (g_im - beta 1) /
// alpha), so that the texture model is independent of global lighting and camera gain.
#include <cstddef>

namespace lipsync {

struct PhotometricTransform
{
    double offset = 0.0; // beta: mean over all values
    double scale = 1.0;  // alpha: standard deviation over all values
};

// Normalises `values` in place to zero mean and unit standard deviation; returns the transform
// (values_original = normalised * scale + offset). A flat texture keeps scale 1.
PhotometricTransform normaliseTexture(float *values, size_t count);
PhotometricTransform normaliseTexture(double *values, size_t count);

} // namespace lipsync
