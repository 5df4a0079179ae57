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
#include <functional>

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

namespace {

// The decoded sound as it comes: `samples` holds the samples from absolute index `first` on (the
// consumer may drop a front it is done with).
struct SampleWindow
{
    std::vector<float> samples;
    long long first = 0;
    long long end() const { return first + (long long)samples.size(); }
};

// Decodes the first audio stream of `path` to mono float at `sampleRate` (0: the stream's own) on
// the media timeline (AudioDecoder::decode), calling `consume(window)` after every decoded packet
// and once at the end (`done`). `whole`: the window will keep everything (room is made for the
// whole sound up front). Returns the output rate.
int decodeStream(const std::string &path, int sampleRate, bool whole,
                 const std::function<void(SampleWindow &, bool done)> &consume)
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

    SampleWindow window;
    const int outRate = sampleRate > 0 ? sampleRate : scan->audioSampleRate;
    if (whole && outRate > 0)
        window.samples.reserve(size_t(scan->audioEndTime * outRate) + 64);
    MonoResampler resampler(path, outRate);
    // Sample k sounds at k / rate on the timeline: frames are placed by their timestamps, the
    // sound before the stream starts and in its gaps is silence (AudioTimeline).
    AudioTimeline timeline(scan->containerDuration);
    const AVRational timeBase = fc->streams[stream]->time_base;
    const double fileStart = libav::fileStartSeconds(fc);
    libav::PacketPtr packet(av_packet_alloc());
    libav::FramePtr frame(av_frame_alloc());
    // Where the resampler's output goes: appended to the window.
    std::vector<float> converted;
    auto append = [&] {
        window.samples.insert(window.samples.end(), converted.begin(), converted.end());
        converted.clear();
    };
    auto receive = [&] {
        // Stops at EAGAIN/EOF, and at a decoding error: that packet is skipped.
        while (avcodec_receive_frame(decoder.get(), frame.get()) >= 0) {
            const double pts = libav::frameSeconds(frame.get(), timeBase, fileStart);
            const AudioTimeline::Placement p = timeline.place(pts, frame->nb_samples, frame->sample_rate);
            if (p.silenceBefore) {
                resampler.flush(converted);
                append();
                const int rate = resampler.outRate() > 0 ? resampler.outRate() : frame->sample_rate;
                const long long at = std::max(0LL, std::llround(p.start * rate));
                // Silence up to the frame (or the flush's tail cut).
                window.samples.resize(size_t(std::max(0LL, at - window.first)), 0.0f);
            }
            if (p.skip < frame->nb_samples) {
                resampler.push(frame.get(), p.skip, converted);
                append();
            }
            av_frame_unref(frame.get());
        }
    };
    int rc;
    while ((rc = av_read_frame(fc, packet.get())) >= 0) {
        if (packet->stream_index == stream) {
            // A damaged packet is skipped (the decoder conceals it); truncation was checked above.
            avcodec_send_packet(decoder.get(), packet.get());
            receive();
            consume(window, false);
        }
        av_packet_unref(packet.get());
    }
    if (rc != AVERROR_EOF)
        throw Error("read error (" + libav::errorText(rc) + ")", path);
    avcodec_send_packet(decoder.get(), nullptr);
    receive();
    resampler.flush(converted);
    append();
    if (window.end() == 0)
        throw Error("no decodable audio (corrupt file)", path);
    consume(window, true);
    return resampler.outRate();
}

void clampSamples(std::vector<float> &samples)
{
    for (float &s : samples)
        s = std::clamp(s, -1.0f, 1.0f);
}

} // namespace

AudioBuffer AudioDecoder::decode(const std::string &path, int sampleRate)
{
    AudioBuffer buffer;
    buffer.sampleRate = decodeStream(path, sampleRate, true, [&](SampleWindow &window, bool done) {
        if (done)
            buffer.samples = std::move(window.samples);
    });
    clampSamples(buffer.samples);
    return buffer;
}

void AudioDecoder::decodeRanges(const std::string &path, int sampleRate,
                                const std::vector<std::pair<double, double>> &ranges,
                                const std::function<void(size_t, AudioBuffer)> &take)
{
    for (size_t k = 0; k < ranges.size(); ++k)
        if (!(ranges[k].second >= ranges[k].first) || ranges[k].first < 0
            || (k > 0 && ranges[k].first < ranges[k - 1].first))
            throw Error("sound ranges must be increasing intervals of the timeline", path);
    const auto scan = libav::scanMedia(path);
    const int rate = sampleRate > 0 ? sampleRate : scan->audioSampleRate;
    size_t next = 0;
    // Hands out every range that the window now holds to its end, then drops what no later
    // range needs.
    auto serve = [&](SampleWindow &window, bool done) {
        while (next < ranges.size()) {
            const long long from = std::llround(ranges[next].first * rate);
            const long long to = std::llround(ranges[next].second * rate);
            if (to > window.end() && !done)
                break;
            AudioBuffer piece;
            piece.sampleRate = rate;
            piece.startTime = double(from) / rate;
            const long long a = std::clamp(from, window.first, window.end());
            const long long b = std::clamp(to, window.first, window.end());
            piece.samples.assign(window.samples.begin() + (a - window.first), window.samples.begin() + (b - window.first));
            clampSamples(piece.samples);
            take(next++, std::move(piece));
        }
        const long long keep = next < ranges.size() ? std::llround(ranges[next].first * rate) : window.end();
        if (keep > window.first) {
            const long long drop = std::min(keep, window.end()) - window.first;
            window.samples.erase(window.samples.begin(), window.samples.begin() + drop);
            window.first += drop;
        }
    };
    decodeStream(path, sampleRate, false, serve);
}

} // namespace lipsync
