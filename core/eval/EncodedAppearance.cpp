#include "eval/EncodedAppearance.h"

#include "eval/MachineObserver.h"
#include "io/VideoReader.h"
#include "util/Error.h"

namespace lipsync {

EncodedAppearance::EncodedAppearance(int streams, int crf)
{
    if (!m_folder.isValid())
        throw Error("no temporary folder for the machine observer's encodes");
    m_options.crf = crf;
    m_options.fullChroma = crf == 0; // lossless: colour not subsampled either
    for (int s = 0; s < streams; ++s)
        m_exporters.push_back(std::make_unique<VideoExporter>(path(s), m_options));
}

EncodedAppearance::~EncodedAppearance() = default;

std::string EncodedAppearance::path(int stream) const
{
    return m_folder.filePath(QStringLiteral("stream%1.mp4").arg(stream)).toStdString();
}

void EncodedAppearance::add(int stream, const cv::Mat &frame)
{
    m_exporters[size_t(stream)]->addFrame(frame);
}

EncodedAppearance::Result EncodedAppearance::appearance(const std::vector<std::vector<std::optional<cv::Rect2d>>> &boxes, int step)
{
    for (auto &exporter : m_exporters)
        exporter->finish();
    auto read = [&](const std::string &file, size_t s, VideoExporter *again) {
        VideoReader reader(file);
        std::vector<Eigen::VectorXf> rows;
        const std::vector<std::optional<cv::Rect2d>> &recorded = boxes.front();
        const std::vector<std::optional<cv::Rect2d>> &own = boxes[std::min(s, boxes.size() - 1)];
        const int frames = std::min(reader.frameCount(), int(recorded.size()));
        for (int t = 0; t < frames; ++t) {
            const bool measured = recorded[size_t(t)] && t % std::max(1, step) == 0;
            if (!measured && !again)
                continue;
            const cv::Mat frame = reader.frame(t);
            if (again)
                again->addFrame(frame);
            if (measured)
                rows.push_back(mouthAppearance(frame, size_t(t) < own.size() && own[size_t(t)] ? *own[size_t(t)]
                                                                                                : *recorded[size_t(t)]));
        }
        Eigen::MatrixXf out(Eigen::Index(rows.size()), rows.empty() ? 0 : rows.front().size());
        for (size_t i = 0; i < rows.size(); ++i)
            out.row(Eigen::Index(i)) = rows[i].transpose();
        return out;
    };
    Result result;
    const std::string second = m_folder.filePath(QStringLiteral("recording-again.mp4")).toStdString();
    VideoExporter again(second, m_options);
    for (size_t s = 0; s < m_exporters.size(); ++s)
        result.streams.push_back(read(path(int(s)), s, s == 0 ? &again : nullptr));
    again.finish();
    result.reencoded = read(second, 0, nullptr);
    return result;
}

} // namespace lipsync
