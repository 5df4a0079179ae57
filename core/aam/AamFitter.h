#pragma once
// Fits an AamModel to an image: project-out inverse compositional image alignment (Matthews &
// Baker, "Active Appearance Models Revisited", IJCV 2004, §4) with a global similarity folded
// into the shape basis, coarse to fine over the model's resolution levels. The steepest-descent
// images and the Hessian are precomputed per level, so one iteration is a warp, a dot product
// with a (params x pixels) matrix and a compositional update of the 23 vertices. After each
// update the shape is projected back onto the shape model (clamped to +-3 s.d.), which is also
// where points a user fixed are honoured (weighted projection that keeps them in place).
//
// Project-out with a fixed Jacobian assumes the face looks like the mean texture; that holds for a
// person-specific model (tracking), not for faces in the wild. AamFitAlgorithm::Wiberg recomputes
// the steepest-descent images each iteration from the gradient of the current appearance instance
// A0 + A c, with c the projection of the current sample, and projects the appearance out of them
// (the Wiberg / fast simultaneous inverse compositional algorithm of Tzimiropoulos & Pantic,
// "Optimization problems for fast AAM fitting in-the-wild", ICCV 2013, §4): a (params x params)
// solve per iteration instead of a product with a precomputed matrix. It also weighs the shape
// model's Gaussian prior against the texture residual (the MAP form of their eq. 15), which keeps
// in-the-wild fits to plausible shapes. The two differ only in how an iteration computes its step
// (aam/AamFitStep.h); the iteration around it is the same.
#include "aam/AamFitLevel.h"
#include "aam/AamModel.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

// A BGR, BGRA or grey image as grey CV_32F (0-255).
cv::Mat greyFloat(const cv::Mat &image);
// Grey images are smoothed (Gaussian, sigma 1 pixel of the level frame) before sampling, in training
// and fitting alike: it widens the basin of convergence of the Gauss-Newton steps.
cv::Mat smoothedForFitting(const cv::Mat &grey);
// The images the fitter samples from a smoothed grey CV_32F image: itself for Grey, the cosine and
// sine of its gradient orientation (Sobel) for GradientOrientation.
std::vector<cv::Mat> fittingChannels(const cv::Mat &smoothedGrey, AamFitFeatures features);
// Samples every channel under `shape` into `out` (channel after channel, pixelCount() each).
void sampleFittingChannels(const PiecewiseAffineWarp &warp, const std::vector<cv::Mat> &channels,
                           const Eigen::VectorXd &shape, float *out);

enum class AamFitAlgorithm {
    ProjectOut, // fixed Jacobian of the mean texture: fast, for person-specific models
    Wiberg,     // Jacobian of the current appearance instance: for generic models
};

struct AamFitOptions
{
    AamFitAlgorithm algorithm = AamFitAlgorithm::ProjectOut;
    int maxIterations = 30;     // per level
    double tolerance = 0.03;    // stop when no vertex moves more (pixels of the level frame)
    int coarsestLevel = -1;     // -1: the model's coarsest; 0 to fit the finest level only
    double shapeLimit = 3.0;    // shape parameters are clamped to this many s.d.
    // Wiberg only: weight of the shape prior against the texture residual per pixel.
    // Neighbouring pixels' errors are strongly correlated, so the residual understates the noise of
    // the |e - J dp|^2 sum by a large factor. Chosen on a validation split of Helen's training
    // faces (docs/performance.md, "The generic AAM on Helen"), never on the test faces.
    static constexpr double kDefaultShapePriorWeight = 20.0;
    double shapePriorWeight = kDefaultShapePriorWeight;
    // Also fit from the start scaled by 1 -+ 0.1 s and shifted by 6 s % of its RMS radius in four
    // directions about its centroid (s = multiStartSpread), keeping the fit with the lowest
    // residual: for a detector's start on a generic face, where one start often lands in a wrong
    // minimum. 7x the cost. s = 1.5 was chosen by cross-validation on Helen's training faces.
    bool multiStart = false;
    double multiStartSpread = 1.5;
    // Keep every accepted step's shape and residual in AamFitResult::history (menpofit's
    // per-iteration result): to see how a fit went, in tests and the tools.
    bool keepHistory = false;
    // Points that must stay where they are (PointState::Fixed): flat shape and a mask.
    Eigen::VectorXd fixedShape;
    std::vector<bool> fixedMask;
};

struct AamFitResult
{
    Eigen::VectorXd shape;       // fitted 23 points, image coordinates
    Similarity pose;             // model (normalised) coordinates -> image
    Eigen::VectorXd shapeParams; // b_s
    double error = 0.0;          // mean squared normalised texture residual after fitting
    int iterations = 0;
    bool converged = false;
    // With AamFitOptions::keepHistory: the start, then the shape after each accepted step, with
    // the residual of the level it was fitted on (coarse levels first; residuals of different
    // levels are not comparable). Each level's residuals decrease.
    struct Step
    {
        Eigen::VectorXd shape;
        double residual = 0;
        int level = 0;
    };
    std::vector<Step> history;
};

class AamFitter
{
public:
    explicit AamFitter(const AamModel &model);

    const AamModel &model() const { return m_model; }

    // `image`: BGR or grey 8-bit. `initialShape`: 23 points in image coordinates.
    AamFitResult fit(const cv::Mat &image, const Eigen::VectorXd &initialShape,
                     const AamFitOptions &options = {}) const;

    // Combined parameters c (the paper's y_t) of a fitted face: shape parameters from the fit,
    // texture parameters from the colour texture under the fitted shape.
    Eigen::VectorXd features(const cv::Mat &bgrImage, const AamFitResult &fit,
                             Eigen::VectorXd *textureParams = nullptr) const;

    // Projects an image-space shape onto the shape model: the similarity and the shape
    // parameters (clamped to `limit` s.d.) of the closest model shape, with optional per-point
    // weights (fixed points weigh heavily). Returns the model shape in image coordinates.
    Eigen::VectorXd projectShape(const Eigen::VectorXd &shape, Similarity &pose,
                                 Eigen::VectorXd &params, double limit = 3.0,
                                 const Eigen::VectorXd &weights = {}) const;

    // Shape from a pose and shape parameters.
    Eigen::VectorXd modelShape(const Similarity &pose, const Eigen::VectorXd &params) const;

    // What fitting precomputed for resolution level `l` (0: the finest): its displacement basis
    // and warp Jacobian, for checks against finite differences.
    const AamFitLevel &level(int l) const { return m_levels.at(size_t(l)); }

private:
    AamFitResult fitOnce(const cv::Mat &grey, const Eigen::VectorXd &initialShape,
                         const AamFitOptions &options) const;
    void prepareLevel(int level);

    const AamModel &m_model;
    std::vector<AamFitLevel> m_levels;
};

} // namespace lipsync
