#include "render/FaceRenderer.h"

#include "aam/FaceDetector.h"
#include "aam/LandmarkScheme.h"
#include "aam/VideoTracking.h"
#include "io/VideoReader.h"
#include "render/FrameComposition.h"
#include "render/LowerFaceWarp.h"
#include "render/PostureTransfer.h"
#include "tasks/Feedback.h"
#include "util/Error.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace lipsync {

namespace {

// Half-width of the moving average over the per-frame poses: the tracker's frame-to-frame
// jitter (a pixel or so) would otherwise make the pasted face shimmer against the background.
constexpr int kPoseSmoothing = 2;
// A fit this many times worse than the video's median marks a covered face [choice]: on the demo
// clips a blink raises the fit error to 5-15 times the median, a block over the mouth to 50-60.
constexpr double kOccludedFit = 25.0;
// ... and this many times worse than its upper quartile [choice]. A covered mouth is a rare
// outlier; an AAM built from few frames of a person can fit every wide-open mouth 25 times worse
// than the closed ones (HD weekly addresses: 40-60 % of a clip's frames), and those frames are
// the speech itself, not covered.
constexpr double kOccludedFitOverUpperQuartile = 4.0;
// Below this share of the recorded inner-lip opening, a generated mouth is drawn closed by the
// AAM (mouthInteriorAlpha) [choice].
constexpr double kClosingRatio = 0.5;
// The drawn inside of a mouth opened wider than recorded reaches full weight where the recording
// lacks this share of the generated opening (mouthInteriorAlpha). [choice: on 40 development GRID
// clips, with 1 (the weight rising over the whole range) a mouth asked to open from a half-open
// one read 57 % of the opening asked (dlib), with 1/3 75 %; the recording's stretched inside
// reads as less open than the person's own inside at that opening.]
constexpr double kInsideFullAt = 1.0 / 3.0;
// The drawn inside's feather (pixels): an edge of about a pixel, inside the lips' inner outline.
constexpr double kInsideFeather = 0.8;
// The drawn inside fades out toward the mouth's corners over this outer share of each half of the
// mouth's width, to nothing at the corner (insideAlpha). [choice: where the lips meet, the
// recording's own lips moved apart are the person's; a tracked corner a few pixels off the
// visible one (rounded lips on HD) would put the drawn inside's dark tip on the lips beside it.
// With 0.4 no such tip shows in the HD frames looked at, and the GRID figures hold
// (docs/performance.md).]
constexpr double kInsideCornerTaper = 0.4;

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
    // Frames whose face is lost or covered: no face found, or a fit far worse than the video's usual.
    m_occluded = occludedFrames(tracked.errors);
    for (int t : tracked.framesWithoutFace)
        if (t >= 0 && t < int(m_occluded.size()))
            m_occluded[size_t(t)] = true;
    std::vector<bool> usable(m_occluded.size());
    std::transform(m_occluded.begin(), m_occluded.end(), usable.begin(), [](bool o) { return !o; });
    m_mouths = MouthExemplars(*m_video, tracked.shapes, usable);
    Eigen::MatrixXd seen = m_tracked;
    for (Eigen::Index t = 0; t < seen.rows(); ++t)
        if (t < Eigen::Index(m_occluded.size()) && m_occluded[size_t(t)])
            seen.row(t).setConstant(std::nan(""));
    m_posture = PostureTransfer::slowPosture(seen, m_video->timestamps());
}

Eigen::VectorXd FaceRenderer::posture(int index) const
{
    if (m_posture.rows() == 0)
        return {};
    return m_posture.row(std::clamp<Eigen::Index>(sourceFrame(index), 0, m_posture.rows() - 1)).transpose();
}

