#include "render/VideoExporter.h"

#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libavutil/channel_layout.h>
#include <libavutil/opt.h>
#include <libswresample/swresample.h>
#include <libswscale/swscale.h>
}

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>

namespace lipsync {

namespace {

namespace fs = std::filesystem;

std::string avError(int code)
{
    char buffer[AV_ERROR_MAX_STRING_SIZE] = {};
    av_strerror(code, buffer, sizeof buffer);
    return buffer;
}

// The muxer follows the extension; anything unknown is written as MP4.
const char *containerFor(const std::string &path)
{
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".mov")
        return "mov";
    if (ext == ".mkv")
        return "matroska";
    return "mp4";
}

// AAC (ISO 14496-3) defines these sampling rates only; others are resampled to 48 kHz.
bool aacSupportsRate(const AVCodec *codec, int rate)
{
    if (!codec->supported_samplerates)
        return true;
    for (const int *r = codec->supported_samplerates; *r; ++r)
        if (*r == rate)
            return true;
    return false;
}

std::vector<float> resample(const std::vector<float> &in, int inRate, int outRate,
                            const std::string &path)
{
    AVChannelLayout mono = AV_CHANNEL_LAYOUT_MONO;
    SwrContext *swr = nullptr;
    int rc = swr_alloc_set_opts2(&swr, &mono, AV_SAMPLE_FMT_FLT, outRate, &mono,
                                 AV_SAMPLE_FMT_FLT, inRate, 0, nullptr);
    if (rc < 0 || (rc = swr_init(swr)) < 0) {
        swr_free(&swr);
        throw Error("cannot resample the audio for AAC: " + avError(rc), path);
    }
    std::vector<float> out(size_t(av_rescale_rnd(int64_t(in.size()), outRate, inRate, AV_ROUND_UP)) + 256);
    const uint8_t *inPlanes[1] = {reinterpret_cast<const uint8_t *>(in.data())};
    uint8_t *outPlanes[1] = {reinterpret_cast<uint8_t *>(out.data())};
    int produced = swr_convert(swr, outPlanes, int(out.size()), inPlanes, int(in.size()));
    int total = std::max(produced, 0);
    if (produced >= 0) { // drain the filter delay
        outPlanes[0] = reinterpret_cast<uint8_t *>(out.data() + total);
        const int tail = swr_convert(swr, outPlanes, int(out.size()) - total, nullptr, 0);
        total += std::max(tail, 0);
    }
    swr_free(&swr);
    if (produced < 0)
        throw Error("cannot resample the audio for AAC: " + avError(produced), path);
    // Keep the duration exact: the drained filter tail may add or lack a sample or two.
    out.resize(size_t(total));
    out.resize(size_t(std::llround(double(in.size()) * outRate / inRate)), 0.0f);
    return out;
}

} // namespace

struct VideoExporter::Impl
{
    std::string path;
    std::string tempPath;
    VideoExportOptions options;
    AVRational frameRate{25, 1};

    std::vector<float> audio; // mono samples at audioRate
    int audioRate = 0;
    bool hasAudio = false;
    int64_t audioSamplesSent = 0;

    AVFormatContext *format = nullptr;
    AVCodecContext *videoCodec = nullptr;
    AVCodecContext *audioCodec = nullptr;
    AVStream *videoStream = nullptr;
    AVStream *audioStream = nullptr;
    AVFrame *videoFrame = nullptr;
    AVFrame *audioFrame = nullptr;
    AVPacket *packet = nullptr;
    SwsContext *sws = nullptr;

    int width = 0;  // of the frames given
    int height = 0;
    int targetFrames = -1;
    // Frame times as pts in the video time base (variable frame rate: 1/90000 s).
    bool variable = false;
    std::map<int64_t, int64_t> pendingDurations; // pts -> duration of frames sent to the encoder
    int64_t framesEncoded = 0;
    int framesAdded = 0;
    bool headerWritten = false;
    bool finished = false;
    bool abandoned = false;

