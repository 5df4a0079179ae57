#include "aam/AamSynthesizer.h"

#include "aam/CubicInterpolation.h"
#include "aam/LandmarkScheme.h"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lipsync {

AamSynthesizer::AamSynthesizer(const AamModel &model, double featherPixels) : m_model(model)
{
    // x = x0 + Ps Ws^-1 Qs c and g = g0 + Pg Qg c (Cootes et al. 2001, eq. 5).
    const int ns = model.shapeModes();
    const int ng = model.textureModes();
    const Eigen::MatrixXd qs = model.combinedBasis.topRows(ns);
    const Eigen::MatrixXd qg = model.combinedBasis.bottomRows(ng);
    m_shapeMatrix = model.shapeBasis * qs / model.shapeWeight;
    m_textureMatrix = (model.textureBasis * qg).cast<float>();
    m_textureMean = model.textureMean.cast<float>();
    m_invSd = model.combinedVariances.cwiseMax(1e-12).cwiseSqrt().cwiseInverse();
    if (model.exemplarCount() > 0)
        m_exemplarsWhite = m_invSd.asDiagonal() * model.exemplarParams;

    const PiecewiseAffineWarp &warp = model.warp(0);
    const cv::Mat &index = warp.indexMap();
    cv::Mat mask = index >= 0;
    // Feather: opacity rises from 0 at the outline to 1 at `featherPixels` inside it.
    cv::Mat padded;
    cv::copyMakeBorder(mask, padded, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
    cv::Mat dist;
    cv::distanceTransform(padded, dist, cv::DIST_L2, 3);
    dist = dist(cv::Rect(1, 1, mask.cols, mask.rows)).clone();
    m_alpha = cv::Mat(mask.size(), CV_32F, cv::Scalar(0));
    const float feather = float(std::max(0.5, featherPixels));
    for (int y = 0; y < mask.rows; ++y)
        for (int x = 0; x < mask.cols; ++x)
            if (mask.at<uchar>(y, x))
                m_alpha.at<float>(y, x) = std::min(1.f, (dist.at<float>(y, x) - 0.5f) / feather + 0.1f);
    // The lower face: opacity ramps up (smoothstep) from 35 % to 75 % of the way from the eyes'
    // line down to the top of the upper lip, across the nose, where the face hardly moves.
    const Eigen::VectorXd &ref = warp.referenceShape();
    double eyes = 0.0, lip = std::numeric_limits<double>::infinity();
    for (int i = 0; i < scheme23::kMouthLeft; ++i)
        eyes += ref[2 * i + 1] / scheme23::kMouthLeft;
    for (int i = scheme23::kMouthLeft; i < scheme23::kPointCount; ++i)
        if (landmarkDefinitions()[size_t(i)].feature == LandmarkFeature::Mouth)
            lip = std::min(lip, ref[2 * i + 1]);
    const double top = eyes + 0.35 * (lip - eyes), bottom = eyes + 0.75 * (lip - eyes);
    m_alphaLower = m_alpha.clone();
    for (int y = 0; y < mask.rows; ++y) {
        const double u = std::clamp((y - top) / std::max(1.0, bottom - top), 0.0, 1.0);
        const float ramp = float(u * u * (3.0 - 2.0 * u));
        for (int x = 0; x < mask.cols; ++x)
            m_alphaLower.at<float>(y, x) *= ramp;
    }
    // Outside pixels next to the frame copy their nearest inside pixel, so bilinear lookups at
    // the outline do not mix in black.
    for (int y = 0; y < mask.rows; ++y) {
        for (int x = 0; x < mask.cols; ++x) {
            if (mask.at<uchar>(y, x))
                continue;
            int best = -1;
            int bestD = 1 << 30;
            for (int dy = -2; dy <= 2; ++dy)
                for (int dx = -2; dx <= 2; ++dx) {
                    const int xx = x + dx, yy = y + dy;
                    if (xx < 0 || yy < 0 || xx >= mask.cols || yy >= mask.rows)
                        continue;
                    const int j = index.at<int>(yy, xx);
                    if (j >= 0 && dx * dx + dy * dy < bestD) {
                        bestD = dx * dx + dy * dy;
                        best = j;
                    }
                }
            if (best >= 0)
                m_borderFill.emplace_back(y * mask.cols + x, best);
        }
    }
}

Eigen::VectorXd AamSynthesizer::shape(const Eigen::VectorXd &combined) const
{
    return m_model.meanShape + m_shapeMatrix * combined;
}

Eigen::VectorXf AamSynthesizer::texture(const Eigen::VectorXd &combined, bool detail) const
{
    Eigen::VectorXf g = m_textureMean + m_textureMatrix * combined.cast<float>();
    if (detail)
        for (const auto &[k, w] : detailWeights(combined))
            g += (w * float(m_model.exemplarScales[k])) * m_model.exemplarDetail.col(k).cast<float>();
    return g;
}

std::vector<std::pair<int, float>> AamSynthesizer::detailWeights(const Eigen::VectorXd &combined) const
{
    const int e = int(m_exemplarsWhite.cols());
    if (e == 0 || combined.size() != m_exemplarsWhite.rows())
        return {};
    const Eigen::VectorXd white = m_invSd.cwiseProduct(combined);
    std::vector<std::pair<double, int>> byDistance(static_cast<size_t>(e));
    for (int k = 0; k < e; ++k)
        byDistance[size_t(k)] = {(m_exemplarsWhite.col(k) - white).norm(), k};
    const size_t kNearest = std::min<size_t>(3, byDistance.size());
    std::partial_sort(byDistance.begin(), byDistance.begin() + std::ptrdiff_t(kNearest), byDistance.end());
    if (kNearest == 1)
        return {{byDistance[0].second, 1.f}};
    constexpr double kEpsilon = 1e-9;
    const double last = 1.0 / (byDistance[kNearest - 1].first + kEpsilon);
    std::vector<std::pair<int, float>> weights;
    double norm = 0.0;
    for (size_t i = 0; i + 1 < kNearest; ++i) {
        const double w = 1.0 / (byDistance[i].first + kEpsilon) - last;
        if (w > 0) {
            weights.emplace_back(byDistance[i].second, float(w));
            norm += w * w;
        }
    }
    if (norm <= 0) // equidistant exemplars: the first alone
        return {{byDistance[0].second, 1.f}};
    // Weights that vanish next to the nearest (c at an exemplar) are left out.
    constexpr float kNegligible = 1e-6f;
    std::vector<std::pair<int, float>> normalised;
    for (const auto &[k, w] : weights)
        if (const float unit = float(w / std::sqrt(norm)); unit >= kNegligible)
            normalised.emplace_back(k, unit);
    return normalised;
}

PhotometricTransform AamSynthesizer::defaultPhotometric() const
{
    return {m_model.meanTextureOffset, m_model.meanTextureScale};
}

cv::Mat AamSynthesizer::textureImage(const Eigen::VectorXd &combined, PhotometricTransform photometric,
                                     bool detail) const
{
    const PiecewiseAffineWarp &warp = m_model.warp(0);
    Eigen::VectorXf g = texture(combined, detail);
    g = (g.array() * float(photometric.scale) + float(photometric.offset)).cwiseMax(0.f).cwiseMin(255.f);
    cv::Mat image = warp.toImage(g.data(), 3, 0.f);
    float *data = image.ptr<float>();
    for (const auto &[offset, inside] : m_borderFill)
        for (int c = 0; c < 3; ++c)
            data[3 * offset + c] = g[3 * inside + c];
    return image;
}

void AamSynthesizer::composite(const Eigen::VectorXd &combined, const Similarity &pose, cv::Mat &frame,
                               const CompositeOptions &options) const
{
    composite(combined, pose, defaultPhotometric(), frame, options);
}

template <class Visit>
void AamSynthesizer::rasterise(const Eigen::VectorXd &combined, const Similarity &pose, cv::Size size,
                               const cv::Mat &alphaMap, const cv::Mat *texture, Visit &&visit) const
{
    const Eigen::VectorXd target = pose.apply(shape(combined));
    const PiecewiseAffineWarp &warp = m_model.warp(0);
    const Eigen::VectorXd &ref = warp.referenceShape();
    const int tw = alphaMap.cols, th = alphaMap.rows;
    const float *texData = texture ? texture->ptr<float>() : nullptr;
    const float *alphaData = alphaMap.ptr<float>();
    float texel[3] = {0.f, 0.f, 0.f};
    for (const Triangle &tri : warp.triangles()) {
        // Frame -> reference affine map of this triangle.
        const Eigen::Vector2d p0 = target.segment<2>(2 * tri[0]), p1 = target.segment<2>(2 * tri[1]),
                              p2 = target.segment<2>(2 * tri[2]);
        const Eigen::Vector2d r0 = ref.segment<2>(2 * tri[0]), r1 = ref.segment<2>(2 * tri[1]),
                              r2 = ref.segment<2>(2 * tri[2]);
        const Eigen::Vector2d u = p1 - p0, v = p2 - p0;
        const double det = u.x() * v.y() - u.y() * v.x();
        if (std::abs(det) < 1e-9)
            continue;
        const int x0 = std::max(0, int(std::floor(std::min({p0.x(), p1.x(), p2.x()}))));
        const int x1 = std::min(size.width - 1, int(std::ceil(std::max({p0.x(), p1.x(), p2.x()}))));
        const int y0 = std::max(0, int(std::floor(std::min({p0.y(), p1.y(), p2.y()}))));
        const int y1 = std::min(size.height - 1, int(std::ceil(std::max({p0.y(), p1.y(), p2.y()}))));
        const double inv = 1.0 / det;
        const float eps = -1e-4f;
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const double dx = x - p0.x(), dy = y - p0.y();
                const float b = float((dx * v.y() - dy * v.x()) * inv);
                const float c = float((u.x() * dy - u.y() * dx) * inv);
                const float a = 1.f - b - c;
                if (a < eps || b < eps || c < eps)
                    continue;
                float rx = float(a * r0.x() + b * r1.x() + c * r2.x());
                float ry = float(a * r0.y() + b * r1.y() + c * r2.y());
                rx = std::clamp(rx, 0.f, float(tw - 1) - 1e-3f);
                ry = std::clamp(ry, 0.f, float(th - 1) - 1e-3f);
                const int ix = int(rx), iy = int(ry);
                const float fx = rx - float(ix), fy = ry - float(iy);
                const float w00 = (1 - fx) * (1 - fy), w01 = fx * (1 - fy), w10 = (1 - fx) * fy,
                            w11 = fx * fy;
                const int i00 = iy * tw + ix;
                const float alpha = w00 * alphaData[i00] + w01 * alphaData[i00 + 1]
                                    + w10 * alphaData[i00 + tw] + w11 * alphaData[i00 + tw + 1];
                if (alpha <= 0.f)
                    continue;
                if (texData) {
                    // Catmull-Rom: a bilinear lookup would blur the texture a second time.
                    sampleCatmullRom<3>(texData, tw, th, 3 * tw, ix, iy, fx, fy, texel);
                }
                visit(x, y, alpha, texel);
            }
        }
    }
}

