#pragma once
// Frame access for the face commands. Uses cv::VideoCapture directly until core/io/VideoReader
// lands on main; then this becomes a thin wrapper around it.
#include <opencv2/core.hpp>

#include <memory>
#include <string>

namespace cv { class VideoCapture; }

namespace lipsync::cli {

bool isImageFile(const std::string &path);

class VideoFrames
{
public:
    // Throws lipsync::Error naming the file if it cannot be opened.
    explicit VideoFrames(const std::string &path);
    ~VideoFrames();
    // Next frame in order; false at the end. Undecodable frames come back empty (not an error).
    bool next(cv::Mat &frame);
    int frameCount() const { return m_frameCount; }
    double frameRate() const { return m_frameRate; }

private:
    std::unique_ptr<cv::VideoCapture> m_capture;
    int m_frameCount = 0;
    double m_frameRate = 0.0;
};

} // namespace lipsync::cli