    [[noreturn]] void fail(const std::string &what, int code) const
    {
        throw Error(what + ": " + avError(code), path);
    }

    void openTemporaryFile()
    {
        const fs::path target(path);
        if (target.filename().empty())
            throw Error("cannot write video: the output path names no file", path);
        fs::path dir = target.parent_path();
        if (dir.empty())
            dir = ".";
        std::error_code ec;
        if (fs::is_directory(target, ec))
            throw Error("cannot write video: the output path is a directory", path);
        if (!fs::is_directory(dir, ec))
            throw Error("cannot write video: the folder " + dir.string()
                            + (fs::exists(dir, ec) ? " is not a folder" : " does not exist"),
                        path);
        std::string hidden(1, '.'); // built by append: GCC 12 warns falsely on "." + string
        hidden.append(target.filename().string()).append(".XXXXXX.part");
        std::string pattern = (dir / hidden).string();
        const int fd = mkstemps(pattern.data(), 5);
        if (fd < 0)
            throw Error(std::string("cannot write video: ") + std::strerror(errno), path);
        // mkstemp creates 0600; an exported video is an ordinary user file.
        fchmod(fd, 0644);
        ::close(fd);
        tempPath = pattern;
    }

    void openContainer()
    {
        int rc = avformat_alloc_output_context2(&format, nullptr, containerFor(path), tempPath.c_str());
        if (rc < 0 || !format)
            fail("cannot create the video container", rc);
        rc = avio_open(&format->pb, tempPath.c_str(), AVIO_FLAG_WRITE);
        if (rc < 0)
            fail("cannot write video", rc);
        packet = av_packet_alloc();
    }

    void openAudio()
    {
        const AVCodec *codec = avcodec_find_encoder_by_name("aac");
        if (!codec)
            throw Error("this FFmpeg has no AAC encoder", path);
        if (!aacSupportsRate(codec, audioRate)) {
            audio = resample(audio, audioRate, 48000, path);
            audioRate = 48000;
        }
        audioCodec = avcodec_alloc_context3(codec);
        audioCodec->sample_fmt = AV_SAMPLE_FMT_FLTP;
        audioCodec->sample_rate = audioRate;
        av_channel_layout_default(&audioCodec->ch_layout, 1);
        // AAC allows at most 6144 bits per channel per 1024-sample frame.
        audioCodec->bit_rate = std::min<int64_t>(options.audioBitRate, 6 * int64_t(audioRate));
        audioCodec->time_base = AVRational{1, audioRate};
        if (format->oformat->flags & AVFMT_GLOBALHEADER)
            audioCodec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        // The "fast" coder costs a third of the default two-loop search; at 96-128 kbit/s for
        // mono speech the difference is inaudible.
        av_opt_set(audioCodec->priv_data, "aac_coder", "fast", 0);
        int rc = avcodec_open2(audioCodec, codec, nullptr);
        if (rc < 0)
            fail("cannot open the AAC encoder", rc);

        audioFrame = av_frame_alloc();
        audioFrame->format = audioCodec->sample_fmt;
        audioFrame->sample_rate = audioRate;
        av_channel_layout_copy(&audioFrame->ch_layout, &audioCodec->ch_layout);
        audioFrame->nb_samples = audioCodec->frame_size > 0 ? audioCodec->frame_size : 1024;
        rc = av_frame_get_buffer(audioFrame, 0);
        if (rc < 0)
            fail("cannot allocate audio frames", rc);
    }

