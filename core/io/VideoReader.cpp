#include "io/VideoReader.h"

#include "io/LibAv.h"
#include "util/Error.h"

#include <opencv2/videoio.hpp>

#include <cmath>

namespace lipsync {

namespace {
// Up to this many frames ahead, decoding forward is cheaper than seeking (and exact).
constexpr int kMaxForwardDecode = 48;
} // namespace

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
    m_videoStart = scan->videoStreamStart;
    m_capture = std::make_unique<cv::VideoCapture>();
    reopen();
    if (m_width <= 0 || m_height <= 0) {
        m_width = int(m_capture->get(cv::CAP_PROP_FRAME_WIDTH));
        m_height = int(m_capture->get(cv::CAP_PROP_FRAME_HEIGHT));
    }
}

VideoReader::~VideoReader() = default;

void VideoReader::reopen()
{
    m_capture->release();
    if (!m_capture->open(m_path, cv::CAP_FFMPEG))
        throw Error("OpenCV cannot open the video (unsupported codec or container)", m_path);
    libav::quietLogs(); // OpenCV sets the libav log level when it first opens a file
    m_nextIndex = 0;
}

cv::Mat VideoReader::readNext()
{
    cv::Mat image; // a fresh matrix each time: the caller keeps the previous frames
    if (!m_capture->read(image) || image.empty())
        throw Error("cannot decode frame " + std::to_string(m_nextIndex) + " of "
                        + std::to_string(m_frameCount) + " (corrupt or truncated file)",
                    m_path);
    ++m_nextIndex;
    return image;
}

bool VideoReader::seekTo(int index, cv::Mat &image)
{
    // OpenCV's seek is not frame-exact on MPEG program streams (GRID): it can land a few frames
    // off near the start. Accept it only when the decoded frame's timestamp is the one wanted.
    if (!m_capture->set(cv::CAP_PROP_POS_FRAMES, index))
        return false;
    cv::Mat candidate;
    if (!m_capture->read(candidate) || candidate.empty())
        return false;
    const double got = m_capture->get(cv::CAP_PROP_POS_MSEC) / 1000.0;
    const double want = m_clock.time(index) - m_videoStart;
    const double tolerance = m_frameRate > 0 ? 0.25 / m_frameRate : 0.001;
    if (std::abs(got - want) > tolerance)
        return false;
    image = candidate;
    m_nextIndex = index + 1;
    return true;
}

cv::Mat VideoReader::frame(int index)
{
    if (index < 0 || index >= m_frameCount)
        throw Error("frame " + std::to_string(index) + " out of range (the video has "
                        + std::to_string(m_frameCount) + " frames)",
                    m_path);
    if (index < m_nextIndex || index - m_nextIndex > kMaxForwardDecode) {
        if (index > kMaxForwardDecode) {
            cv::Mat image;
            if (seekTo(index, image))
                return image;
        }
        reopen(); // exact: decode forward from the first frame
    }
    while (m_nextIndex < index) {
        if (!m_capture->grab())
            throw Error("cannot decode frame " + std::to_string(m_nextIndex) + " of "
                            + std::to_string(m_frameCount) + " (corrupt or truncated file)",
                        m_path);
        ++m_nextIndex;
    }
    return readNext();
}

double VideoReader::timestamp(int index) const
{
    return m_clock.time(index);
}

} // namespace lipsync
