#pragma once
// The frames the machine observer judges (MachineObserver): each stream of one sequence — the
// recording and each rendering — is encoded by the exporter of `lipsync export video` and `render`
// (VideoExporter: H.264; losslessly with colour at full resolution, or at an export's quality),
// decoded back, and the mouth's appearance read in the stream's own mouth box. The recording's stream is encoded a second time
// for the control that compares a recording with its own re-encode. Streams are written as their
// frames come (bounded memory) into a temporary folder that goes with the object.
#include "render/VideoExporter.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <QTemporaryDir>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

class EncodedAppearance
{
public:
    // `streams` streams of frames of one size; stream 0 is the recording. Encoded at x264's
    // constant rate factor `crf` (0: lossless, and 4:4:4 so that the colour is not halved either).
    EncodedAppearance(int streams, int crf);
    ~EncodedAppearance();
    EncodedAppearance(const EncodedAppearance &) = delete;
    EncodedAppearance &operator=(const EncodedAppearance &) = delete;

    void add(int stream, const cv::Mat &frame);

    struct Result
    {
        std::vector<Eigen::MatrixXf> streams; // one row per measured frame
        Eigen::MatrixXf reencoded;            // the recording's second encode
    };
    // Every `step`-th frame with a mouth box in the recording (boxes[0][t]), from every stream,
    // each read in its own box (boxes[s][t], the recording's where a stream has none).
    Result appearance(const std::vector<std::vector<std::optional<cv::Rect2d>>> &boxes, int step);

private:
    std::string path(int stream) const;

    QTemporaryDir m_folder;
    std::vector<std::unique_ptr<VideoExporter>> m_exporters;
    VideoExportOptions m_options;
};

} // namespace lipsync