std::vector<bool> FaceRenderer::occludedFrames(const Eigen::VectorXd &errors)
{
    std::vector<double> finite;
    for (Eigen::Index t = 0; t < errors.size(); ++t)
        if (std::isfinite(errors[t]))
            finite.push_back(errors[t]);
    std::sort(finite.begin(), finite.end());
    auto quantile = [&finite](double q) {
        return finite.empty() ? 0.0 : finite[size_t(q * double(finite.size() - 1))];
    };
    const double median = quantile(0.5);
    const double upperQuartile = quantile(0.75);
    std::vector<bool> occluded(size_t(errors.size()), false);
    for (Eigen::Index t = 0; t < errors.size(); ++t) {
        const double e = errors[t];
        occluded[size_t(t)] = !std::isfinite(e)
                              || (median > 0 && e > kOccludedFit * median && e > kOccludedFitOverUpperQuartile * upperQuartile);
    }
    return occluded;
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

void FaceRenderer::retime(int frames, const BackgroundRetimingOptions &options)
{
    m_retiming = retimingFor(frames, options);
}

BackgroundRetiming FaceRenderer::retimingFor(int frames, const BackgroundRetimingOptions &options) const
{
    return m_video && frames > 0 ? retimeBackground(m_poses, frames, options) : BackgroundRetiming{};
}

int FaceRenderer::sourceFrame(int index) const
{
    if (m_retiming.frames.empty())
        return index;
    return m_retiming.frames[size_t(std::clamp(index, 0, int(m_retiming.frames.size()) - 1))];
}

cv::Mat FaceRenderer::background(int index)
{
    if (!m_video)
        return m_neutral.clone();
    const int clamped = std::clamp(sourceFrame(index), 0, m_frameCount - 1);
    if (clamped != m_lastIndex) {
        m_last = m_video->frame(clamped);
        m_lastIndex = clamped;
    }
    return m_last.clone();
}

bool FaceRenderer::occluded(int index) const
{
    if (m_occluded.empty())
        return false;
    return m_occluded[size_t(std::clamp(sourceFrame(index), 0, int(m_occluded.size()) - 1))];
}

const Similarity &FaceRenderer::pose(int index) const
{
    return m_poses[size_t(std::clamp(sourceFrame(index), 0, int(m_poses.size()) - 1))];
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
    if (occluded(index))
        return; // what covers the face stays in front of it
    if (options.synthesisesFace()) {
        m_synthesizer.composite(features, drawnPose(index, features), frame, options);
        return;
    }
    // The recording's own lower face moved to the generated lips' opening and width, then the
    // inside of the mouth where the recording had less of it.
    const Eigen::VectorXd tracked = trackedShape(index);
    const Eigen::VectorXd generated = warpedShape(index, features);
    LowerFaceWarp::apply(frame, tracked, generated);
    bool closing = false;
    const cv::Mat alpha = mouthInteriorAlpha(generated, tracked, &closing);
    cv::Rect box = cv::boundingRect(alpha > 0.f);
    if (box.empty())
        return;
    cv::Mat synthesised = frame.clone();
    // Closed lips, or the inside of the mouth: the person's own from another moment of the video,
    // where it has them.
    int exemplar = -1;
    if (m_video && (closing ? options.recordedClosures : options.recordedInsides)) {
        const double time = m_video->timestamp(sourceFrame(index));
        exemplar = closing ? m_mouths.chooseClosed(time)
                           : m_mouths.chooseOpen(time, MouthExemplars::openingShare(generated));
    }
    // The person's own open mouth is drawn with its lips, moved onto the generated ones, around
    // it: what its colour is matched on.
    bool ownInside = exemplar >= 0 && !closing;
    if (ownInside)
        box = (box | cv::boundingRect(LowerFaceWarp::outerLips(generated, 0.0))) & cv::Rect(cv::Point(0, 0), m_size);
    cv::Mat patch = synthesised(box);
    if (exemplar < 0 || !m_mouths.draw(exemplar, generated, box, patch)) {
        ownInside = false;
        CompositeOptions whole = options;
        whole.region = FaceRegion::Full;
        m_synthesizer.composite(features, drawnPose(index, features), synthesised, whole);
    }
    // The synthesis's colour matched to the frame's where they meet: the mean difference over
    // the feathered band (alpha between 0.02 and 0.5: the edge of what is fully drawn, all of a
    // faint blend), added to what is drawn (the face-wide colour matching sees the face's
    // outline, not the lips). For the person's own open mouth, over its lips instead, against the
    // frame's moved lips (at the inside's edge its dark inside would meet the frame's lips).
    double shift[3] = {0, 0, 0};
    if (options.matchColour) {
        cv::Mat lips; // the box's pixels inside the generated outer lips
        if (ownInside) {
            lips = cv::Mat(box.size(), CV_8U, cv::Scalar(0));
            auto fill = [&lips, &box](const std::vector<cv::Point2f> &polygon, double value) {
                std::vector<cv::Point> outline;
                for (const cv::Point2f &p : polygon)
                    outline.emplace_back(int(std::lround(p.x)) - box.x, int(std::lround(p.y)) - box.y);
                cv::fillPoly(lips, std::vector<std::vector<cv::Point>>{outline}, cv::Scalar(value));
            };
            // The lips only: not the inside, faint toward the corners, which is no lip.
            fill(LowerFaceWarp::outerLips(generated, 0.0), 255);
            fill(LowerFaceWarp::mouthInterior(generated), 0);
        }
        double sum[3] = {0, 0, 0};
        long count = 0;
        for (int y = box.y; y < box.y + box.height; ++y) {
            const float *a = alpha.ptr<float>(y);
            const uchar *onLips = ownInside ? lips.ptr<uchar>(y - box.y) : nullptr;
            const uchar *out = frame.ptr<uchar>(y), *in = synthesised.ptr<uchar>(y);
            for (int x = box.x; x < box.x + box.width; ++x)
                if (onLips ? onLips[x - box.x] && a[x] < 0.02f : a[x] > 0.02f && a[x] < 0.5f) {
                    for (int ch = 0; ch < 3; ++ch)
                        sum[ch] += double(out[3 * x + ch]) - double(in[3 * x + ch]);
                    ++count;
                }
        }
        if (count > 0)
            for (int ch = 0; ch < 3; ++ch)
                shift[ch] = sum[ch] / double(count);
    }
    for (int y = box.y; y < box.y + box.height; ++y) {
        const float *a = alpha.ptr<float>(y);
        uchar *out = frame.ptr<uchar>(y);
        const uchar *in = synthesised.ptr<uchar>(y);
        for (int x = box.x; x < box.x + box.width; ++x)
            if (a[x] > 0.f)
                for (int ch = 0; ch < 3; ++ch)
                    out[3 * x + ch] = cv::saturate_cast<uchar>(a[x] * (in[3 * x + ch] + shift[ch])
                                                               + (1.f - a[x]) * out[3 * x + ch]);
    }
}

Eigen::VectorXd FaceRenderer::trackedShape(int index) const
{
    const Eigen::VectorXd c = m_tracked.rows() > 0
                                  ? Eigen::VectorXd(m_tracked.row(std::clamp<Eigen::Index>(sourceFrame(index), 0, m_tracked.rows() - 1)).transpose())
                                  : Eigen::VectorXd::Zero(m_aam.combinedModes());
    return pose(index).apply(m_synthesizer.shape(c));
}

Similarity FaceRenderer::drawnPose(int index, const Eigen::VectorXd &features) const
{
    return alignByEyes(m_synthesizer.shape(features), trackedShape(index));
}

Eigen::VectorXd FaceRenderer::drawnShape(int index, const Eigen::VectorXd &features) const
{
    const Eigen::VectorXd shape = m_synthesizer.shape(features);
    return alignByEyes(shape, trackedShape(index)).apply(shape);
}

Eigen::VectorXd FaceRenderer::warpedShape(int index, const Eigen::VectorXd &features) const
{
    return LowerFaceWarp::speechShape(trackedShape(index), drawnShape(index, features));
}

Eigen::VectorXd FaceRenderer::renderedShape(int index, const Eigen::VectorXd &features, const CompositeOptions &options) const
{
    return options.synthesisesFace() ? drawnShape(index, features) : warpedShape(index, features);
}

cv::Mat FaceRenderer::featheredPolygon(const std::vector<cv::Point2f> &outline, double feather, float weight,
                                       cv::Rect *reach) const
{
    constexpr int kShift = 4; // fillPoly's sub-pixel bits
    std::vector<cv::Point> polygon;
    for (const cv::Point2f &p : outline)
        polygon.emplace_back(int(std::lround(p.x * (1 << kShift))), int(std::lround(p.y * (1 << kShift))));
    cv::Mat mask(m_size, CV_8U, cv::Scalar(0));
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{polygon}, cv::Scalar(255), cv::LINE_AA, kShift);
    const int radius = int(std::ceil(2.0 * feather));
    cv::GaussianBlur(mask, mask, cv::Size(2 * radius + 1, 2 * radius + 1), feather);
    if (reach) {
        // The outline's box, grown by the blur's radius and a pixel each for the anti-aliased edge
        // and the rounding.
        const int grow = radius + 2;
        const cv::Rect box = cv::boundingRect(outline);
        *reach = cv::Rect(box.x - grow, box.y - grow, box.width + 2 * grow, box.height + 2 * grow)
                 & cv::Rect(cv::Point(0, 0), m_size);
    }
    cv::Mat alpha;
    mask.convertTo(alpha, CV_32F, weight / 255.0);
    return alpha;
}

