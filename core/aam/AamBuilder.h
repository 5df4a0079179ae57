#pragma once
// Trains an AamModel from labelled images (Cootes, Edwards & Taylor 2001, §3-4): generalised
// Procrustes alignment and shape PCA, Delaunay triangulation of the mean shape, piecewise-affine
// warp of every image to it, photometric normalisation and texture PCA, then the combined PCA of
// [Ws b_s; b_g] with Ws = r I, r^2 = (texture variance) / (shape variance).
#include "aam/AamModel.h"

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace lipsync {

class Feedback;
class FaceDetector;

struct AamTrainingExample
{
    std::string name;      // for messages (file name)
    std::string imagePath; // read when `image` is empty
    cv::Mat image;         // BGR 8-bit (grey is converted)
    Eigen::VectorXd shape; // 23 points, flat, 0-based pixels
};

struct AamBuildOptions
{
    // Fractions of variance retained. The combined model keeps 98 % up to the paper's 32 modes
    // (§4): 150 selected GRID s1 frames reach the cap at 95 %, 20 frames allow 19 modes at most.
    double shapeVariance = 0.95;
    double textureVariance = 0.95;
    double combinedVariance = 0.98;
    // The paper's 32 parameters (§4: "a 32 parameter model proves sufficient"); 0: no cap.
    static constexpr int kPaperCombinedModes = 32;
    int maxCombinedModes = kPaperCombinedModes;
    // Size of the level-0 reference frame: pixels between the outer eye corners. 0: automatic,
    // kAutoReferenceScale times the training faces' median size, within [kAutoReferenceMin,
    // kAutoReferenceMax]: textures sampled finer than the faces were recorded keep the mouth
    // sharp when the model draws it back into the frames (docs/performance.md, "Person AAMs from
    // selected frames").
    double referenceEyeDistance = 0.0;
    static constexpr double kAutoReferenceScale = 1.5;
    static constexpr double kAutoReferenceMin = 50.0;
    static constexpr double kAutoReferenceMax = 100.0;
    // Resolution levels for fitting, each half the previous. 0: automatic, as many as keep the
    // coarsest level's eye distance at least kCoarsestEyeDistance pixels.
    int levels = 0;
    static constexpr double kCoarsestEyeDistance = 20.0;
    // Also train on every image flipped left to right (points renumbered by the scheme's
    // symmetric permutation, mirrorShape()): twice the shapes and textures for a generic model,
    // and a symmetric mean. Off for person-specific models, whose asymmetry is real.
    bool mirror = false;
    // Training images kept as exemplar detail (AamModel::exemplarDetail) for synthesis to draw
    // real teeth and lip highlights on the model's smooth texture; when there are more, a
    // farthest-point subset in the combined parameters. 0: none (a model only for fitting).
    int maxExemplars = 200;
    // Texture bases rounded to single precision (AamModel::singlePrecisionBases): files half the
    // size; the rounding (7 significant digits) is far below the pixels' own quantisation.
    bool singlePrecisionBases = true;
    // Texture the fitter matches: grey (person-specific tracking) or gradient orientations.
    AamFitFeatures fitFeatures = AamFitFeatures::Grey;
    // When set, the detector is run on every training image to learn where its keypoints put
    // the 23 points (AamModel::detectorShape), which makes fits from a detection start closer.
    FaceDetector *detector = nullptr;

    // The settings for a generic (in-the-wild) model, chosen by 5-fold cross-validation on Helen's
    // training faces only (docs/performance.md, "The generic AAM on Helen"): mirrored training
    // images and gradient-orientation textures in a larger reference frame (70 pixels between the
    // outer eye corners). Fit it with AamFitAlgorithm::Wiberg and multiStart.
    static AamBuildOptions generic()
    {
        AamBuildOptions o;
        o.mirror = true;
        o.fitFeatures = AamFitFeatures::GradientOrientation;
        o.referenceEyeDistance = 70.0;
        o.levels = 2;
        o.combinedVariance = 0.95;
        o.maxCombinedModes = 0;
        o.maxExemplars = 0;
        return o;
    }
};

// How many modes one PCA of the build kept, the fraction of its variance they explain, and what
// stopped it (the variance fraction, the mode cap, or the number of training images).
struct AamModeChoice
{
    int modes = 0;
    double retainedVariance = 0.0;
    PcaLimit limit = PcaLimit::Rank;
};

struct AamBuildReport
{
    AamModeChoice shape, texture, combined;
    double referenceEyeDistance = 0.0; // what the level-0 frame was built with
    int levels = 0;
};

// Images with a .pts of the same stem (68 or 23 points) in `directory`, sorted by name. Throws
// lipsync::Error if the directory does not exist or holds no labelled image. `warnings` receives
// one line per image without landmarks or with an unreadable .pts.
std::vector<AamTrainingExample> loadTrainingDirectory(const std::string &directory,
                                                      std::vector<std::string> *warnings = nullptr);

// The exemplar detail of training image i (AamModel::exemplarDetail): what the model's synthesis
// at the image's own parameters misses of its colour texture, r_i = g_i - (g0 + Pg Qg c_i), high-
// passed — less its blur by a Gaussian of kDetailSigma reference pixels, normalised over the face's
// pixels so the outline does not leak in. The fine structure the modes smooth away (teeth, lip
// highlights, skin grain) stays; the coarse shape of the image's mouth, which the parameters set,
// does not travel with it onto other parameters. `residual`: 3 values per pixel of `warp`.
constexpr double kDetailSigma = 2.0;
Eigen::VectorXd textureDetail(const PiecewiseAffineWarp &warp, const Eigen::VectorXd &residual);

// Builds the model. Examples that cannot be used (unreadable image, points outside the image,
// degenerate shape) are skipped with a line in `warnings`. Throws lipsync::Error when fewer than
// 3 usable examples remain, or Canceled when `feedback` is canceled.
// `report`, when given, receives the mode choices of the shape, texture and combined PCAs.
AamModel buildAam(std::vector<AamTrainingExample> examples, const AamBuildOptions &options,
                  Feedback &feedback, std::vector<std::string> *warnings = nullptr,
                  AamBuildReport *report = nullptr);

} // namespace lipsync