    void openVideo(int frameWidth, int frameHeight)
    {
        width = frameWidth;
        height = frameHeight;
        const AVCodec *codec = avcodec_find_encoder_by_name("libx264");
        if (!codec)
            throw Error("this FFmpeg has no libx264 encoder", path);
        videoCodec = avcodec_alloc_context3(codec);
        videoCodec->width = width + (width & 1);
        videoCodec->height = height + (height & 1);
        videoCodec->pix_fmt = options.fullChroma ? AV_PIX_FMT_YUV444P : AV_PIX_FMT_YUV420P;
        videoCodec->time_base = variable ? AVRational{1, kVariableTimeBase} : AVRational{frameRate.den, frameRate.num};
        videoCodec->framerate = frameRate;
        videoCodec->sample_aspect_ratio = AVRational{1, 1};
        // A key frame every two seconds keeps scrubbing in players responsive.
        videoCodec->gop_size = std::max(1, int(std::lround(2.0 * options.frameRate())));
        videoCodec->color_range = AVCOL_RANGE_MPEG;
        videoCodec->colorspace = AVCOL_SPC_SMPTE170M; // swscale's default BGR->YUV matrix (BT.601)
        videoCodec->color_primaries = AVCOL_PRI_SMPTE170M;
        videoCodec->color_trc = AVCOL_TRC_SMPTE170M;
        if (format->oformat->flags & AVFMT_GLOBALHEADER)
            videoCodec->flags |= AV_CODEC_FLAG_GLOBAL_HEADER;
        videoCodec->thread_count = std::max(0, options.threads);
        av_opt_set(videoCodec->priv_data, "preset", options.preset.c_str(), 0);
        av_opt_set(videoCodec->priv_data, "crf", std::to_string(options.crf).c_str(), 0);
        int rc = avcodec_open2(videoCodec, codec, nullptr);
        if (rc < 0)
            fail("cannot open the H.264 encoder", rc);
        videoStream = avformat_new_stream(format, nullptr);
        videoStream->time_base = videoCodec->time_base;
        videoStream->avg_frame_rate = frameRate;
        videoStream->r_frame_rate = frameRate;
        avcodec_parameters_from_context(videoStream->codecpar, videoCodec);

        videoFrame = av_frame_alloc();
        videoFrame->format = videoCodec->pix_fmt;
        videoFrame->width = videoCodec->width;
        videoFrame->height = videoCodec->height;
        rc = av_frame_get_buffer(videoFrame, 0);
        if (rc < 0)
            fail("cannot allocate video frames", rc);
        // Exact rounding: swscale's fast path darkens every pass by about one level, which an
        // export of an export (or of a render beside its recording) would accumulate.
        sws = sws_getContext(videoCodec->width, videoCodec->height, AV_PIX_FMT_BGR24,
                             videoCodec->width, videoCodec->height, videoCodec->pix_fmt,
                             SWS_BICUBIC | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INP, nullptr, nullptr, nullptr);
        if (!sws)
            throw Error("cannot create the colour converter", path);
    }

    // Video first, then sound: the stream order players and editors expect.
    void addAudioStream()
    {
        audioStream = avformat_new_stream(format, nullptr);
        audioStream->time_base = audioCodec->time_base;
        avcodec_parameters_from_context(audioStream->codecpar, audioCodec);
    }

    void writeHeader()
    {
        AVDictionary *muxerOptions = nullptr;
        if (std::strcmp(format->oformat->name, "matroska") != 0)
            av_dict_set(&muxerOptions, "movflags", "+faststart", 0); // index first: plays while loading
        const int rc = avformat_write_header(format, &muxerOptions);
        av_dict_free(&muxerOptions);
        if (rc < 0)
            fail("cannot write the video header", rc);
        headerWritten = true;
    }

