#include "render/FaceRenderer.h"

#include "aam/FaceDetector.h"
#include "aam/VideoTracking.h"
#include "io/VideoReader.h"
#include "render/FrameComposition.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <algorithm>

namespace lipsync {

namespace {

// Half-width of the moving average over the per-frame poses: the tracker's frame-to-frame
// jitter (a pixel or so) would otherwise make the pasted face shimmer against the background.
constexpr int kPoseSmoothing = 2;

std::vector<Similarity> smoothPoses(const std::vector<Similarity> &poses)
{
    std::vector<Similarity> out(poses.size());
    const int n = int(poses.size());
    for (int i = 0; i < n; ++i) {
        Similarity sum{0, 0, 0, 0};
        int count = 0;
        for (int j = std::max(0, i - kPoseSmoothing); j <= std::min(n - 1, i + kPoseSmoothing); ++j) {
            sum.a += poses[size_t(j)].a;
            sum.b += poses[size_t(j)].b;
            sum.tx += poses[size_t(j)].tx;
            sum.ty += poses[size_t(j)].ty;
            ++count;
        }
        out[size_t(i)] = Similarity{sum.a / count, sum.b / count, sum.tx / count, sum.ty / count};
    }
    return out;
}

} // namespace

FaceRenderer::FaceRenderer(const AamModel &aam, cv::Size size)
    : m_aam(aam), m_synthesizer(aam), m_size(size)
{
    if (size.width < 16 || size.height < 16)
        throw Error("cannot render: the frame is too small");
    // The mean face centred, its points spanning half the frame height.
    const Eigen::VectorXd &mean = aam.meanShape;
    double top = 1e9, bottom = -1e9;
    for (Eigen::Index i = 1; i < mean.size(); i += 2) {
        top = std::min(top, mean[i]);
        bottom = std::max(bottom, mean[i]);
    }
    const double scale = 0.5 * size.height / std::max(1e-6, bottom - top);
    const Eigen::Vector2d centre = shapeCentroid(mean);
    m_poses = {Similarity{scale, 0.0, 0.5 * size.width - scale * centre.x(),
                          0.5 * size.height - scale * centre.y()}};
    // The whole mean face (eyes included, no frame to take them from), then each frame's lower
    // face over it as into a video.
    m_neutral = cv::Mat(size, CV_8UC3, cv::Scalar(128, 128, 128));
    CompositeOptions whole;
    whole.region = FaceRegion::Full;
    whole.matchColour = false;
    m_synthesizer.composite(Eigen::VectorXd::Zero(aam.combinedModes()), m_poses[0], m_neutral, whole);
}

FaceRenderer::FaceRenderer(const AamModel &aam, const std::string &videoPath, Feedback &feedback,
                           FaceDetector *detector, int frames)
    : m_aam(aam), m_synthesizer(aam)
{
    m_video = std::make_unique<VideoReader>(videoPath);
    m_size = cv::Size(m_video->width(), m_video->height());
    m_frameCount = frames > 0 ? std::min(frames, m_video->frameCount()) : m_video->frameCount();
    std::unique_ptr<FaceDetector> ownDetector;
    if (!detector) {
        ownDetector = std::make_unique<FaceDetector>(FaceDetectorPaths::boxesOnly());
        detector = ownDetector.get();
    }
    feedback.setStatus("Tracking the face in " + videoPath);
    const VideoTrackingResult tracked = trackVideo(aam, videoPath, *detector, feedback, {}, m_frameCount);
    m_tracked = tracked.features;
    // The pose of each frame: the similarity taking the shape the tracked parameters imply (in
    // model coordinates) onto the fitted points.
    std::vector<Similarity> poses;
    for (Eigen::Index t = 0; t < tracked.shapes.rows(); ++t)
        poses.push_back(alignSimilarity(m_synthesizer.shape(m_tracked.row(t).transpose()),
                                        tracked.shapes.row(t).transpose()));
    if (poses.empty())
        throw Error("cannot render: no frame of the video holds a face", videoPath);
    m_poses = smoothPoses(poses);
}

FaceRenderer::~FaceRenderer() = default;

bool FaceRenderer::hasVideo() const
{
    return bool(m_video);
}

int FaceRenderer::videoFrameCount() const
{
    return m_video ? m_frameCount : 0;
}

double FaceRenderer::videoFrameRate() const
{
    return m_video ? m_video->frameRate() : 0.0;
}

cv::Size FaceRenderer::frameSize() const
{
    return m_size;
}

cv::Mat FaceRenderer::background(int index)
{
    if (!m_video)
        return m_neutral.clone();
    const int clamped = std::clamp(index, 0, m_frameCount - 1);
    if (clamped != m_lastIndex) {
        m_last = m_video->frame(clamped);
        m_lastIndex = clamped;
    }
    return m_last.clone();
}

const Similarity &FaceRenderer::pose(int index) const
{
    return m_poses[size_t(std::clamp(index, 0, int(m_poses.size()) - 1))];
}

void FaceRenderer::renderInto(int index, const Eigen::VectorXd &features, cv::Mat &frame) const
{
    renderInto(index, features, frame, m_composite);
}

void FaceRenderer::renderInto(int index, const Eigen::VectorXd &features, cv::Mat &frame,
                              const CompositeOptions &options) const
{
    if (features.size() != m_aam.combinedModes())
        throw Error("cannot render: " + std::to_string(features.size())
                    + " parameters given, the AAM has " + std::to_string(m_aam.combinedModes()));
    if (frame.type() != CV_8UC3 || frame.size() != m_size)
        throw Error("cannot render: the frame is not a " + std::to_string(m_size.width) + "x"
                    + std::to_string(m_size.height) + " BGR image");
    m_synthesizer.composite(features, pose(index), frame, options);
}

cv::Mat FaceRenderer::synthesisedWeight(int index, const Eigen::VectorXd &features) const
{
    if (features.size() != m_aam.combinedModes())
        throw Error("cannot render: " + std::to_string(features.size())
                    + " parameters given, the AAM has " + std::to_string(m_aam.combinedModes()));
    return m_synthesizer.compositeWeight(features, pose(index), m_size, m_composite.region);
}

cv::Mat FaceRenderer::render(int index, const Eigen::VectorXd &features)
{
    cv::Mat frame = background(index);
    renderInto(index, features, frame);
    return frame;
}

cv::Mat FaceRenderer::renderSideBySide(int index, const Eigen::VectorXd &features,
                                       const std::string &leftLabel, const std::string &rightLabel)
{
    const cv::Mat real = background(index);
    cv::Mat generated = real.clone();
    renderInto(index, features, generated);
    return composeSideBySide(real, generated, leftLabel, rightLabel);
}

} // namespace lipsync
