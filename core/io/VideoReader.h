#pragma once
// Video frames through OpenCV with real timestamps. Random access by frame index (seeks and
// decodes forward; sequential reads are cheap). Frames are BGR 8-bit cv::Mat.
#include <opencv2/core.hpp>

#include <memory>
#include <string>

namespace cv { class VideoCapture; }

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
    // Presentation time of frame `index` in seconds.
    double timestamp(int index) const;

private:
    std::string m_path;
    std::unique_ptr<cv::VideoCapture> m_capture;
    int m_frameCount = 0;
    double m_frameRate = 0.0;
    int m_width = 0;
    int m_height = 0;
    int m_nextIndex = 0; // index of the frame the next read() returns
};

} // namespace lipsync
