#include "io/AudioDecoder.h"

#include "io/LibAv.h"
#include "util/Error.h"

extern "C" {
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
}

#include <algorithm>

namespace lipsync {

namespace {

// Converts decoded frames of any layout, format and rate to mono float at the output rate,
// averaging the channels. Rebuilds itself if the input parameters change mid-stream.
class MonoResampler
{
public:
    MonoResampler(const std::string &path, int outRate) : m_path(path), m_outRate(outRate) {}
    ~MonoResampler() { av_channel_layout_uninit(&m_inLayout); }
    MonoResampler(const MonoResampler &) = delete;
    MonoResampler &operator=(const MonoResampler &) = delete;

    void push(const AVFrame *frame, std::vector<float> &out)
    {
        if (!m_swr || frame->format != m_inFormat || frame->sample_rate != m_inRate
            || av_channel_layout_compare(&frame->ch_layout, &m_inLayout) != 0) {
            flush(out);
            setup(frame);
        }
        convert(const_cast<const uint8_t **>(frame->extended_data), frame->nb_samples, out);
    }

    void flush(std::vector<float> &out)
    {
        if (m_swr)
            convert(nullptr, 0, out);
    }

    int outRate() const { return m_outRate; }

private:
    void setup(const AVFrame *frame)
    {
        av_channel_layout_uninit(&m_inLayout);
        if (frame->ch_layout.order == AV_CHANNEL_ORDER_UNSPEC || frame->ch_layout.nb_channels <= 0)
            av_channel_layout_default(&m_inLayout, std::max(1, frame->ch_layout.nb_channels));
        else
            av_channel_layout_copy(&m_inLayout, &frame->ch_layout);
        m_inFormat = frame->format;
        m_inRate = frame->sample_rate;
        if (m_outRate <= 0)
            m_outRate = m_inRate;
        if (m_inRate <= 0)
            throw Error("audio stream has no sample rate", m_path);

        SwrContext *raw = nullptr;
        AVChannelLayout mono = AV_CHANNEL_LAYOUT_MONO;
        int rc = swr_alloc_set_opts2(&raw, &mono, AV_SAMPLE_FMT_FLT, m_outRate, &m_inLayout,
                                     AVSampleFormat(m_inFormat), m_inRate, 0, nullptr);
        m_swr.reset(raw);
        if (rc >= 0) {
            // Mean of the channels rather than swresample's default downmix (which sums
            // stereo at -3 dB each and can leave [-1, 1]).
            const int channels = m_inLayout.nb_channels;
            std::vector<double> matrix(size_t(channels), 1.0 / channels);
            rc = swr_set_matrix(m_swr.get(), matrix.data(), channels);
        }
        if (rc >= 0)
            rc = swr_init(m_swr.get());
        if (rc < 0)
            throw Error("cannot set up audio resampling (" + libav::errorText(rc) + ")", m_path);
    }

    void convert(const uint8_t **in, int inSamples, std::vector<float> &out)
    {
        for (;;) {
            const int capacity = swr_get_out_samples(m_swr.get(), inSamples) + 32;
            const size_t offset = out.size();
            out.resize(offset + size_t(capacity));
            uint8_t *dst = reinterpret_cast<uint8_t *>(out.data() + offset);
            const int n = swr_convert(m_swr.get(), &dst, capacity, in, inSamples);
            if (n < 0) {
                out.resize(offset);
                throw Error("audio resampling failed (" + libav::errorText(n) + ")", m_path);
            }
            out.resize(offset + size_t(n));
            // With input, one call consumes it all (capacity covers it); when flushing, call
            // until the resampler is drained.
            if (in || n == 0)
                return;
        }
    }

    std::string m_path;
    int m_outRate;
    libav::SwrPtr m_swr;
    AVChannelLayout m_inLayout{};
    int m_inFormat = -1;
    int m_inRate = 0;
};

} // namespace

AudioBuffer AudioDecoder::decode(const std::string &path, int sampleRate)
{
    if (sampleRate < 0)
        throw Error("invalid sample rate " + std::to_string(sampleRate), path);
    // One shared pass rejects missing, empty, unsupported and truncated files consistently
    // with VideoReader and MediaInfo (cached per file).
    const auto scan = libav::scanMedia(path);
    if (scan->audioStream < 0)
        throw Error("no audio stream", path);

    libav::FormatPtr format = libav::openInput(path);
    AVFormatContext *fc = format.get();
    const int stream = libav::firstAudioStream(fc);
    if (stream < 0)
        throw Error("no audio stream", path);
    for (unsigned i = 0; i < fc->nb_streams; ++i)
        if (int(i) != stream)
            fc->streams[i]->discard = AVDISCARD_ALL; // demux the audio only
    libav::CodecPtr decoder = libav::openDecoder(path, fc, stream);

    AudioBuffer buffer;
    buffer.startTime = scan->audioStartTime;
    if (scan->audioSampleRate > 0 && scan->audioSamples > 0) {
        const int outRate = sampleRate > 0 ? sampleRate : scan->audioSampleRate;
        buffer.samples.reserve(size_t(double(scan->audioSamples) * outRate / scan->audioSampleRate)
                               + 64);
    }
    MonoResampler resampler(path, sampleRate);
    libav::PacketPtr packet(av_packet_alloc());
    libav::FramePtr frame(av_frame_alloc());
    auto receive = [&] {
        // Stops at EAGAIN/EOF, and at a decoding error: that packet is skipped.
        while (avcodec_receive_frame(decoder.get(), frame.get()) >= 0) {
            resampler.push(frame.get(), buffer.samples);
            av_frame_unref(frame.get());
        }
    };
    int rc;
    while ((rc = av_read_frame(fc, packet.get())) >= 0) {
        if (packet->stream_index == stream) {
            // A damaged packet is skipped (the decoder conceals it); truncation was checked above.
            avcodec_send_packet(decoder.get(), packet.get());
            receive();
        }
        av_packet_unref(packet.get());
    }
    if (rc != AVERROR_EOF)
        throw Error("read error (" + libav::errorText(rc) + ")", path);
    avcodec_send_packet(decoder.get(), nullptr);
    receive();
    resampler.flush(buffer.samples);

    if (buffer.samples.empty())
        throw Error("no decodable audio (corrupt file)", path);
    buffer.sampleRate = resampler.outRate();
    for (float &s : buffer.samples)
        s = std::clamp(s, -1.0f, 1.0f);
    return buffer;
}

} // namespace lipsync