cv::Mat FaceRenderer::insideWeight(const Eigen::VectorXd &shape) const
{
    return insideAlpha(shape, 1.f);
}

cv::Mat FaceRenderer::insideAlpha(const Eigen::VectorXd &shape, float weight) const
{
    cv::Rect box;
    cv::Mat alpha = featheredPolygon(LowerFaceWarp::mouthInterior(shape), kInsideFeather, weight, &box);
    // Faded toward the corners: s is a pixel's place along the mouth, 0 midway between the
    // corners and 1 at either; the weight falls smoothly from 1 at 1 - kInsideCornerTaper to 0.
    using namespace scheme23;
    const Eigen::Vector2d left = shape.segment<2>(2 * kMouthLeft), right = shape.segment<2>(2 * kMouthRight);
    const Eigen::Vector2d centre = 0.5 * (left + right), half = 0.5 * (right - left);
    const double halfSquared = half.squaredNorm();
    if (halfSquared < 1.0)
        return alpha;
    for (int y = box.y; y < box.y + box.height; ++y) {
        float *a = alpha.ptr<float>(y);
        for (int x = box.x; x < box.x + box.width; ++x) {
            const double s = std::abs((Eigen::Vector2d(x, y) - centre).dot(half)) / halfSquared;
            const double u = std::clamp((1.0 - s) / kInsideCornerTaper, 0.0, 1.0);
            a[x] *= float(u * u * (3.0 - 2.0 * u));
        }
    }
    return alpha;
}

