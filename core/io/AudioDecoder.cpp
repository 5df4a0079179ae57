#include "io/AudioDecoder.h"

#include "io/LibAv.h"
#include "util/Error.h"

extern "C" {
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
}

#include "io/AudioTimeline.h"

#include <algorithm>
#include <cmath>

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

    // Converts the frame's samples from `skip` on.
    void push(const AVFrame *frame, long long skip, std::vector<float> &out)
    {
        if (!m_swr || frame->format != m_inFormat || frame->sample_rate != m_inRate
            || av_channel_layout_compare(&frame->ch_layout, &m_inLayout) != 0) {
            flush(out);
            setup(frame);
        }
        skip = std::clamp<long long>(skip, 0, frame->nb_samples);
        const AVSampleFormat format = AVSampleFormat(frame->format);
        const int bytes = av_get_bytes_per_sample(format);
        const bool planar = av_sample_fmt_is_planar(format);
        const int channels = std::max(1, frame->ch_layout.nb_channels);
        std::vector<const uint8_t *> planes(size_t(planar ? channels : 1));
        for (size_t c = 0; c < planes.size(); ++c)
            planes[c] = frame->extended_data[c] + skip * bytes * (planar ? 1 : channels);
        convert(planes.data(), int(frame->nb_samples - skip), out);
    }

    // Drains what the resampler holds; the next push starts afresh (after a gap: the sound
    // before and after it are resampled as two pieces).
    void flush(std::vector<float> &out)
    {
        if (m_swr)
            convert(nullptr, 0, out);
        m_swr.reset();
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
    const int outRate = sampleRate > 0 ? sampleRate : scan->audioSampleRate;
    if (outRate > 0)
        buffer.samples.reserve(size_t(scan->audioEndTime * outRate) + 64);
    MonoResampler resampler(path, sampleRate);
    // Sample k sounds at k / rate on the timeline: frames are placed by their timestamps, the
    // sound before the stream starts and in its gaps is silence (AudioTimeline).
    AudioTimeline timeline(scan->containerDuration);
    const AVRational timeBase = fc->streams[stream]->time_base;
    const double fileStart = libav::fileStartSeconds(fc);
    libav::PacketPtr packet(av_packet_alloc());
    libav::FramePtr frame(av_frame_alloc());
    auto receive = [&] {
        // Stops at EAGAIN/EOF, and at a decoding error: that packet is skipped.
        while (avcodec_receive_frame(decoder.get(), frame.get()) >= 0) {
            const double pts = frame->best_effort_timestamp != AV_NOPTS_VALUE
                                   ? double(frame->best_effort_timestamp) * av_q2d(timeBase) - fileStart
                                   : NAN;
            const AudioTimeline::Placement p = timeline.place(pts, frame->nb_samples, frame->sample_rate);
            if (p.silenceBefore) {
                resampler.flush(buffer.samples);
                const int rate = resampler.outRate() > 0 ? resampler.outRate() : frame->sample_rate;
                const size_t at = size_t(std::max(0LL, std::llround(p.start * rate)));
                buffer.samples.resize(at, 0.0f); // silence up to the frame (or the flush's tail cut)
            }
            if (p.skip < frame->nb_samples)
                resampler.push(frame.get(), p.skip, buffer.samples);
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
