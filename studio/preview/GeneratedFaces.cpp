#include "preview/GeneratedFaces.h"

#include "aam/PtsFile.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace lipsync::studio {

GeneratedFaces::GeneratedFaces(std::shared_ptr<const AamModel> aam, std::shared_ptr<const FaceRenderer> renderer,
                               const FrameClock &frames)
    : m_aam(std::move(aam)), m_renderer(std::move(renderer)),
      m_frames(frames.rate() > 0 ? frames : FrameClock::uniform(25.0, frames.count()))
{
}

void GeneratedFaces::setFixedFrame(const QImage &background, int poseFrame)
{
    m_fixed = background.convertToFormat(QImage::Format_RGB888);
    m_fixedPose = std::max(0, poseFrame);
}

void GeneratedFaces::setRetimedBackground(std::vector<int> frames, QVector<QImage> images)
{
    m_retimed = std::move(frames);
    m_retimedImages = std::move(images);
    m_fixed = QImage();
    m_fixedPose = -1;
}

int GeneratedFaces::frameCount() const
{
    Eigen::Index n = 0;
    for (const Track &t : m_tracks)
        n = std::max(n, t.params.rows());
    return int(n);
}

Eigen::VectorXd GeneratedFaces::paramsAt(int track, int frame) const
{
    const Track &t = m_tracks[std::size_t(track)];
    const Eigen::VectorXd c = t.params.row(std::clamp(frame, 0, int(t.params.rows()) - 1)).transpose();
    return t.posture ? t.posture->apply(c, m_renderer->posture(poseFrame(frame))) : c;
}

QImage GeneratedFaces::render(int track, int frame, const CompositeOptions &options, const QImage &background) const
{
    if (track < 0 || track >= int(m_tracks.size()) || m_tracks[std::size_t(track)].params.rows() == 0)
        return {};
    const QImage *source = &background;
    if (!m_fixed.isNull())
        source = &m_fixed;
    else if (!m_retimed.empty() && poseFrame(frame) < m_retimedImages.size())
        source = &m_retimedImages[poseFrame(frame)];
    QImage out = source->convertToFormat(QImage::Format_RGB888);
    if (out.isNull())
        return {};
    const cv::Size size = m_renderer->frameSize();
    if (out.width() != size.width || out.height() != size.height) // a downscaled huge clip
        out = out.scaled(size.width, size.height, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
    out.detach();
    // The renderer draws BGR: into a BGR copy, then back into the RGB image.
    cv::Mat rgb(out.height(), out.width(), CV_8UC3, out.bits(), std::size_t(out.bytesPerLine()));
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    m_renderer->renderInto(poseFrame(frame), paramsAt(track, frame), bgr, options);
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return out;
}

LandmarkSet GeneratedFaces::landmarks(int track, int frame, const CompositeOptions &options) const
{
    if (track < 0 || track >= int(m_tracks.size()) || m_tracks[std::size_t(track)].params.rows() == 0)
        return {};
    return landmarkSetFromShape(m_renderer->renderedShape(poseFrame(frame), paramsAt(track, frame), options), PointState::Automatic);
}

std::optional<LandmarkSet> GeneratedFaces::trackedLandmarks(int frame) const
{
    const Eigen::MatrixXd &tracked = m_renderer->trackedFeatures();
    if (m_fixedPose >= 0 || !m_retimed.empty() || tracked.rows() == 0 || frame < 0)
        return std::nullopt;
    const int row = std::min(frame, int(tracked.rows()) - 1);
    return landmarkSetFromShape(m_renderer->trackedShape(row), PointState::Automatic);
}

} // namespace lipsync::studio
