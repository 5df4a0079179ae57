#include "render/MouthExemplars.h"

#include "aam/LandmarkScheme.h"
#include "io/VideoReader.h"
#include "render/LowerFaceWarp.h"
#include "render/ThinPlateWarp.h"
#include "util/Error.h"

#include <Eigen/QR>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace lipsync {

namespace {

constexpr int kFirstMouthPoint = scheme23::kMouthLeft; // mouth_left .. inner_lip_bottom: 8..17
constexpr int kMouthPoints = 10;
// The crop reaches this many mouth widths beyond the outer lips on every side [choice: the
// drawn lips' feathered band ends within 0.3 widths, FaceRenderer::mouthInteriorAlpha].
constexpr double kCropMargin = 0.6;
// The motion of a frame without a usable neighbour: unknown, kept last.
constexpr double kUnknownMotion = 1e9;

} // namespace

MouthExemplars::MouthExemplars(VideoReader &video, const Eigen::MatrixXd &shapes, const std::vector<bool> &usable)
{
    const int frames = int(std::min<Eigen::Index>(shapes.rows(), video.frameCount()));
    auto valid = [&](int t) {
        return t >= 0 && t < frames && (size_t(t) >= usable.size() || usable[size_t(t)])
               && shapes.cols() == 2 * scheme23::kPointCount && shapes.row(t).allFinite();
    };
    std::vector<std::pair<double, int>> closed;          // (gap over width, frame)
    std::vector<std::tuple<int, double, int>> open;      // (band, motion, then its distance from the typical; frame)
    for (int t = 0; t < frames; ++t) {
        if (!valid(t))
            continue;
        const Eigen::VectorXd shape = shapes.row(t).transpose();
        const double width = LowerFaceWarp::mouthWidth(shape);
        if (width < 4.0)
            continue;
        const double share = openingShare(shape);
        if (share <= kClosedShare) {
            closed.emplace_back(share, t);
            continue;
        }
        if (share > kMaxOpenShare)
            continue;
        // How far the mouth points move to the neighbouring frames, in mouth widths.
        double motion = 0.0;
        int neighbours = 0;
        for (int n : {t - 1, t + 1})
            if (valid(n)) {
                motion += (shapes.row(n) - shapes.row(t)).segment(2 * kFirstMouthPoint, 2 * kMouthPoints).norm() / width;
                ++neighbours;
            }
        open.emplace_back(bandOf(share), neighbours ? motion / neighbours : kUnknownMotion, t);
    }
    std::sort(closed.begin(), closed.end());
    // Of each band, the mouths whose motion is nearest the open mouths' median first: as sharp as
    // the person's speech usually is, neither the stillest (crisper than any moving mouth of the
    // recording) nor the most blurred.
    std::vector<double> motions;
    for (const auto &[band, motion, t] : open)
        if (motion < kUnknownMotion)
            motions.push_back(motion);
    if (!motions.empty()) {
        std::nth_element(motions.begin(), motions.begin() + std::ptrdiff_t(motions.size() / 2), motions.end());
        const double typical = motions[motions.size() / 2];
        for (auto &[band, motion, t] : open)
            if (motion < kUnknownMotion)
                motion = std::abs(motion - typical);
    }
    std::sort(open.begin(), open.end());
    std::vector<std::pair<int, int>> chosen; // (frame, band)
    auto spaced = [&](int t, int band) {
        const double time = video.timestamp(t);
        return std::none_of(chosen.begin(), chosen.end(), [&](const std::pair<int, int> &c) {
            return c.second == band && std::abs(video.timestamp(c.first) - time) < kSpacingSeconds;
        });
    };
    for (const auto &[share, t] : closed) {
        if (int(chosen.size()) >= kMaxExemplars)
            break;
        if (spaced(t, -1))
            chosen.emplace_back(t, -1);
    }
    std::vector<int> kept; // per band
    for (const auto &[band, motion, t] : open) {
        if (size_t(band) >= kept.size())
            kept.resize(size_t(band) + 1, 0);
        if (kept[size_t(band)] < kOpenPerBand && spaced(t, band)) {
            chosen.emplace_back(t, band);
            ++kept[size_t(band)];
        }
    }
    // In time order (a forward read of the video); the open mouths of a band in the order kept.
    std::vector<int> rank(chosen.size());
    for (size_t i = 0; i < chosen.size(); ++i)
        rank[i] = int(i);
    std::stable_sort(rank.begin(), rank.end(), [&](int a, int b) { return chosen[size_t(a)].first < chosen[size_t(b)].first; });
    const cv::Rect image(0, 0, video.width(), video.height());
    for (int i : rank) {
        const auto [t, band] = chosen[size_t(i)];
        Exemplar e;
        e.frame = t;
        e.time = video.timestamp(t);
        e.band = band;
        e.order = i;
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

double MouthExemplars::openingShare(const Eigen::VectorXd &shape)
{
    return std::max(0.0, LowerFaceWarp::opening(shape)) / LowerFaceWarp::mouthWidth(shape);
}

std::vector<int> MouthExemplars::closedFrames() const
{
    std::vector<int> out;
    for (const Exemplar &e : m_exemplars)
        if (e.band < 0)
            out.push_back(e.frame);
    return out;
}

std::vector<int> MouthExemplars::openFrames() const
{
    std::vector<int> out;
    for (const Exemplar &e : m_exemplars)
        if (e.band >= 0)
            out.push_back(e.frame);
    return out;
}

int MouthExemplars::bandOf(double share)
{
    return std::max(0, int(std::floor((share - kClosedShare) / kOpenStep)));
}

int MouthExemplars::chooseClosed(double time) const
{
    int best = -1;
    double bestDistance = 0.0;
    for (size_t i = 0; i < m_exemplars.size(); ++i) {
        const double d = std::abs(m_exemplars[i].time - time);
        if (m_exemplars[i].band < 0 && d >= kAwaySeconds && (best < 0 || d < bestDistance)) {
            best = int(i);
            bestDistance = d;
        }
    }
    return best;
}

int MouthExemplars::chooseOpen(double time, double share) const
{
    const int wanted = bandOf(share);
    int best = -1;
    std::pair<int, int> bestKey; // (bands away, order kept)
    for (size_t i = 0; i < m_exemplars.size(); ++i) {
        const Exemplar &e = m_exemplars[i];
        if (e.band < 0 || std::abs(e.time - time) < kAwaySeconds)
            continue;
        const std::pair<int, int> key(std::abs(e.band - wanted), e.order);
        if (best < 0 || key < bestKey) {
            best = int(i);
            bestKey = key;
        }
    }
    return best;
}

bool MouthExemplars::draw(int which, const Eigen::VectorXd &generated, const cv::Rect &box, cv::Mat &patch) const
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
    if (e.band >= 0) {
        // An open mouth: a thin-plate spline (an affine map and a bend) takes each of the ten
        // points exactly where the generated lips put it, so the drawn inside ends at the
        // generated inner lips, where the caller's mask ends it (with the affine map alone a
        // mouth of another shape shows its own lips inside the generated ones, and the opening
        // reads smaller). The spline's backward map reads the crop at p - d(p) for patch pixel p.
        Eigen::VectorXd sources(2 * kMouthPoints), targets(2 * kMouthPoints);
        for (int k = 0; k < kMouthPoints; ++k) {
            sources.segment<2>(2 * k) = from.row(k).head<2>().transpose();
            targets.segment<2>(2 * k) = to.row(k).transpose();
        }
        const ThinPlateWarp spline(sources, targets);
        if (spline.valid()) {
            const Eigen::Index n = Eigen::Index(box.width) * box.height;
            Eigen::ArrayXd px(n), py(n), dx, dy;
            for (Eigen::Index k = 0; k < n; ++k) {
                px[k] = double(k % box.width);
                py[k] = double(k / box.width);
            }
            spline.displacements(px, py, dx, dy);
            const Eigen::ArrayXf qx = (px - dx).cast<float>(), qy = (py - dy).cast<float>();
            // Row-major, as cv::Mat: each map wraps its array.
            const cv::Mat mapX(box.size(), CV_32F, const_cast<float *>(qx.data()));
            const cv::Mat mapY(box.size(), CV_32F, const_cast<float *>(qy.data()));
            cv::remap(e.crop, patch, mapX, mapY, cv::INTER_LANCZOS4, cv::BORDER_REPLICATE);
            return true;
        }
    }
    const cv::Matx23d affine(map(0, 0), map(1, 0), map(2, 0), map(0, 1), map(1, 1), map(2, 1));
    // Lanczos, as the lower face's warp (ThinPlateWarp): a bilinear lookup at sub-pixel offsets
    // softens the recorded lips it moves.
    cv::warpAffine(e.crop, patch, affine, box.size(), cv::INTER_LANCZOS4, cv::BORDER_REPLICATE);
    return true;
}

} // namespace lipsync
