#pragma once
// Internal to core/io: small RAII wrappers around libavformat/libavcodec/libswresample and the
// checks every media reader shares (missing/empty files, unsupported containers, truncation).
// Not part of the public API: include only from core/io/*.cpp.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswresample/swresample.h>
}

#include "annotation/FrameClock.h"
#include "io/AudioTimeline.h"

#include <memory>
#include <string>
#include <vector>

namespace lipsync::libav {

struct FormatCloser { void operator()(AVFormatContext *c) const { avformat_close_input(&c); } };
struct CodecFreer { void operator()(AVCodecContext *c) const { avcodec_free_context(&c); } };
struct PacketFreer { void operator()(AVPacket *p) const { av_packet_free(&p); } };
struct FrameFreer { void operator()(AVFrame *f) const { av_frame_free(&f); } };
struct SwrFreer { void operator()(SwrContext *s) const { swr_free(&s); } };

using FormatPtr = std::unique_ptr<AVFormatContext, FormatCloser>;
using CodecPtr = std::unique_ptr<AVCodecContext, CodecFreer>;
using PacketPtr = std::unique_ptr<AVPacket, PacketFreer>;
using FramePtr = std::unique_ptr<AVFrame, FrameFreer>;
using SwrPtr = std::unique_ptr<SwrContext, SwrFreer>;

// libav's text for an AVERROR code.
std::string errorText(int code);

// Keeps libav from writing decoder chatter ("ac-tex damaged ...") on stderr: the CLI promises one
// line per error, and readers report damage through lipsync::Error instead. Lowers the global
// level to AV_LOG_QUIET unless LIPSYNC_FFMPEG_LOG is set, and installs (once) a log callback
// that forwards to libav's default one and lets scanMedia hear the demuxer's "Packet corrupt".
// Cheap; call before any libav work (OpenCV resets the level when it first opens a capture,
// so call again after that).
void quietLogs();

// Throws lipsync::Error naming the file if it is missing, not a regular file, or empty.
void checkReadableFile(const std::string &path);

// Opens the container and reads stream info. Throws lipsync::Error naming the file for missing,
// empty and unrecognised files.
FormatPtr openInput(const std::string &path);

// The file's start on the media timeline (its earliest stream's start), in the streams' seconds:
// timestamps less this are seconds from the file's start.
double fileStartSeconds(const AVFormatContext *format);

// A decoded frame's presentation time in seconds from the file's start (its best-effort
// timestamp in `timeBase`, less `fileStart`), NaN when it has none. One definition for the scan's
// clock and every reader placed on it.
double frameSeconds(const AVFrame *frame, AVRational timeBase, double fileStart);

// Opens a decoder for stream `index`. Throws lipsync::Error naming the file.
CodecPtr openDecoder(const std::string &path, AVFormatContext *format, int index);

// Index of the first audio stream, or -1.
int firstAudioStream(const AVFormatContext *format);
// Index of the main video stream (not cover art), or -1.
int firstVideoStream(const AVFormatContext *format);

// Everything a full pass over a file learns: the decoded video frame count and timestamps,
// decoded audio length, and whether the file ends inside a packet (truncated).
struct MediaScan
{
    std::string formatName;
    double containerDuration = 0.0; // seconds, as the container states or estimates it

    int videoStream = -1;
    std::string videoCodec;
    int width = 0;
    int height = 0;
    double frameRate = 0.0;              // the stream's frame rate (avg/r_frame_rate)
    int frameRateNum = 0, frameRateDen = 0; // the same as a fraction (30000/1001)
    std::vector<double> frameTimes;      // decoded frames' presentation times, seconds from the file start
    FrameClock frames;                   // the same as a clock (evenly spaced when they are)
    int damagedFrames = 0;               // frames the decoder had to conceal
    double videoStreamStart = 0.0;       // the video stream's start_time, seconds from the file start

    int audioStream = -1;
    std::string audioCodec;
    int audioSampleRate = 0;
    int audioChannels = 0;
    long long audioSamples = 0;          // decoded samples per channel
    double audioStartTime = 0.0;         // first audio sample, seconds from the file start
    double audioEndTime = 0.0;           // end of the last sample on the timeline (gaps included)
    AudioTimeline audioTimeline;         // the decoded frames placed by their timestamps

    bool truncated = false;
    std::string truncatedReason;
};

// Demuxes and decodes the whole file once (video frames are decoded but not converted).
// Results are cached per (path, size, modification time), so repeated calls are free.
// Throws lipsync::Error naming the file for missing, empty, unsupported, stream-less and
// truncated files.
std::shared_ptr<const MediaScan> scanMedia(const std::string &path);

} // namespace lipsync::libav