    // Sends a frame (or nullptr to flush) and writes every packet the encoder returns.
    void encode(AVCodecContext *codec, AVStream *stream, AVFrame *frame)
    {
        int rc = avcodec_send_frame(codec, frame);
        if (rc < 0)
            fail("cannot encode", rc);
        while (true) {
            rc = avcodec_receive_packet(codec, packet);
            if (rc == AVERROR(EAGAIN) || rc == AVERROR_EOF)
                return;
            if (rc < 0)
                fail("cannot encode", rc);
            if (codec == videoCodec) {
                // The frame's own length (the muxer needs it for the last sample's length).
                if (auto it = pendingDurations.find(packet->pts); it != pendingDurations.end()) {
                    packet->duration = it->second;
                    pendingDurations.erase(it);
                } else if (packet->duration == 0) {
                    packet->duration = 1;
                }
            }
            av_packet_rescale_ts(packet, codec->time_base, stream->time_base);
            packet->stream_index = stream->index;
            rc = av_interleaved_write_frame(format, packet);
            if (rc < 0)
                fail("cannot write video", rc);
        }
    }

    // Encodes audio up to `untilSample` (exclusive), in whole encoder frames except at the end.
    void sendAudioUntil(int64_t untilSample)
    {
        if (!hasAudio)
            return;
        const int64_t total = int64_t(audio.size());
        untilSample = std::min(untilSample, total);
        const int frameSize = audioFrame->nb_samples;
        const bool smallLastFrame = audioCodec->codec->capabilities & AV_CODEC_CAP_SMALL_LAST_FRAME;
        while (audioSamplesSent < untilSample) {
            const int64_t remaining = total - audioSamplesSent;
            if (remaining >= frameSize && audioSamplesSent + frameSize > untilSample)
                return; // wait for a whole frame unless this is the end of the sound
            const int count = int(std::min<int64_t>(frameSize, remaining));
            int rc = av_frame_make_writable(audioFrame);
            if (rc < 0)
                fail("cannot encode audio", rc);
            auto *plane = reinterpret_cast<float *>(audioFrame->data[0]);
            std::copy_n(audio.data() + audioSamplesSent, count, plane);
            audioFrame->nb_samples = frameSize;
            if (count < frameSize) {
                if (smallLastFrame)
                    audioFrame->nb_samples = count;
                else
                    std::fill(plane + count, plane + frameSize, 0.0f);
            }
            audioFrame->pts = audioSamplesSent;
            encode(audioCodec, audioStream, audioFrame);
            audioSamplesSent += count;
        }
    }

    // Presentation time of frame i relative to the first, in the video time base.
    int64_t framePts(int64_t i) const
    {
        if (!variable)
            return i;
        const FrameClock &clock = options.frames;
        return std::llround((clock.time(int(i)) - clock.startTime()) * kVariableTimeBase);
    }

    void encodeVideoFrame()
    {
        const int64_t i = framesEncoded++;
        videoFrame->pts = framePts(i);
        pendingDurations[videoFrame->pts] = framePts(i + 1) - videoFrame->pts;
        encode(videoCodec, videoStream, videoFrame);
        // Interleave: sound up to the end of this frame.
        if (hasAudio)
            sendAudioUntil(av_rescale_q(framePts(framesEncoded), videoCodec->time_base, AVRational{1, audioRate}));
    }

    static constexpr int kVariableTimeBase = 90000;

    void removeTemporary()
    {
        if (format) {
            if (format->pb)
                avio_closep(&format->pb);
        }
        if (!tempPath.empty()) {
            std::error_code ec;
            fs::remove(tempPath, ec);
            tempPath.clear();
        }
    }

    void release()
    {
        sws_freeContext(sws);
        sws = nullptr;
        av_frame_free(&videoFrame);
        av_frame_free(&audioFrame);
        av_packet_free(&packet);
        avcodec_free_context(&videoCodec);
        avcodec_free_context(&audioCodec);
        if (format) {
            if (format->pb)
                avio_closep(&format->pb);
            avformat_free_context(format);
            format = nullptr;
        }
    }
};

