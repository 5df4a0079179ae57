#include "VideoFrames.h"

#include "util/Error.h"

#include <opencv2/videoio.hpp>

#include <algorithm>
#include <cctype>

namespace lipsync::cli {

bool isImageFile(const std::string &path)
{
    std::string lower = path;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const char *ext : {".jpg", ".jpeg", ".png", ".bmp", ".tif", ".tiff", ".ppm", ".pgm"})
        if (lower.size() > std::char_traits<char>::length(ext)
            && lower.ends_with(ext))
            return true;
    return false;
}

VideoFrames::VideoFrames(const std::string &path)
    : m_capture(std::make_unique<cv::VideoCapture>(path, cv::CAP_FFMPEG))
{
    if (!m_capture->isOpened())
        throw Error("cannot open the video", path);
    m_frameCount = int(m_capture->get(cv::CAP_PROP_FRAME_COUNT));
    m_frameRate = m_capture->get(cv::CAP_PROP_FPS);
}

VideoFrames::~VideoFrames() = default;

bool VideoFrames::next(cv::Mat &frame)
{
    if (!m_capture->grab())
        return false;
    m_capture->retrieve(frame);
    return true;
}

} // namespace lipsync::cli
