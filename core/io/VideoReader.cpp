#include "io/VideoReader.h"

#include "io/LibAv.h"
#include "util/Error.h"

extern "C" {
#include <libavutil/pixdesc.h>
#include <libswscale/swscale.h>
}

#include <cmath>

namespace lipsync {

namespace {
// Up to this many frames ahead, decoding forward is cheaper than seeking (and exact).
constexpr int kMaxForwardDecode = 48;

bool fullRangeFormat(AVPixelFormat format)
{
    return format == AV_PIX_FMT_YUVJ420P || format == AV_PIX_FMT_YUVJ422P || format == AV_PIX_FMT_YUVJ444P
           || format == AV_PIX_FMT_YUVJ440P || format == AV_PIX_FMT_YUVJ411P;
}
} // namespace

// One open file: the demuxer, the video decoder, the picture last decoded and its converter.
struct VideoReader::Decoder
{
    libav::FormatPtr format;
    libav::CodecPtr codec;
    libav::PacketPtr packet{av_packet_alloc()};
    libav::FramePtr picture{av_frame_alloc()};
    SwsContext *converter = nullptr;
    cv::Mat scratch; // the converter's output rows, padded
    int stream = -1;
    double fileStart = 0.0;
    bool drained = false; // the end of the file was sent to the decoder

    Decoder(const std::string &path, int videoStream)
        : format(libav::openInput(path)), stream(videoStream)
    {
        codec = libav::openDecoder(path, format.get(), stream);
        fileStart = libav::fileStartSeconds(format.get());
    }
    ~Decoder() { sws_freeContext(converter); }
    Decoder(const Decoder &) = delete;
    Decoder &operator=(const Decoder &) = delete;

    // Decodes the next picture into `picture`; false at the end of the stream. Damaged packets
    // are passed on as the scan passed them (the decoder conceals what it can).
    bool next()
    {
        av_frame_unref(picture.get());
        for (;;) {
            const int rc = avcodec_receive_frame(codec.get(), picture.get());
            if (rc >= 0)
                return true;
            if (rc != AVERROR(EAGAIN) || drained)
                return false;
            for (;;) {
                if (av_read_frame(format.get(), packet.get()) < 0) {
                    avcodec_send_packet(codec.get(), nullptr);
                    drained = true;
                    break;
                }
                const bool ours = packet->stream_index == stream;
                if (ours)
                    avcodec_send_packet(codec.get(), packet.get());
                av_packet_unref(packet.get());
                if (ours)
                    break;
            }
        }
    }

    bool holdsPicture() const { return picture->data[0] != nullptr; }

    // The held picture's presentation time in seconds from the file's start (NaN if it has none),
    // as libav::scanMedia placed it on the clock.
    double time() const { return libav::frameSeconds(picture.get(), format->streams[stream]->time_base, fileStart); }

    // Moves to the last key frame at or before `seconds` from the file's start.
    bool seek(double seconds)
    {
        const AVRational base = format->streams[stream]->time_base;
        const auto ts = int64_t(std::floor((seconds + fileStart) / av_q2d(base)));
        if (av_seek_frame(format.get(), stream, ts, AVSEEK_FLAG_BACKWARD) < 0)
            return false;
        avcodec_flush_buffers(codec.get());
        av_frame_unref(picture.get());
        drained = false;
        return true;
    }