cv::Mat FaceRenderer::mouthInteriorAlpha(const Eigen::VectorXd &generated, const Eigen::VectorXd &tracked,
                                         bool *closing) const
{
    cv::Mat alpha(m_size, CV_32F, cv::Scalar(0));
    const double wanted = LowerFaceWarp::opening(generated);
    const double recorded = LowerFaceWarp::opening(tracked);
    constexpr double kMinOpening = 1.5; // pixels: a closed mouth has no inside to draw
    if (wanted > kMinOpening && wanted > recorded) {
        // The warp stretches the recorded opening to the generated one: where that is a thin line
        // pulled wide, the inside is drawn; where the recording was as open, it is its own, and
        // between, the drawn inside weighs fully from a recording a third short (kInsideFullAt).
        const double u = std::clamp((wanted - recorded) / (kInsideFullAt * wanted), 0.0, 1.0);
        alpha = insideAlpha(generated, float(u * u * (3.0 - 2.0 * u)));
    } else if (recorded > 2.0 * kMinOpening && wanted < kClosingRatio * recorded) {
        // Lips asked to close far more than the recording's: no warp brings lips together that
        // were apart (it would squeeze the open mouth to a line, or fold), so the closed lips are
        // drawn, blended in over a feathered band beyond the generated lips' outline as the
        // closure grows from half the recorded opening to a tenth of it.
        const double u = std::clamp((kClosingRatio * recorded - wanted) / ((kClosingRatio - 0.1) * recorded), 0.0, 1.0);
        const double width = LowerFaceWarp::mouthWidth(generated);
        if (closing)
            *closing = true;
        alpha = featheredPolygon(LowerFaceWarp::outerLips(generated, 0.12 * width), 0.06 * width,
                                 float(u * u * (3.0 - 2.0 * u)));
    }
    return alpha;
}

cv::Mat FaceRenderer::synthesisedWeight(int index, const Eigen::VectorXd &features, bool *inside, bool *closing) const
{
    if (inside)
        *inside = false;
    if (closing)
        *closing = false;
    if (features.size() != m_aam.combinedModes())
        throw Error("cannot render: " + std::to_string(features.size())
                    + " parameters given, the AAM has " + std::to_string(m_aam.combinedModes()));
    if (occluded(index))
        return cv::Mat(m_size, CV_32F, cv::Scalar(0));
    if (m_composite.synthesisesFace())
        return m_synthesizer.compositeWeight(features, drawnPose(index, features), m_size, m_composite.region);
    bool closed = false;
    cv::Mat alpha = mouthInteriorAlpha(warpedShape(index, features), trackedShape(index), &closed);
    if (inside)
        *inside = !closed && cv::countNonZero(alpha) > 0;
    if (closing)
        *closing = closed;
    return alpha;
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
