#pragma once
// Test helper: reads an exported file back with libavformat/libavcodec, as a player would, and
// reports what ffprobe would (codecs, sizes, durations, start times) plus decoded content: the
// mean brightness and timestamp of every video frame and the timestamped audio samples.
extern "C" {
#include <libavcodec/avcodec.h>
#include <libavformat/avformat.h>
#include <libswscale/swscale.h>
}

#include <opencv2/core.hpp>

#include <stdexcept>
#include <string>
#include <vector>

struct MediaProbe
{
    AVCodecID videoCodec = AV_CODEC_ID_NONE;
    AVCodecID audioCodec = AV_CODEC_ID_NONE;
    int width = 0;
    int height = 0;
    int sampleRate = 0;
    int videoStreams = 0;
    int audioStreams = 0;
    double containerDuration = 0; // seconds
    double videoStart = 0;        // seconds, first presented frame
    double videoDuration = 0;
    double audioStart = 0;
    double audioDuration = 0;
    int videoPackets = 0;
    int videoStreamIndex = -1;

    std::vector<double> frameTimes;      // presentation time of each decoded frame, seconds
    std::vector<double> frameBrightness; // mean luma of each decoded frame
    std::vector<cv::Mat> frames;         // decoded BGR frames (when keepFrames)
    double firstAudioTime = 0;           // presentation time of the first decoded sample
    std::vector<float> audio;            // decoded mono samples (first channel)

    static MediaProbe read(const std::string &path, bool keepFrames = false)
    {
        MediaProbe probe;
        AVFormatContext *format = nullptr;
        if (avformat_open_input(&format, path.c_str(), nullptr, nullptr) < 0)
            throw std::runtime_error("cannot open " + path);
        avformat_find_stream_info(format, nullptr);
        probe.containerDuration = format->duration > 0 ? format->duration / double(AV_TIME_BASE) : 0;
        AVCodecContext *decoders[16] = {};
        for (unsigned i = 0; i < format->nb_streams && i < 16; ++i) {
            AVStream *s = format->streams[i];
            const double tb = av_q2d(s->time_base);
            const double start = s->start_time == AV_NOPTS_VALUE ? 0 : s->start_time * tb;
            const double duration = s->duration == AV_NOPTS_VALUE ? 0 : s->duration * tb;
            if (s->codecpar->codec_type == AVMEDIA_TYPE_VIDEO) {
                ++probe.videoStreams;
                probe.videoStreamIndex = int(i);
                probe.videoCodec = s->codecpar->codec_id;
                probe.width = s->codecpar->width;
                probe.height = s->codecpar->height;
                probe.videoStart = start;
                probe.videoDuration = duration;
            } else if (s->codecpar->codec_type == AVMEDIA_TYPE_AUDIO) {
                ++probe.audioStreams;
                probe.audioCodec = s->codecpar->codec_id;
                probe.sampleRate = s->codecpar->sample_rate;
                probe.audioStart = start;
                probe.audioDuration = duration;
            } else {
                continue;
            }
            const AVCodec *codec = avcodec_find_decoder(s->codecpar->codec_id);
            decoders[i] = avcodec_alloc_context3(codec);
            avcodec_parameters_to_context(decoders[i], s->codecpar);
            decoders[i]->pkt_timebase = s->time_base;
            avcodec_open2(decoders[i], codec, nullptr);
        }
        AVPacket *packet = av_packet_alloc();
        AVFrame *frame = av_frame_alloc();
        bool firstAudio = true;
        auto drain = [&](int index) {
            AVStream *s = format->streams[index];
            while (avcodec_receive_frame(decoders[index], frame) >= 0) {
                const double t = frame->best_effort_timestamp * av_q2d(s->time_base);
                if (s->codecpar->codec_type == AVMEDIA_TYPE_VIDEO) {
                    probe.frameTimes.push_back(t);
                    double sum = 0;
                    for (int y = 0; y < frame->height; ++y)
                        for (int x = 0; x < frame->width; ++x)
                            sum += frame->data[0][y * frame->linesize[0] + x];
                    probe.frameBrightness.push_back(sum / (frame->width * frame->height));
                    if (keepFrames) {
                        // A spare row: swscale's SIMD paths may write a little past the end.
                        cv::Mat padded(frame->height + 2, frame->width, CV_8UC3);
                        cv::Mat bgr = padded.rowRange(0, frame->height);
                        SwsContext *sws = sws_getContext(frame->width, frame->height,
                                                         AVPixelFormat(frame->format), frame->width,
                                                         frame->height, AV_PIX_FMT_BGR24,
                                                         SWS_BILINEAR, nullptr, nullptr, nullptr);
                        uint8_t *dst[1] = {bgr.data};
                        int dstStride[1] = {int(bgr.step[0])};
                        sws_scale(sws, frame->data, frame->linesize, 0, frame->height, dst, dstStride);
                        sws_freeContext(sws);
                        probe.frames.push_back(bgr);
                    }
                } else {
                    if (firstAudio)
                        probe.firstAudioTime = t;
                    firstAudio = false;
                    const auto *samples = reinterpret_cast<const float *>(frame->data[0]);
                    probe.audio.insert(probe.audio.end(), samples, samples + frame->nb_samples);
                }
                av_frame_unref(frame);
            }
        };
        while (av_read_frame(format, packet) >= 0) {
            const int index = packet->stream_index;
            if (index < 16 && decoders[index]) {
                if (format->streams[index]->codecpar->codec_type == AVMEDIA_TYPE_VIDEO)
                    ++probe.videoPackets;
                avcodec_send_packet(decoders[index], packet);
                drain(index);
            }
            av_packet_unref(packet);
        }
        for (unsigned i = 0; i < format->nb_streams && i < 16; ++i) {
            if (decoders[i]) {
                avcodec_send_packet(decoders[i], nullptr);
                drain(int(i));
                avcodec_free_context(&decoders[i]);
            }
        }
        av_frame_free(&frame);
        av_packet_free(&packet);
        avformat_close_input(&format);
        return probe;
    }
};