VideoExporter::VideoExporter(const std::string &path, const VideoExportOptions &options,
                             const AudioBuffer *audio)
    : d(std::make_unique<Impl>())
{
    // FFmpeg logs encoder statistics at info level on stderr; unless the application chose a
    // level, keep its errors only (our failures are reported as lipsync::Error).
    if (av_log_get_level() == AV_LOG_INFO)
        av_log_set_level(AV_LOG_ERROR);
    d->path = path;
    d->options = options;
    if (options.frameRateNumerator <= 0 || options.frameRateDenominator <= 0)
        throw Error("cannot write video: the frame rate must be positive", path);
    d->frameRate = AVRational{options.frameRateNumerator, options.frameRateDenominator};
    if (!options.frames.empty()) {
        d->targetFrames = options.frames.count();
        d->variable = options.frames.isVariable();
    }
    if (audio) {
        if (audio->sampleRate <= 0 || audio->samples.empty())
            throw Error("cannot write video: the audio track is empty", path);
        d->hasAudio = true;
        d->audio = audio->samples;
        d->audioRate = audio->sampleRate;
        // The sound lasts exactly as long as the frames: cut, or continued with silence.
        if (!options.frames.empty())
            d->audio.resize(size_t(std::llround(options.frames.duration() * audio->sampleRate)), 0.0f);
        if (d->audio.empty())
            throw Error("cannot write video: the frames last no time", path);
    }
    d->openTemporaryFile();
    try {
        d->openContainer();
        if (d->hasAudio)
            d->openAudio();
    } catch (...) {
        d->removeTemporary();
        d->release();
        throw;
    }
}

VideoExporter::~VideoExporter()
{
    if (!d->finished)
        abandon();
}

void VideoExporter::abandon()
{
    d->abandoned = true;
    d->removeTemporary();
    d->release();
}

const std::string &VideoExporter::path() const
{
    return d->path;
}

int VideoExporter::targetFrameCount() const
{
    return d->targetFrames;
}

int VideoExporter::framesAdded() const
{
    return d->framesAdded;
}

void VideoExporter::addFrame(const cv::Mat &frame)
{
    if (d->finished || d->abandoned)
        throw Error("cannot add a frame: the export is closed", d->path);
    if (frame.empty() || frame.depth() != CV_8U
        || (frame.channels() != 1 && frame.channels() != 3 && frame.channels() != 4))
        throw Error("cannot write video: frame " + std::to_string(d->framesAdded)
                        + " is not an 8-bit grey, BGR or BGRA image",
                    d->path);
    if (d->targetFrames >= 0 && d->framesEncoded >= d->targetFrames) {
        ++d->framesAdded; // beyond the end of the sound
        return;
    }
    try {
        if (!d->videoCodec) {
            d->openVideo(frame.cols, frame.rows);
            if (d->hasAudio)
                d->addAudioStream();
            d->writeHeader();
        }
        if (frame.cols != d->width || frame.rows != d->height)
            throw Error("cannot write video: frame " + std::to_string(d->framesAdded) + " is "
                            + std::to_string(frame.cols) + "x" + std::to_string(frame.rows)
                            + ", the first frame was " + std::to_string(d->width) + "x"
                            + std::to_string(d->height),
                        d->path);
        cv::Mat bgr;
        if (frame.channels() == 1)
            cv::cvtColor(frame, bgr, cv::COLOR_GRAY2BGR);
        else if (frame.channels() == 4)
            cv::cvtColor(frame, bgr, cv::COLOR_BGRA2BGR);
        else
            bgr = frame;
        if ((d->width | d->height) & 1) // yuv420p needs even sizes: repeat the last column/row
            cv::copyMakeBorder(bgr, bgr, 0, d->height & 1, 0, d->width & 1, cv::BORDER_REPLICATE);
        if (!bgr.isContinuous())
            bgr = bgr.clone();
        const int rc = av_frame_make_writable(d->videoFrame);
        if (rc < 0)
            d->fail("cannot encode video", rc);
        const uint8_t *src[1] = {bgr.data};
        const int srcStride[1] = {int(bgr.step[0])};
        sws_scale(d->sws, src, srcStride, 0, bgr.rows, d->videoFrame->data, d->videoFrame->linesize);
        d->encodeVideoFrame();
        ++d->framesAdded;
    } catch (...) {
        abandon();
        throw;
    }
}

