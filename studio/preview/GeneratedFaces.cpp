#include "preview/GeneratedFaces.h"

#include "aam/Procrustes.h"
#include "aam/PtsFile.h"
#include "aam/VideoTracking.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>

namespace lipsync::studio {

SequencePoses posesFromTracking(const AamSynthesizer &synthesizer, const VideoTrackingResult &tracking)
{
    SequencePoses out;
    out.shapes = tracking.shapes;
    out.poses.reserve(std::size_t(tracking.features.rows()));
    for (Eigen::Index t = 0; t < tracking.features.rows(); ++t) {
        const Eigen::VectorXd model = synthesizer.shape(tracking.features.row(t).transpose());
        out.poses.push_back(alignSimilarity(model, tracking.shapes.row(t).transpose()));
    }
    return out;
}

GeneratedFaces::GeneratedFaces(std::shared_ptr<const AamModel> aam, double frameRate)
    : m_aam(std::move(aam)), m_synth(std::make_unique<AamSynthesizer>(*m_aam)),
      m_frameRate(frameRate > 0 ? frameRate : 25.0)
{
}

void GeneratedFaces::setNeutralFrame(const QImage &background, const Similarity &pose)
{
    m_neutral = background.convertToFormat(QImage::Format_RGB888);
    m_neutralPose = pose;
}

void GeneratedFaces::setMeanFaceFrame(QSize size)
{
    QImage grey(size, QImage::Format_RGB888);
    grey.fill(QColor(0x80, 0x80, 0x80));
    // The mean face fills 60% of the height, centred.
    const Eigen::VectorXd &s = m_aam->meanShape;
    double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
    for (Eigen::Index i = 0; i + 1 < s.size(); i += 2) {
        minX = std::min(minX, s[i]);
        maxX = std::max(maxX, s[i]);
        minY = std::min(minY, s[i + 1]);
        maxY = std::max(maxY, s[i + 1]);
    }
    Similarity pose;
    pose.a = 0.6 * size.height() / std::max(1e-9, maxY - minY);
    pose.b = 0.0;
    pose.tx = size.width() / 2.0 - pose.a * (minX + maxX) / 2.0;
    pose.ty = size.height() / 2.0 - pose.a * (minY + maxY) / 2.0;
    setNeutralFrame(grey, pose);
}

int GeneratedFaces::frameCount() const
{
    Eigen::Index n = 0;
    for (const Track &t : m_tracks)
        n = std::max(n, t.params.rows());
    return int(n);
}

Similarity GeneratedFaces::poseAt(int frame) const
{
    if (!m_neutral.isNull() || !m_poses || m_poses->poses.empty())
        return m_neutralPose;
    return m_poses->poses[std::size_t(std::clamp(frame, 0, int(m_poses->poses.size()) - 1))];
}

Eigen::VectorXd GeneratedFaces::paramsAt(int track, int frame) const
{
    const Eigen::MatrixXd &p = m_tracks[std::size_t(track)].params;
    return p.row(std::clamp(frame, 0, int(p.rows()) - 1)).transpose();
}

QImage GeneratedFaces::render(int track, int frame, const QImage &background) const
{
    if (track < 0 || track >= int(m_tracks.size()) || m_tracks[std::size_t(track)].params.rows() == 0)
        return {};
    QImage out = (m_neutral.isNull() ? background : m_neutral).convertToFormat(QImage::Format_RGB888);
    if (out.isNull())
        return {};
    out.detach();
    // The synthesiser draws BGR; draw into a BGR view of the RGB image and swap back.
    cv::Mat rgb(out.height(), out.width(), CV_8UC3, out.bits(), std::size_t(out.bytesPerLine()));
    cv::Mat bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    m_synth->composite(paramsAt(track, frame), poseAt(frame), bgr);
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return out;
}

LandmarkSet GeneratedFaces::landmarks(int track, int frame) const
{
    if (track < 0 || track >= int(m_tracks.size()) || m_tracks[std::size_t(track)].params.rows() == 0)
        return {};
    return landmarkSetFromShape(poseAt(frame).apply(m_synth->shape(paramsAt(track, frame))), PointState::Automatic);
}

std::optional<LandmarkSet> GeneratedFaces::trackedLandmarks(int frame) const
{
    if (!m_poses || m_poses->shapes.rows() == 0 || frame < 0)
        return std::nullopt;
    const int row = std::min(frame, int(m_poses->shapes.rows()) - 1);
    return landmarkSetFromShape(m_poses->shapes.row(row).transpose(), PointState::Automatic);
}

} // namespace lipsync::studio