    // The held picture as BGR. The matrix is the stream's (BT.709 for unlabelled pictures 720
    // lines high or more, BT.601 below, as players assume); exact rounding and full chroma
    // interpolation keep a decode-export-decode round trip at the same colours. The chroma is
    // interpolated bilinearly, as players' GPU paths do: a bicubic one costs twice as much (at
    // 720p 7.3 against 3.7 ms a frame, a quarter of a render's time) for 0.4 levels' difference
    // on average.
    cv::Mat bgr(const std::string &path)
    {
        const auto source = AVPixelFormat(picture->format);
        const int w = picture->width, h = picture->height;
        converter = sws_getCachedContext(converter, w, h, source, w, h, AV_PIX_FMT_BGR24,
                                         SWS_BILINEAR | SWS_ACCURATE_RND | SWS_FULL_CHR_H_INT, nullptr, nullptr,
                                         nullptr);
        if (!converter) {
            const char *name = av_get_pix_fmt_name(source);
            throw Error(std::string("cannot convert the video's pixel format ") + (name ? name : "?"), path);
        }
        int matrix = picture->colorspace;
        if (matrix == AVCOL_SPC_UNSPECIFIED || matrix == AVCOL_SPC_RGB || matrix == AVCOL_SPC_RESERVED)
            matrix = h >= 720 ? SWS_CS_ITU709 : SWS_CS_ITU601;
        const int fullRange = picture->color_range == AVCOL_RANGE_JPEG || fullRangeFormat(source);
        sws_setColorspaceDetails(converter, sws_getCoefficients(matrix), fullRange, sws_getCoefficients(SWS_CS_ITU601),
                                 1, 0, 1 << 16, 1 << 16);
        // swscale's vector code may write whole blocks past a row's end: it writes into rows
        // with room to spare, and the frame is their copy.
        const int room = (w * 3 + 63) / 64 * 64 + 64;
        if (scratch.rows < h + 1 || scratch.step[0] < size_t(room))
            scratch.create(h + 1, room, CV_8UC1);
        uint8_t *const planes[4] = {scratch.data, nullptr, nullptr, nullptr};
        const int strides[4] = {int(scratch.step[0]), 0, 0, 0};
        sws_scale(converter, picture->data, picture->linesize, 0, h, planes, strides);
        return cv::Mat(h, w, CV_8UC3, scratch.data, scratch.step[0]).clone();
    }
};

VideoReader::VideoReader(const std::string &path) : m_path(path)
{
    const auto scan = libav::scanMedia(path); // throws for missing, empty, truncated, unsupported
    if (scan->videoStream < 0)
        throw Error("no video stream", path);
    m_clock = scan->frames;
    m_frameCount = m_clock.count();
    m_width = scan->width;
    m_height = scan->height;
    m_frameRate = m_clock.rate();
    m_videoStream = scan->videoStream;
    reopen();
}

VideoReader::~VideoReader() = default;

void VideoReader::reopen()
{
    m_decoder.reset();
    m_decoder = std::make_unique<Decoder>(m_path, m_videoStream);
    m_nextIndex = 0;
}

bool VideoReader::seekTo(int index)
{
    // Seeks land on a key frame at or before the one wanted; the picture decoded there is placed
    // on the clock by its timestamp. Containers that seek inexactly (MPEG program streams, GRID)
    // or pictures without a timestamp fall back to decoding from the start.
    if (!m_decoder->seek(m_clock.time(index)) || !m_decoder->next() || !m_decoder->picture->key_frame)
        return false;
    const double t = m_decoder->time();
    if (!std::isfinite(t))
        return false;
    const int landed = m_clock.nearestFrame(t);
    const double tolerance = m_frameRate > 0 ? 0.25 / m_frameRate : 0.001;
    if (landed < 0 || landed > index || std::abs(m_clock.time(landed) - t) > tolerance)
        return false;
    m_nextIndex = landed + 1;
    return true;
}

cv::Mat VideoReader::frame(int index)
{
    if (index < 0 || index >= m_frameCount)
        throw Error("frame " + std::to_string(index) + " out of range (the video has "
                        + std::to_string(m_frameCount) + " frames)",
                    m_path);
    const bool held = index == m_nextIndex - 1 && m_decoder->holdsPicture();
    if (!held && (index < m_nextIndex || index - m_nextIndex > kMaxForwardDecode)) {
        if (index <= kMaxForwardDecode || !seekTo(index))
            reopen(); // exact: decode forward from the first frame
    }
    while (m_nextIndex <= index) {
        if (!m_decoder->next())
            throw Error("cannot decode frame " + std::to_string(m_nextIndex) + " of "
                            + std::to_string(m_frameCount) + " (corrupt or truncated file)",
                        m_path);
        ++m_nextIndex;
    }
    return m_decoder->bgr(m_path);
}

double VideoReader::timestamp(int index) const
{
    return m_clock.time(index);
}

} // namespace lipsync