void VideoExporter::finish()
{
    if (d->finished)
        return;
    if (d->abandoned)
        throw Error("cannot finish the export: it was abandoned", d->path);
    try {
        if (!d->videoCodec)
            throw Error("cannot write video: no frames were given", d->path);
        // Hold the last frame until the sound ends (videoFrame still holds it).
        while (d->targetFrames >= 0 && d->framesEncoded < d->targetFrames)
            d->encodeVideoFrame();
        if (d->hasAudio) {
            d->sendAudioUntil(int64_t(d->audio.size()));
            d->encode(d->audioCodec, d->audioStream, nullptr);
        }
        d->encode(d->videoCodec, d->videoStream, nullptr);
        int rc = av_write_trailer(d->format);
        if (rc < 0)
            d->fail("cannot write the video index", rc);
        rc = avio_closep(&d->format->pb);
        if (rc < 0)
            d->fail("cannot write video", rc);
        std::error_code ec;
        fs::rename(d->tempPath, d->path, ec);
        if (ec)
            throw Error("cannot write video: " + ec.message(), d->path);
        d->tempPath.clear();
        d->finished = true;
        d->release();
    } catch (...) {
        abandon();
        throw;
    }
}

void VideoExportOptions::setFrames(const FrameClock &clock)
{
    frames = clock;
    if (clock.rate() > 0)
        setFrameRate(clock.rate());
}

void VideoExportOptions::setFrameRate(double fps)
{
    if (std::abs(fps - std::round(fps)) < 1e-3) {
        frameRateNumerator = int(std::lround(fps));
        frameRateDenominator = 1;
    } else if (std::abs(fps * 1.001 - std::round(fps * 1.001)) < 1e-3) {
        frameRateNumerator = int(std::lround(fps * 1.001)) * 1000;
        frameRateDenominator = 1001;
    } else {
        frameRateNumerator = int(std::lround(fps * 1000));
        frameRateDenominator = 1000;
    }
}

AudioBuffer alignAudioToVideo(const AudioBuffer &audio, double firstFrameTime)
{
    AudioBuffer aligned;
    aligned.sampleRate = audio.sampleRate;
    aligned.startTime = firstFrameTime;
    const long long shift = std::llround((audio.startTime - firstFrameTime) * audio.sampleRate);
    if (shift >= 0) {
        aligned.samples.assign(size_t(shift), 0.0f);
        aligned.samples.insert(aligned.samples.end(), audio.samples.begin(), audio.samples.end());
    } else if (size_t(-shift) < audio.samples.size()) {
        aligned.samples.assign(audio.samples.begin() + std::ptrdiff_t(-shift), audio.samples.end());
    }
    return aligned;
}

int exportVideo(const std::string &path, int frameCount,
                 const std::function<cv::Mat(int)> &frameAt, const AudioBuffer *audio,
                 Feedback &feedback, const VideoExportOptions &options)
{
    if (frameCount <= 0)
        throw Error("cannot write video: no frames to export", path);
    feedback.setStatus("Exporting " + path);
    VideoExportOptions exact = options;
    if (exact.frames.empty())
        exact.frames = FrameClock::uniform(options.frameRate(), frameCount);
    else if (exact.frames.count() != frameCount)
        throw Error("cannot write video: " + std::to_string(frameCount) + " frames for a clock of "
                        + std::to_string(exact.frames.count()),
                    path);
    VideoExporter exporter(path, exact, audio);
    for (int i = 0; i < frameCount; ++i) {
        feedback.throwIfCanceled();
        exporter.addFrame(frameAt(i));
        feedback.setProgress(0.95 * (i + 1) / frameCount);
    }
    feedback.throwIfCanceled();
    exporter.finish();
    feedback.setProgress(1.0);
    return frameCount;
}

} // namespace lipsync
