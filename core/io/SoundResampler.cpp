#include "io/SoundResampler.h"

#include "io/LibAv.h"
#include "util/Error.h"

extern "C" {
#include <libavutil/channel_layout.h>
}

namespace lipsync {

struct SoundResampler::Impl
{
    libav::SwrPtr swr;
    int channels = 1;

    std::vector<float> convert(const float *in, int frames)
    {
        std::vector<float> out(size_t(swr_get_out_samples(swr.get(), frames) + 32));
        uint8_t *dst = reinterpret_cast<uint8_t *>(out.data());
        const uint8_t *src = reinterpret_cast<const uint8_t *>(in);
        const int n = swr_convert(swr.get(), &dst, int(out.size()), in ? &src : nullptr, frames);
        if (n < 0)
            throw Error("sound resampling failed (" + libav::errorText(n) + ")");
        out.resize(size_t(n));
        return out;
    }
};

SoundResampler::SoundResampler(int inputRate, int channels, int outputRate) : d(std::make_unique<Impl>())
{
    if (inputRate <= 0 || outputRate <= 0 || channels <= 0)
        throw Error("sound resampling needs positive rates and channel count");
    d->channels = channels;
    AVChannelLayout in{}, mono = AV_CHANNEL_LAYOUT_MONO;
    av_channel_layout_default(&in, channels);
    SwrContext *raw = nullptr;
    int rc = swr_alloc_set_opts2(&raw, &mono, AV_SAMPLE_FMT_FLT, outputRate, &in, AV_SAMPLE_FMT_FLT, inputRate, 0,
                                 nullptr);
    d->swr.reset(raw);
    if (rc >= 0) {
        std::vector<double> matrix(size_t(channels), 1.0 / channels); // the mean of the channels
        rc = swr_set_matrix(d->swr.get(), matrix.data(), channels);
    }
    if (rc >= 0)
        rc = swr_init(d->swr.get());
    av_channel_layout_uninit(&in);
    if (rc < 0)
        throw Error("cannot set up sound resampling (" + libav::errorText(rc) + ")");
}

SoundResampler::~SoundResampler() = default;

std::vector<float> SoundResampler::push(const float *interleaved, size_t frames)
{
    return frames == 0 ? std::vector<float>() : d->convert(interleaved, int(frames));
}

std::vector<float> SoundResampler::flush()
{
    std::vector<float> out;
    for (;;) {
        const std::vector<float> more = d->convert(nullptr, 0);
        if (more.empty())
            return out;
        out.insert(out.end(), more.begin(), more.end());
    }
}

} // namespace lipsync
