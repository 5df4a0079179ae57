#include "render/ClosedLipExemplars.h"

#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"
#include "render/LowerFaceWarp.h"
#include "util/Error.h"

#include <Eigen/QR>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace lipsync {

namespace {

constexpr int kFirstMouthPoint = scheme23::kMouthLeft; // mouth_left .. inner_lip_bottom: 8..17
constexpr int kMouthPoints = 10;
// The crop reaches this many mouth widths beyond the outer lips on every side [choice: the
// drawn lips' feathered band ends within 0.3 widths, FaceRenderer::mouthInteriorAlpha].
constexpr double kCropMargin = 0.6;

} // namespace

ClosedLipExemplars::ClosedLipExemplars(VideoReader &video, const Eigen::MatrixXd &shapes,
                                       const std::vector<bool> &usable)
{
    const int frames = int(std::min<Eigen::Index>(shapes.rows(), video.frameCount()));
    std::vector<std::pair<double, int>> closed; // (gap over width, frame)
    for (int t = 0; t < frames; ++t) {
        const Eigen::VectorXd shape = shapes.row(t).transpose();
        if ((size_t(t) < usable.size() && !usable[size_t(t)]) || shape.size() != 2 * scheme23::kPointCount
            || !shape.allFinite())
            continue;
        if (LowerFaceWarp::mouthWidth(shape) < 4.0)
            continue;
        const double share = openingShare(shape);
        if (share <= kClosedShare)
            closed.emplace_back(share, t);
    }
    std::sort(closed.begin(), closed.end());
    std::vector<int> chosen;
    for (const auto &[share, t] : closed) {
        if (int(chosen.size()) >= kMaxExemplars)
            break;
        const double time = video.timestamp(t);
        if (std::none_of(chosen.begin(), chosen.end(),
                         [&](int c) { return std::abs(video.timestamp(c) - time) < kSpacingSeconds; }))
            chosen.push_back(t);
    }
    std::sort(chosen.begin(), chosen.end());
    const cv::Rect image(0, 0, video.width(), video.height());
    for (int t : chosen) {
        Exemplar e;
        e.frame = t;
        e.time = video.timestamp(t);
        e.shape = shapes.row(t).transpose();
        const std::vector<cv::Point2f> lips = LowerFaceWarp::outerLips(e.shape, 0.0);
        const cv::Rect lipBox = cv::boundingRect(lips);
        const int margin = int(std::ceil(kCropMargin * LowerFaceWarp::mouthWidth(e.shape)));
        const cv::Rect box = cv::Rect(lipBox.x - margin, lipBox.y - margin, lipBox.width + 2 * margin,
                                      lipBox.height + 2 * margin)
                             & image;
        if (box.width < 8 || box.height < 8)
            continue;
        try {
            e.crop = video.frame(t)(box).clone();
        } catch (const Error &) {
            continue; // a frame the tracker read but that does not decode again: no exemplar from it
        }
        e.offset = box.tl();
        m_exemplars.push_back(std::move(e));
    }
}

double ClosedLipExemplars::openingShare(const Eigen::VectorXd &shape)
{
    return std::max(0.0, LowerFaceWarp::opening(shape)) / LowerFaceWarp::mouthWidth(shape);
}

std::vector<int> ClosedLipExemplars::frames() const
{
    std::vector<int> out;
    for (const Exemplar &e : m_exemplars)
        out.push_back(e.frame);
    return out;
}

int ClosedLipExemplars::choose(double time) const
{
    int best = -1;
    double bestDistance = 0.0;
    for (size_t i = 0; i < m_exemplars.size(); ++i) {
        const double d = std::abs(m_exemplars[i].time - time);
        if (d >= kAwaySeconds && (best < 0 || d < bestDistance)) {
            best = int(i);
            bestDistance = d;
        }
    }
    return best;
}

bool ClosedLipExemplars::draw(int which, const Eigen::VectorXd &generated, const cv::Rect &box, cv::Mat &patch) const
{
    if (which < 0 || which >= int(m_exemplars.size()) || generated.size() != 2 * scheme23::kPointCount
        || !generated.allFinite() || patch.type() != CV_8UC3 || patch.size() != box.size())
        return false;
    const Exemplar &e = m_exemplars[size_t(which)];
    // The affine map from the crop's pixels to the box's that takes the exemplar's mouth points
    // nearest the generated ones (least squares over the ten points, x and y each).
    Eigen::MatrixXd from(kMouthPoints, 3);
    Eigen::MatrixXd to(kMouthPoints, 2);
    for (int k = 0; k < kMouthPoints; ++k) {
        const int i = kFirstMouthPoint + k;
        from.row(k) << e.shape[2 * i] - e.offset.x, e.shape[2 * i + 1] - e.offset.y, 1.0;
        to.row(k) << generated[2 * i] - box.x, generated[2 * i + 1] - box.y;
    }
    const Eigen::MatrixXd map = from.colPivHouseholderQr().solve(to); // 3 x 2
    const double det = map(0, 0) * map(1, 1) - map(1, 0) * map(0, 1);
    if (!map.allFinite() || det < 1.0 / 16.0 || det > 16.0)
        return false;
    const cv::Matx23d affine(map(0, 0), map(1, 0), map(2, 0), map(0, 1), map(1, 1), map(2, 1));
    // Lanczos, as the lower face's warp (ThinPlateWarp): a bilinear lookup at sub-pixel offsets
    // softens the recorded lips it moves.
    cv::warpAffine(e.crop, patch, affine, box.size(), cv::INTER_LANCZOS4, cv::BORDER_REPLICATE);
    return true;
}

} // namespace lipsync
