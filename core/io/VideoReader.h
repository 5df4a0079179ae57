#pragma once
// Video frames decoded by libavcodec with real timestamps. Random access by frame index (seeks and
// decodes forward; sequential reads are cheap). Frames are BGR 8-bit cv::Mat, converted by
// libswscale with the stream's own colour matrix and range and exact rounding, so that a frame
// decoded, exported (VideoExporter) and decoded again keeps its colours.
//
// The frame count and the timestamps come from one full decode of the file at construction
// (cached per file for the process), so frameCount() is what really decodes, not the
// container's estimate. Frames a stream holds before its first keyframe (some GRID clips) are
// returned as the decoder produces them (often flat grey), not skipped.
// Truncated files (cut inside a packet) are rejected by the constructor, as by MediaInfo::probe
// and AudioDecoder::decode. One reader is not thread-safe; use one per thread.
#include "annotation/FrameClock.h"

#include <opencv2/core.hpp>

#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class VideoReader
{
public:
    // Throws lipsync::Error naming the file if it cannot be opened or holds no video.
    explicit VideoReader(const std::string &path);
    ~VideoReader();
    VideoReader(const VideoReader &) = delete;
    VideoReader &operator=(const VideoReader &) = delete;

    const std::string &path() const { return m_path; }
    int frameCount() const { return m_frameCount; }
    double frameRate() const { return m_frameRate; }
    int width() const { return m_width; }
    int height() const { return m_height; }

    // Frame `index` (0-based). Throws lipsync::Error if it cannot be decoded (truncated file).
    cv::Mat frame(int index);
    // Presentation time of frame `index` in seconds from the start of the file (the time base
    // AudioBuffer::startTime uses). Indices outside the video extrapolate at frameRate().
    double timestamp(int index) const;
    // All frames' presentation times (frameCount() entries).
    std::vector<double> timestamps() const { return m_clock.times(); }
    // The same as a clock (frame <-> time both ways).
    const FrameClock &clock() const { return m_clock; }

private:
    struct Decoder;

    void reopen();
    bool seekTo(int index);

    std::string m_path;
    std::unique_ptr<Decoder> m_decoder;
    int m_frameCount = 0;
    double m_frameRate = 0.0;
    int m_width = 0;
    int m_height = 0;
    int m_nextIndex = 0; // index of the frame the next read() returns
    FrameClock m_clock; // every frame's presentation time
    int m_videoStream = -1;
};

} // namespace lipsync
