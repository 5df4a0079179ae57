#include "aam/TextureNormalisation.h"

#include <cmath>

namespace lipsync {

namespace {

template<typename T>
PhotometricTransform normaliseImpl(T *values, size_t count)
{
    PhotometricTransform t;
    if (count == 0)
        return t;
    double sum = 0.0, sq = 0.0;
    for (size_t i = 0; i < count; ++i) {
        sum += values[i];
        sq += double(values[i]) * values[i];
    }
    t.offset = sum / double(count);
    const double var = std::max(0.0, sq / double(count) - t.offset * t.offset);
    t.scale = var > 1e-12 ? std::sqrt(var) : 1.0;
    const double inv = 1.0 / t.scale;
    for (size_t i = 0; i < count; ++i)
        values[i] = T((values[i] - t.offset) * inv);
    return t;
}

} // namespace

PhotometricTransform normaliseTexture(float *values, size_t count)
{
    return normaliseImpl(values, count);
}

PhotometricTransform normaliseTexture(double *values, size_t count)
{
    return normaliseImpl(values, count);
}

} // namespace lipsync
