#include "io/WavWriter.h"

#include "io/AtomicFile.h"
#include "io/LibAv.h"
#include "util/Error.h"

extern "C" {
#include <libavutil/channel_layout.h>
}

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace lipsync {

namespace {

struct OutputFreer
{
    void operator()(AVFormatContext *c) const
    {
        if (c->pb) {
            uint8_t *buffer = nullptr;
            avio_close_dyn_buf(c->pb, &buffer);
            av_free(buffer);
        }
        avformat_free_context(c);
    }
};

} // namespace

void writeWav(const std::string &path, const std::vector<float> &samples, size_t begin, size_t end, int sampleRate)
{
    end = std::min(end, samples.size());
    begin = std::min(begin, end);
    if (sampleRate <= 0)
        throw Error("invalid sample rate " + std::to_string(sampleRate), path);
    auto check = [&](int rc, const char *what) {
        if (rc < 0)
            throw Error(std::string("cannot write WAV audio (") + what + ": " + libav::errorText(rc) + ")", path);
    };
    AVFormatContext *raw = nullptr;
    check(avformat_alloc_output_context2(&raw, nullptr, "wav", nullptr), "muxer");
    std::unique_ptr<AVFormatContext, OutputFreer> format(raw);
    AVStream *stream = avformat_new_stream(format.get(), nullptr);
    if (!stream)
        throw Error("cannot write WAV audio (no stream)", path);
    AVCodecParameters *par = stream->codecpar;
    par->codec_type = AVMEDIA_TYPE_AUDIO;
    par->codec_id = AV_CODEC_ID_PCM_S16LE;
    par->format = AV_SAMPLE_FMT_S16;
    par->sample_rate = sampleRate;
    par->bits_per_coded_sample = 16;
    par->block_align = 2;
    par->bit_rate = int64_t(sampleRate) * 16;
    av_channel_layout_default(&par->ch_layout, 1);
    stream->time_base = AVRational{1, sampleRate};
    check(avio_open_dyn_buf(&format->pb), "buffer");
    check(avformat_write_header(format.get(), nullptr), "header");

    constexpr size_t kBlock = 4096;
    libav::PacketPtr packet(av_packet_alloc());
    for (size_t at = begin; at < end; at += kBlock) {
        const size_t n = std::min(kBlock, end - at);
        check(av_new_packet(packet.get(), int(2 * n)), "packet");
        auto *pcm = reinterpret_cast<int16_t *>(packet->data);
        for (size_t i = 0; i < n; ++i)
            pcm[i] = int16_t(std::lround(std::clamp(samples[at + i], -1.0f, 1.0f) * 32767.0f));
        packet->stream_index = stream->index;
        packet->pts = packet->dts = int64_t(at - begin);
        packet->duration = int64_t(n);
        check(av_write_frame(format.get(), packet.get()), "samples");
        av_packet_unref(packet.get());
    }
    check(av_write_trailer(format.get()), "trailer");
    uint8_t *buffer = nullptr;
    const int size = avio_close_dyn_buf(format->pb, &buffer);
    format->pb = nullptr;
    const std::string bytes(reinterpret_cast<const char *>(buffer), size_t(std::max(0, size)));
    av_free(buffer);
    writeFileAtomically(path, bytes);
}

} // namespace lipsync
