#include "io/LibAv.h"

#include "util/Environment.h"
#include "util/Error.h"

extern "C" {
#include <libavutil/log.h>
}

#include <cmath>
#include <cstdarg>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>
#include <tuple>

namespace lipsync::libav {

namespace fs = std::filesystem;

std::string errorText(int code)
{
    char text[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, text, sizeof text);
    return text;
}

namespace {

// The demuxer reports a packet cut short by the end of the file ("Packet corrupt") only in its
// log: the parser that splits MPEG streams into frames drops the packet's corrupt flag. A scan
// registers its context here to hear about it (same thread: av_read_frame is synchronous).
thread_local const void *t_watchedContext = nullptr;
thread_local bool t_corruptPacketReported = false;

void logCallback(void *context, int level, const char *format, va_list args)
{
    if (context && context == t_watchedContext && format
        && std::strncmp(format, "Packet corrupt", 14) == 0)
        t_corruptPacketReported = true;
    av_log_default_callback(context, level, format, args);
}

struct WatchCorruptPackets
{
    explicit WatchCorruptPackets(const void *context)
    {
        t_watchedContext = context;
        t_corruptPacketReported = false;
    }
    ~WatchCorruptPackets() { t_watchedContext = nullptr; }
    bool reported() const { return t_corruptPacketReported; }
};

} // namespace

void quietLogs()
{
    static std::once_flag installed;
    std::call_once(installed, [] { av_log_set_callback(logCallback); });
    static const bool verbose = environment::isSet("LIPSYNC_FFMPEG_LOG");
    if (!verbose && av_log_get_level() != AV_LOG_QUIET)
        av_log_set_level(AV_LOG_QUIET);
}

void checkReadableFile(const std::string &path)
{
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (ec || !fs::exists(status))
        throw Error("file not found", path);
    if (!fs::is_regular_file(status))
        throw Error("not a regular file", path);
    const auto size = fs::file_size(path, ec);
    if (ec)
        throw Error("cannot read file: " + ec.message(), path);
    if (size == 0)
        throw Error("empty file", path);
}

FormatPtr openInput(const std::string &path)
{
    quietLogs();
    checkReadableFile(path);
    AVFormatContext *raw = nullptr;
    int rc = avformat_open_input(&raw, path.c_str(), nullptr, nullptr);
    if (rc < 0)
        throw Error("unsupported or corrupt media file (" + errorText(rc) + ")", path);
    FormatPtr format(raw);
    rc = avformat_find_stream_info(format.get(), nullptr);
    if (rc < 0)
        throw Error("cannot read stream information (" + errorText(rc) + ")", path);
    if (firstAudioStream(format.get()) < 0 && firstVideoStream(format.get()) < 0)
        throw Error("no audio or video stream (unsupported or corrupt media file)", path);
    return format;
}

double fileStartSeconds(const AVFormatContext *format)
{
    return format->start_time != AV_NOPTS_VALUE ? double(format->start_time) / AV_TIME_BASE : 0.0;
}

double frameSeconds(const AVFrame *frame, AVRational timeBase, double fileStart)
{
    if (frame->best_effort_timestamp == AV_NOPTS_VALUE)
        return NAN;
    return double(frame->best_effort_timestamp) * av_q2d(timeBase) - fileStart;
}

CodecPtr openDecoder(const std::string &path, AVFormatContext *format, int index)
{
    const AVCodecParameters *par = format->streams[index]->codecpar;
    const AVCodec *codec = avcodec_find_decoder(par->codec_id);
    if (!codec)
        throw Error(std::string("no decoder for codec '") + avcodec_get_name(par->codec_id) + "'",
                    path);
    CodecPtr context(avcodec_alloc_context3(codec));
    if (!context)
        throw Error("out of memory opening the decoder", path);
    int rc = avcodec_parameters_to_context(context.get(), par);
    if (rc >= 0) {
        context->pkt_timebase = format->streams[index]->time_base;
        context->thread_count = 1; // several readers may run at once; keep each one light
        rc = avcodec_open2(context.get(), codec, nullptr);
    }
    if (rc < 0)
        throw Error(std::string("cannot open the ") + codec->name + " decoder (" + errorText(rc)
                        + ")",
                    path);
    return context;
}

int firstAudioStream(const AVFormatContext *format)
{
    for (unsigned i = 0; i < format->nb_streams; ++i)
        if (format->streams[i]->codecpar->codec_type == AVMEDIA_TYPE_AUDIO)
            return int(i);
    return -1;
}

int firstVideoStream(const AVFormatContext *format)
{
    for (unsigned i = 0; i < format->nb_streams; ++i) {
        const AVStream *st = format->streams[i];
        if (st->codecpar->codec_type == AVMEDIA_TYPE_VIDEO
            && !(st->disposition & AV_DISPOSITION_ATTACHED_PIC))
            return int(i);
    }
    return -1;
}

namespace {

bool damaged(const AVFrame *frame)
{
    return frame->decode_error_flags != 0 || (frame->flags & AV_FRAME_FLAG_CORRUPT);
}

// Length in bytes of the MPEG audio frame (layer I/II/III) whose header starts `data`, or 0 when
// it is not a valid header or uses the free format. Parsed audio packets hold one frame each,
// so a shorter last packet means the file was cut inside it.
int mpegAudioFrameLength(const uint8_t *data, int size)
{
    if (size < 4)
        return 0;
    const uint32_t h = uint32_t(data[0]) << 24 | uint32_t(data[1]) << 16 | uint32_t(data[2]) << 8 | data[3];
    if ((h & 0xffe00000u) != 0xffe00000u)
        return 0;
    const int version = (h >> 19) & 3; // 0: MPEG 2.5, 2: MPEG 2, 3: MPEG 1
    const int layer = 4 - int((h >> 17) & 3); // 1, 2, 3 (4: reserved)
    const int bitrateIndex = (h >> 12) & 15;
    const int rateIndex = (h >> 10) & 3;
    const int padding = (h >> 9) & 1;
    if (version == 1 || layer == 4 || bitrateIndex == 0 || bitrateIndex == 15 || rateIndex == 3)
        return 0;
    static const int kbps[5][15] = {
        {0, 32, 64, 96, 128, 160, 192, 224, 256, 288, 320, 352, 384, 416, 448}, // V1 L1
        {0, 32, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320, 384},    // V1 L2
        {0, 32, 40, 48, 56, 64, 80, 96, 112, 128, 160, 192, 224, 256, 320},     // V1 L3
        {0, 32, 48, 56, 64, 80, 96, 112, 128, 144, 160, 176, 192, 224, 256},    // V2 L1
        {0, 8, 16, 24, 32, 40, 48, 56, 64, 80, 96, 112, 128, 144, 160},         // V2 L2/L3
    };
    static const int rates[3] = {44100, 48000, 32000};
    const bool v1 = version == 3;
    const int table = v1 ? layer - 1 : (layer == 1 ? 3 : 4);
    const int bitrate = kbps[table][bitrateIndex] * 1000;
    const int sampleRate = rates[rateIndex] >> (v1 ? 0 : (version == 2 ? 1 : 2));
    if (layer == 1)
        return (12 * bitrate / sampleRate + padding) * 4;
    if (layer == 3 && !v1)
        return 72 * bitrate / sampleRate + padding;
    return 144 * bitrate / sampleRate + padding;
}

double seconds(int64_t ts, AVRational base)
{
    return double(ts) * av_q2d(base);
}

// The duration a stream's header declares, or a negative value when the container only
// estimates it (from timestamps or the bit rate, which a truncated file makes consistent).
double declaredDuration(const AVFormatContext *format, const AVStream *st)
{
    if (format->duration_estimation_method != AVFMT_DURATION_FROM_STREAM
        || st->duration == AV_NOPTS_VALUE || st->duration <= 0)
        return -1.0;
    return seconds(st->duration, st->time_base);
}

// The video stream's description in `scan`, and its decoder set to count frames (none without one).
CodecPtr openVideoForScan(const std::string &path, AVFormatContext *fc, double fileStart, MediaScan &scan)
{
    CodecPtr video;
    scan.videoStream = firstVideoStream(fc);
    if (scan.videoStream >= 0) {
        AVStream *st = fc->streams[scan.videoStream];
        video = openDecoder(path, fc, scan.videoStream);
        // Counting only: the picture is not used, so skip the pixel work (bitstream errors, and
        // so truncation, are still seen while parsing).
        video->skip_loop_filter = AVDISCARD_ALL;
        video->skip_idct = AVDISCARD_ALL;
        scan.videoCodec = avcodec_get_name(st->codecpar->codec_id);
        scan.width = st->codecpar->width;
        scan.height = st->codecpar->height;
        const AVRational rate = av_guess_frame_rate(fc, st, nullptr);
        scan.frameRate = rate.num > 0 && rate.den > 0 ? av_q2d(rate) : 0.0;
        if (scan.frameRate > 0) {
            scan.frameRateNum = rate.num;
            scan.frameRateDen = rate.den;
        }
        if (st->start_time != AV_NOPTS_VALUE)
            scan.videoStreamStart = seconds(st->start_time, st->time_base) - fileStart;
    }
    return video;
}

// The audio stream's description in `scan`, and its decoder (none without one, or when the codec
// has no decoder).
CodecPtr openAudioForScan(const std::string &path, AVFormatContext *fc, MediaScan &scan)
{
    CodecPtr audio;
    scan.audioStream = firstAudioStream(fc);
    if (scan.audioStream >= 0) {
        const AVCodecParameters *par = fc->streams[scan.audioStream]->codecpar;
        scan.audioCodec = avcodec_get_name(par->codec_id);
        scan.audioSampleRate = par->sample_rate;
        scan.audioChannels = par->ch_layout.nb_channels;
        // A stream without a decoder is reported as present but undecodable by AudioDecoder;
        // here it only has no decoded length.
        try {
            audio = openDecoder(path, fc, scan.audioStream);
        } catch (const Error &) {
            audio.reset();
        }
    }
    return audio;
}

// What the end of the demuxing showed: the signs of a file cut inside a packet.
struct LastPacketSigns
{
    bool lastVideoDamaged = false;
    bool lastPacketCorrupt = false; // flagged, or reported in the demuxer's log
    bool lastAudioPacketShort = false;
    int videoPackets = 0;
    bool hasVideo = false, hasAudio = false; // the streams were decoded
};

void judgeTruncation(MediaScan &scan, const AVFormatContext *fc, const LastPacketSigns &signs)
{
    // Truncation: the file ends inside a packet. MPEG program streams carry no length, so the
    // signs are the decoder concealing damage in the very last picture, a last MPEG audio
    // packet shorter than its header says, or a video packet that yields no picture;
    // the demuxer reporting a packet cut short; containers with a length in their header
    // (WAV, MP4, ...) flag the cut packet or decode shorter than they declare.
    if (signs.lastVideoDamaged) {
        scan.truncated = true;
        scan.truncatedReason = "the last video frame is incomplete";
    } else if (signs.lastPacketCorrupt) {
        scan.truncated = true;
        scan.truncatedReason = "a packet is cut short";
    } else if (signs.lastAudioPacketShort) {
        scan.truncated = true;
        scan.truncatedReason = "the last audio frame is incomplete";
    } else if (signs.hasVideo && signs.videoPackets > int(scan.frameTimes.size())) {
        // Each (parsed) video packet is one picture; one that yields no frame was cut short.
        scan.truncated = true;
        scan.truncatedReason = std::to_string(signs.videoPackets - int(scan.frameTimes.size()))
                               + " video packet(s) do not decode";
    } else {
        auto shortOf = [](double decoded, double declared) {
            return declared > 0 && decoded < declared - std::max(0.1, 0.02 * declared);
        };
        if (signs.hasVideo && scan.frameRate > 0) {
            // The frames' span by their timestamps (a variable frame rate has fewer frames than
            // duration x rate), one nominal period for the last.
            const double decoded = scan.frames.duration();
            const double declared = declaredDuration(fc, fc->streams[scan.videoStream]);
            if (shortOf(decoded, declared)) {
                scan.truncated = true;
                scan.truncatedReason = "video decodes to " + std::to_string(decoded)
                                       + " s of " + std::to_string(declared) + " s declared";
            }
        }
        if (!scan.truncated && signs.hasAudio && scan.audioSampleRate > 0) {
            const double decoded = double(scan.audioSamples) / scan.audioSampleRate;
            const double declared = declaredDuration(fc, fc->streams[scan.audioStream]);
            if (shortOf(decoded, declared)) {
                scan.truncated = true;
                scan.truncatedReason = "audio decodes to " + std::to_string(decoded)
                                       + " s of " + std::to_string(declared) + " s declared";
            }
        }
    }
}

std::shared_ptr<MediaScan> scanUncached(const std::string &path)
{
    FormatPtr format = openInput(path);
    AVFormatContext *fc = format.get();
    auto scan = std::make_shared<MediaScan>();
    scan->formatName = fc->iformat ? fc->iformat->name : "";
    if (fc->duration != AV_NOPTS_VALUE && fc->duration > 0)
        scan->containerDuration = double(fc->duration) / AV_TIME_BASE;
    const double fileStart = fileStartSeconds(fc);

    CodecPtr video = openVideoForScan(path, fc, fileStart, *scan);
    CodecPtr audio = openAudioForScan(path, fc, *scan);

    PacketPtr packet(av_packet_alloc());
    FramePtr frame(av_frame_alloc());
    bool lastVideoDamaged = false;
    scan->audioTimeline = AudioTimeline(scan->containerDuration);
    bool lastPacketCorrupt = false;
    int videoPackets = 0;
    bool lastAudioPacketShort = false;
    const AVCodecID audioCodecId = scan->audioStream >= 0
                                       ? fc->streams[scan->audioStream]->codecpar->codec_id
                                       : AV_CODEC_ID_NONE;
    const bool mpegAudio = audioCodecId == AV_CODEC_ID_MP1 || audioCodecId == AV_CODEC_ID_MP2
                           || audioCodecId == AV_CODEC_ID_MP3;

    auto receiveVideo = [&] {
        while (avcodec_receive_frame(video.get(), frame.get()) >= 0) {
            const AVStream *st = fc->streams[scan->videoStream];
            double t = frameSeconds(frame.get(), st->time_base, fileStart);
            if (!std::isfinite(t)) // no timestamp: one period after the last frame
                t = !scan->frameTimes.empty() && scan->frameRate > 0
                        ? scan->frameTimes.back() + 1.0 / scan->frameRate
                        : (scan->frameRate > 0 ? double(scan->frameTimes.size()) / scan->frameRate : 0.0);
            scan->frameTimes.push_back(t);
            lastVideoDamaged = damaged(frame.get());
            if (lastVideoDamaged)
                ++scan->damagedFrames;
            av_frame_unref(frame.get());
        }
    };
    auto receiveAudio = [&] {
        while (avcodec_receive_frame(audio.get(), frame.get()) >= 0) {
            const AVStream *st = fc->streams[scan->audioStream];
            const double pts = frameSeconds(frame.get(), st->time_base, fileStart);
            scan->audioTimeline.place(pts, frame->nb_samples, frame->sample_rate);
            scan->audioSamples += frame->nb_samples;
            if (frame->sample_rate > 0)
                scan->audioSampleRate = frame->sample_rate;
            if (frame->ch_layout.nb_channels > 0)
                scan->audioChannels = frame->ch_layout.nb_channels;
            av_frame_unref(frame.get());
        }
    };

    const WatchCorruptPackets watch(fc);
    int rc;
    while ((rc = av_read_frame(fc, packet.get())) >= 0) {
        const int index = packet->stream_index;
        if (index == scan->videoStream || index == scan->audioStream)
            lastPacketCorrupt = (packet->flags & AV_PKT_FLAG_CORRUPT) != 0;
        if (index == scan->videoStream) {
            if (packet->size > 0)
                ++videoPackets;
            avcodec_send_packet(video.get(), packet.get()); // damage shows in the frames
            receiveVideo();
        } else if (index == scan->audioStream && audio) {
            if (mpegAudio) {
                const int expected = mpegAudioFrameLength(packet->data, packet->size);
                lastAudioPacketShort = expected > 0 && packet->size < expected;
            }
            // Damaged audio packets are skipped by the decoder; the length check below notices.
            avcodec_send_packet(audio.get(), packet.get());
            receiveAudio();
        }
        av_packet_unref(packet.get());
    }
    if (rc != AVERROR_EOF)
        throw Error("read error (" + errorText(rc) + ")", path);
    if (video) {
        avcodec_send_packet(video.get(), nullptr);
        receiveVideo();
    }
    if (audio) {
        avcodec_send_packet(audio.get(), nullptr);
        receiveAudio();
    }

    if (video && scan->frameTimes.empty())
        throw Error("no decodable video frame (corrupt or truncated file)", path);
    scan->frames = FrameClock::fromTimes(scan->frameTimes, scan->frameRate);
    scan->audioStartTime = scan->audioTimeline.firstTime();
    scan->audioEndTime = scan->audioTimeline.endTime();

    judgeTruncation(*scan, fc, {lastVideoDamaged, lastPacketCorrupt || watch.reported(), lastAudioPacketShort,
                                videoPackets, bool(video), bool(audio)});
    return scan;
}

} // namespace

std::shared_ptr<const MediaScan> scanMedia(const std::string &path)
{
    checkReadableFile(path);
    std::error_code ec;
    std::string key = fs::absolute(path, ec).lexically_normal().string();
    if (ec)
        key = path;
    const auto size = fs::file_size(path, ec);
    const auto mtime = fs::last_write_time(path, ec).time_since_epoch().count();
    using Key = std::tuple<std::string, std::uintmax_t, long long>;
    static std::mutex mutex;
    static std::map<Key, std::shared_ptr<const MediaScan>> cache;
    const Key k{key, size, static_cast<long long>(mtime)};
    {
        std::lock_guard lock(mutex);
        if (auto it = cache.find(k); it != cache.end())
            return it->second;
    }
    std::shared_ptr<const MediaScan> scan = scanUncached(path);
    if (scan->truncated)
        throw Error("truncated or damaged file: " + scan->truncatedReason, path);
    std::lock_guard lock(mutex);
    if (cache.size() > 4096)
        cache.clear();
    cache[k] = scan;
    return scan;
}

} // namespace lipsync::libav