void AamSynthesizer::composite(const Eigen::VectorXd &combined, const Similarity &pose,
                               PhotometricTransform photometric, cv::Mat &frame,
                               const CompositeOptions &options) const
{
    CV_Assert(frame.type() == CV_8UC3);
    const cv::Mat tex = textureImage(combined, photometric, options.detail);
    const cv::Mat &alphaMap = alphaOf(options.region);
    if (!options.matchColour) {
        rasterise(combined, pose, frame.size(), alphaMap, &tex, [&](int x, int y, float alpha, const float *t) {
            uchar *px = frame.ptr<uchar>(y) + 3 * x;
            for (int ch = 0; ch < 3; ++ch)
                px[ch] = cv::saturate_cast<uchar>(alpha * t[ch] + (1.f - alpha) * px[ch]);
        });
        return;
    }
    // Two steps over the covered pixels, kept in between: the seam's mean difference (where
    // the blend is partial), then the blend with that offset.
    struct Covered
    {
        int offset;
        float alpha;
        float texel[3];
    };
    std::vector<Covered> covered;
    covered.reserve(size_t(cv::countNonZero(alphaMap)) * 2);
    double sum[3] = {0, 0, 0};
    double weight = 0.0;
    rasterise(combined, pose, frame.size(), alphaMap, &tex, [&](int x, int y, float alpha, const float *t) {
        covered.push_back({y * int(frame.step) + 3 * x, alpha, {t[0], t[1], t[2]}});
        if (alpha < 0.98f) {
            const uchar *px = frame.ptr<uchar>(y) + 3 * x;
            for (int ch = 0; ch < 3; ++ch)
                sum[ch] += double(px[ch]) - t[ch];
            weight += 1.0;
        }
    });
    float shift[3] = {0.f, 0.f, 0.f};
    constexpr double kMaxShift = 48.0; // a lighting correction, not a repaint
    if (weight > 0)
        for (int ch = 0; ch < 3; ++ch)
            shift[ch] = float(std::clamp(sum[ch] / weight, -kMaxShift, kMaxShift));
    uchar *data = frame.data;
    for (const Covered &c : covered) {
        uchar *px = data + c.offset;
        for (int ch = 0; ch < 3; ++ch)
            px[ch] = cv::saturate_cast<uchar>(c.alpha * (c.texel[ch] + shift[ch]) + (1.f - c.alpha) * px[ch]);
    }
}

cv::Mat AamSynthesizer::compositeWeight(const Eigen::VectorXd &combined, const Similarity &pose, cv::Size size,
                                        FaceRegion region) const
{
    cv::Mat weight(size, CV_32F, cv::Scalar(0));
    rasterise(combined, pose, size, alphaOf(region), nullptr,
              [&](int x, int y, float alpha, const float *) { weight.at<float>(y, x) = alpha; });
    return weight;
}

} // namespace lipsync
