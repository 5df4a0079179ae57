#include "aam/AamFitter.h"

#include "aam/AamFitStep.h"
#include "aam/TextureNormalisation.h"

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <opencv2/imgproc.hpp>

#include <array>
#include <cmath>

namespace lipsync {

cv::Mat greyFloat(const cv::Mat &image)
{
    cv::Mat grey;
    if (image.channels() == 3)
        cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    else if (image.channels() == 4)
        cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
    else
        grey = image;
    cv::Mat out;
    grey.convertTo(out, CV_32F);
    return out;
}

cv::Mat smoothedForFitting(const cv::Mat &grey)
{
    cv::Mat out;
    cv::GaussianBlur(grey, out, cv::Size(5, 5), 1.0);
    return out;
}

std::vector<cv::Mat> fittingChannels(const cv::Mat &smoothedGrey, AamFitFeatures features)
{
    if (features == AamFitFeatures::Grey)
        return {smoothedGrey};
    cv::Mat gx, gy, magnitude;
    cv::Sobel(smoothedGrey, gx, CV_32F, 1, 0);
    cv::Sobel(smoothedGrey, gy, CV_32F, 0, 1);
    cv::magnitude(gx, gy, magnitude);
    // cos and sin of the orientation; a tiny floor keeps flat regions finite (their orientations
    // are noise, which the IGO texture model treats as such: Tzimiropoulos et al. 2012, §3).
    magnitude += 1e-3f;
    cv::divide(gx, magnitude, gx);
    cv::divide(gy, magnitude, gy);
    return {gx, gy};
}

void sampleFittingChannels(const PiecewiseAffineWarp &warp, const std::vector<cv::Mat> &channels,
                           const Eigen::VectorXd &shape, float *out)
{
    const size_t n = size_t(warp.pixelCount());
    for (size_t c = 0; c < channels.size(); ++c)
        warp.sampleGrey(channels[c], shape, out + c * n);
}

namespace {

// Pixel-centre-preserving rescale of shape coordinates.
Eigen::VectorXd scaled(const Eigen::VectorXd &shape, double f)
{
    return (shape.array() + 0.5) * f - 0.5;
}

} // namespace

AamFitter::AamFitter(const AamModel &model) : m_model(model)
{
    m_levels.resize(model.levels.size());
    for (int l = 0; l < int(model.levels.size()); ++l)
        prepareLevel(l);
}

void AamFitter::prepareLevel(int l)
{
    AamFitLevel &level = m_levels[size_t(l)];
    const PiecewiseAffineWarp &warp = m_model.warp(l);
    const AamTextureLevel &tex = m_model.levels[size_t(l)];
    const Similarity toRef = m_model.referenceTransform(l);
    level.reference = toRef.apply(m_model.meanShape);
    // Samples are normalised to zero mean and unit variance; the template must be too, or its
    // gradient is too weak by the factor std(A0) and every step overshoots.
    level.templateMean = tex.mean.cast<float>();
    normaliseTexture(level.templateMean.data(), size_t(level.templateMean.size()));
    // Appearance subspace to project out: the texture modes plus the template itself, so that the
    // contrast change left by normalising each sample to unit variance is not read as motion.
    {
        Eigen::MatrixXd a(tex.mean.size(), tex.basis.cols() + 1);
        a << tex.mean, tex.basis;
        Eigen::HouseholderQR<Eigen::MatrixXd> aqr(a);
        level.appearance =
            (aqr.householderQ() * Eigen::MatrixXd::Identity(a.rows(), a.cols())).cast<float>();
    }

    // Basis of shape displacements in the reference frame: the similarity (scale-rotation of s0
    // about its centroid, translation; Matthews & Baker §4.3) and the shape modes, orthonormalised.
    const int k = m_model.pointCount();
    const int ns = m_model.shapeModes();
    Eigen::MatrixXd raw(2 * k, 4 + ns);
    const Eigen::Vector2d c = shapeCentroid(level.reference);
    for (int i = 0; i < k; ++i) {
        const double x = level.reference[2 * i] - c.x(), y = level.reference[2 * i + 1] - c.y();
        raw.row(2 * i).head(4) << x, -y, 1, 0;
        raw.row(2 * i + 1).head(4) << y, x, 0, 1;
    }
    raw.rightCols(ns) = m_model.shapeBasis.leftCols(ns) * toRef.scale();
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(raw);
    level.basis = qr.householderQ() * Eigen::MatrixXd::Identity(2 * k, 4 + ns);
    const int P = int(level.basis.cols());
    // The shape modes are orthonormal, so a reference-frame displacement B p changes b by
    // S^T B p / scale.
    level.toShapeParams = m_model.shapeBasis.leftCols(ns).transpose() * level.basis / toRef.scale();

    // Jacobian of the piecewise-affine warp at every pixel: barycentric blend of the basis
    // displacements of its triangle's vertices (Matthews & Baker §4.1.1).
    const int N = warp.pixelCount();
    level.warpX.resize(N, P);
    level.warpY.resize(N, P);
    for (int i = 0; i < N; ++i) {
        const Triangle &tri = warp.triangles()[size_t(warp.pixelTriangle(i))];
        const float *w = warp.pixelBarycentric(i);
        for (int j = 0; j < P; ++j) {
            double dx = 0, dy = 0;
            for (int v = 0; v < 3; ++v) {
                dx += w[v] * level.basis(2 * tri[size_t(v)], j);
                dy += w[v] * level.basis(2 * tri[size_t(v)] + 1, j);
            }
            level.warpX(i, j) = float(dx);
            level.warpY(i, j) = float(dy);
        }
    }
    const Eigen::MatrixXd sdd = steepestDescent(level, warp, level.templateMean).cast<double>();
    Eigen::MatrixXd hessian = sdd.transpose() * sdd;
    hessian.diagonal().array() += 1e-6 * hessian.diagonal().mean();
    level.update = hessian.ldlt().solve(sdd.transpose()).cast<float>();
}

Eigen::VectorXd AamFitter::modelShape(const Similarity &pose, const Eigen::VectorXd &params) const
{
    return pose.apply(Eigen::VectorXd(m_model.meanShape + m_model.shapeBasis * params));
}

Eigen::VectorXd AamFitter::projectShape(const Eigen::VectorXd &shape, Similarity &pose,
                                        Eigen::VectorXd &params, double limit,
                                        const Eigen::VectorXd &weights) const
{
    const Eigen::MatrixXd &S = m_model.shapeBasis;
    params = Eigen::VectorXd::Zero(S.cols());
    // Alternate similarity and shape parameters (converges in a few rounds; one suffices without
    // weights since the modes are orthogonal to the similarity in the tangent space).
    const int rounds = weights.size() ? 4 : 2;
    for (int round = 0; round < rounds; ++round) {
        const Eigen::VectorXd model = m_model.meanShape + S * params;
        pose = alignSimilarity(model, shape, weights);
        const Eigen::VectorXd y = pose.inverse().apply(shape) - m_model.meanShape;
        if (weights.size() == 0) {
            params = S.transpose() * y;
        } else {
            Eigen::VectorXd w2(y.size());
            for (Eigen::Index i = 0; i < weights.size(); ++i)
                w2[2 * i] = w2[2 * i + 1] = weights[i];
            Eigen::MatrixXd lhs = S.transpose() * w2.asDiagonal() * S;
            // Weak prior towards the mean keeps the solve well posed with few free points.
            for (Eigen::Index j = 0; j < S.cols(); ++j)
                lhs(j, j) += 1e-3 / std::max(1e-12, m_model.shapeVariances[j]) * 1e-3;
            params = lhs.ldlt().solve(S.transpose() * (w2.asDiagonal() * y));
        }
        for (Eigen::Index j = 0; j < params.size(); ++j) {
            const double bound = limit * std::sqrt(m_model.shapeVariances[j]);
            params[j] = std::clamp(params[j], -bound, bound);
        }
    }
    pose = alignSimilarity(Eigen::VectorXd(m_model.meanShape + S * params), shape, weights);
    return modelShape(pose, params);
}

AamFitResult AamFitter::fit(const cv::Mat &image, const Eigen::VectorXd &initialShape,
                            const AamFitOptions &options) const
{
    const cv::Mat grey = image.type() == CV_32F ? image : greyFloat(image);
    AamFitResult best = fitOnce(grey, initialShape, options);
    if (!options.multiStart)
        return best;
    const Eigen::Vector2d c = shapeCentroid(initialShape);
    const double size = shapeSize(initialShape) / std::sqrt(double(m_model.pointCount())); // RMS radius
    const std::array<std::array<double, 3>, 6> moves{{{0.9, 0, 0},
                                                      {1.1, 0, 0},
                                                      {1, 0.06, 0},
                                                      {1, -0.06, 0},
                                                      {1, 0, 0.06},
                                                      {1, 0, -0.06}}};
    for (const auto &[scale, dx, dy] : moves) {
        const double sc = 1.0 + (scale - 1.0) * options.multiStartSpread;
        const double mx = dx * options.multiStartSpread, my = dy * options.multiStartSpread;
        const Similarity move{sc, 0, (1 - sc) * c.x() + mx * size, (1 - sc) * c.y() + my * size};
        AamFitResult r = fitOnce(grey, move.apply(initialShape), options);
        r.iterations += best.iterations;
        if (r.error < best.error)
            best = std::move(r);
        else
            best.iterations = r.iterations;
    }
    return best;
}

namespace {

// The face's box in an image of `size`, grown by half its size on each side (the whole image when
// that leaves less than 2 pixels).
cv::Rect regionAround(const Eigen::VectorXd &shape, const cv::Size &size)
{
    double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
    for (Eigen::Index i = 0; i + 1 < shape.size(); i += 2) {
        x0 = std::min(x0, shape[i]);
        x1 = std::max(x1, shape[i]);
        y0 = std::min(y0, shape[i + 1]);
        y1 = std::max(y1, shape[i + 1]);
    }
    const double mx = 0.5 * (x1 - x0) + 4, my = 0.5 * (y1 - y0) + 4;
    const cv::Rect wanted(int(std::floor(x0 - mx)), int(std::floor(y0 - my)), int(std::ceil(x1 - x0 + 2 * mx)),
                          int(std::ceil(y1 - y0 + 2 * my)));
    const cv::Rect roi = wanted & cv::Rect(0, 0, size.width, size.height);
    return roi.width < 2 || roi.height < 2 ? cv::Rect(0, 0, size.width, size.height) : roi;
}

// Projection weights that hold the fixed points (PointState::Fixed) where they are.
Eigen::VectorXd fixedPointWeights(const std::vector<bool> &fixed)
{
    Eigen::VectorXd weights = Eigen::VectorXd::Ones(Eigen::Index(fixed.size()));
    for (size_t i = 0; i < fixed.size(); ++i)
        if (fixed[i])
            weights[Eigen::Index(i)] = 1000.0;
    return weights;
}

} // namespace

AamFitResult AamFitter::fitOnce(const cv::Mat &grey, const Eigen::VectorXd &initialShape,
                                const AamFitOptions &options) const
{
    const int k = m_model.pointCount();
    const bool hasFixed = options.fixedShape.size() == 2 * k && int(options.fixedMask.size()) == k;
    const Eigen::VectorXd weights = hasFixed ? fixedPointWeights(options.fixedMask) : Eigen::VectorXd();
    auto pinFixed = [&](Eigen::VectorXd &s) {
        if (hasFixed)
            for (int i = 0; i < k; ++i)
                if (options.fixedMask[size_t(i)])
                    s.segment<2>(2 * i) = options.fixedShape.segment<2>(2 * i);
    };

    AamFitResult result;
    Eigen::VectorXd start = initialShape;
    pinFixed(start);
    result.shape = projectShape(start, result.pose, result.shapeParams, options.shapeLimit, weights);

    const std::unique_ptr<AamFitStep> algorithm = makeAamFitStep(m_model, options);
    const int levels = int(m_levels.size());
    const int first = options.coarsestLevel < 0 ? levels - 1 : std::min(options.coarsestLevel, levels - 1);
    std::vector<float> sample;
    for (int l = first; l >= 0; --l) {
        const AamFitLevel &level = m_levels[size_t(l)];
        const PiecewiseAffineWarp &warp = m_model.warp(l);
        // Sample an image whose scale matches the level's reference frame (downscale only: the
        // warp interpolates when the face is smaller than the frame).
        const double wanted = m_model.referenceScale * m_model.levels[size_t(l)].scale;
        double f = wanted / result.pose.scale();
        cv::Mat levelImage;
        if (f < 0.8) {
            cv::resize(grey, levelImage, cv::Size(), f, f, cv::INTER_AREA);
        } else {
            f = 1.0;
            levelImage = grey;
        }
        // Smooth only the region around the face: tracking a 360x288 video then costs a few
        // thousand pixels per frame, not the whole frame.
        const cv::Rect roi = regionAround(scaled(result.shape, f), levelImage.size());
        const std::vector<cv::Mat> channels =
            fittingChannels(smoothedForFitting(levelImage(roi)), m_model.fitFeatures);
        const Eigen::Vector2d offset(roi.x, roi.y);
        auto toLevel = [&](const Eigen::VectorXd &shape) {
            Eigen::VectorXd out = scaled(shape, f);
            for (int i = 0; i < k; ++i)
                out.segment<2>(2 * i) -= offset;
            return out;
        };
        auto fromLevel = [&](Eigen::VectorXd shape) {
            for (int i = 0; i < k; ++i)
                shape.segment<2>(2 * i) += offset;
            return scaled(shape, 1.0 / f);
        };
        const int N = warp.pixelCount() * m_model.fitChannels();
        sample.resize(size_t(N));
        // Residual of a shape: the part of the normalised texture error the appearance model
        // cannot explain (the project-out cost, Matthews & Baker eq. 39).
        auto evaluate = [&](const Eigen::VectorXd &shape, Eigen::VectorXf &error) {
            sampleFittingChannels(warp, channels, toLevel(shape), sample.data());
            normaliseTexture(sample.data(), sample.size());
            error = Eigen::Map<Eigen::VectorXf>(sample.data(), N) - level.templateMean;
            const Eigen::VectorXf c = level.appearance.transpose() * error;
            return double(error.squaredNorm() - c.squaredNorm()) / N;
        };
        Eigen::VectorXf error, candidateError;
        double residual = evaluate(result.shape, error);
        if (options.keepHistory)
            result.history.push_back({result.shape, residual, l});
        double step = 1.0;
        Eigen::VectorXd fullStep; // Gauss-Newton step at the current shape (kept while backtracking)
        for (int it = 0; it < options.maxIterations; ++it) {
            ++result.iterations;
            const Eigen::VectorXd current = toLevel(result.shape);
            if (fullStep.size() == 0)
                fullStep = algorithm->step(level, warp, error, residual, result.shapeParams);
            const Eigen::VectorXd dp = step * fullStep;
            // Inverse compositional update: W(x; p) <- W(x; p) o W(x; dp)^-1, with the inverse
            // approximated by -dp and the composition done on the mesh vertices (§4.1.2).
            const Eigen::VectorXd inverseRef = level.reference - level.basis * dp;
            Eigen::VectorXd next = fromLevel(warp.warpVertices(inverseRef, current));
            pinFixed(next);
            Eigen::VectorXd params;
            Similarity pose;
            next = projectShape(next, pose, params, options.shapeLimit, weights);
            const double nextResidual = evaluate(next, candidateError);
            if (!(nextResidual < residual)) {
                // The linearisation overshot: retry with half the step (a backtracking line
                // search keeps the fit from diverging on faces far from the training set).
                step *= 0.5;
                if (step < 0.1) {
                    result.converged = true;
                    break;
                }
                continue;
            }
            double moved = 0.0;
            for (int i = 0; i < k; ++i)
                moved = std::max(moved, (next.segment<2>(2 * i) - result.shape.segment<2>(2 * i)).norm());
            result.shape = next;
            result.pose = pose;
            result.shapeParams = params;
            residual = nextResidual;
            if (options.keepHistory)
                result.history.push_back({result.shape, residual, l});
            std::swap(error, candidateError);
            fullStep.resize(0);
            step = std::min(1.0, step * 2.0);
            if (moved * f < options.tolerance) {
                result.converged = true;
                break;
            }
        }
        if (l == 0)
            result.error = residual;
    }
    pinFixed(result.shape);
    return result;
}

Eigen::VectorXd AamFitter::features(const cv::Mat &bgrImage, const AamFitResult &fit,
                                    Eigen::VectorXd *textureParams) const
{
    const PiecewiseAffineWarp &warp = m_model.warp(0);
    cv::Mat colour = bgrImage;
    if (colour.type() == CV_8UC1)
        cv::cvtColor(bgrImage, colour, cv::COLOR_GRAY2BGR);
    Eigen::VectorXd shape = fit.shape;
    const double f = m_model.referenceScale / fit.pose.scale();
    if (f < 0.8) {
        cv::resize(colour, colour, cv::Size(), f, f, cv::INTER_AREA);
        shape = scaled(shape, f);
    }
    std::vector<float> buffer(size_t(3 * warp.pixelCount()));
    warp.sampleColour(colour, shape, buffer.data());
    normaliseTexture(buffer.data(), buffer.size());
    const Eigen::VectorXd g = Eigen::Map<Eigen::VectorXf>(buffer.data(), Eigen::Index(buffer.size())).cast<double>();
    const Eigen::VectorXd bg = m_model.textureBasis.transpose() * (g - m_model.textureMean);
    if (textureParams)
        *textureParams = bg;
    return m_model.combinedFromParts(fit.shapeParams, bg);
}

} // namespace lipsync
