#pragma once
// A trained Active Appearance Model (Cootes, Edwards & Taylor 2001): the shape model (mean and
// modes of the Procrustes-aligned 23 points), the texture model (colour, photometrically
// normalised, in the triangulated mean-shape frame), and the combined model whose parameters c
// are the paper's face features y_t (§4: "a 32 parameter model proves sufficient"). It also
// keeps grey texture models at each resolution level for fitting.
//
// Texture: colour (B, G, R) for the combined model and synthesis, normalised per image by one
// offset and scale over all channels (so colour balance is kept); the fitter works on grey
// (normalised to zero mean, unit variance), which is what makes it fast.
#include "aam/Pca.h"
#include "aam/PiecewiseAffineWarp.h"
#include "aam/Procrustes.h"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lipsync {

// What the fitter's texture models describe. Grey: the smoothed, normalised intensity (fast, what
// person-specific tracking uses). GradientOrientation: the cosine and sine of the image gradient's
// orientation per pixel (IGO; Tzimiropoulos, Zafeiriou & Pantic, "Subspace learning from image
// gradient orientations", PAMI 2012; Tzimiropoulos & Pantic, ICCV 2013 fit AAMs in the wild with
// them): invariant to lighting, twice the values per pixel.
enum class AamFitFeatures { Grey = 0, GradientOrientation = 1 };

struct AamTextureLevel
{
    double scale = 1.0;       // size relative to level 0
    Eigen::VectorXd mean;     // grey, normalised, one value per reference pixel
    Eigen::MatrixXd basis;    // pixels x modes
    Eigen::VectorXd variances;
};

class AamModel
{
public:
    // Version 2 adds the detector keypoint regression and the fitting features, version 3 the
    // exemplar detail, version 4 single-precision texture bases; a file is written with the
    // lowest version that holds its content, so older files load and are written back unchanged
    // and their identifiers do not change.
    static constexpr int kFormatVersion = 4;

    // Shape model, in normalised (centred, unit size) coordinates.
    Eigen::VectorXd meanShape;
    Eigen::MatrixXd shapeBasis;
    Eigen::VectorXd shapeVariances;
    std::vector<Triangle> triangles;
    // Pixels per normalised unit of the level-0 reference frame.
    double referenceScale = 100.0;

    // Colour texture model (3 values per level-0 reference pixel).
    Eigen::VectorXd textureMean;
    Eigen::MatrixXd textureBasis;
    Eigen::VectorXd textureVariances;
    double meanTextureScale = 50.0;   // average photometric scale alpha of the training images
    double meanTextureOffset = 128.0; // average photometric offset beta

    // Combined model: c = Q^T [Ws b_s; b_g].
    double shapeWeight = 1.0;
    Eigen::MatrixXd combinedBasis; // (ns + ng) x nc
    Eigen::VectorXd combinedVariances;

    // Fitting texture models, level 0 first (finest): fitChannels() values per reference pixel,
    // channel after channel.
    AamFitFeatures fitFeatures = AamFitFeatures::Grey;
    std::vector<AamTextureLevel> levels;
    int fitChannels() const { return fitFeatures == AamFitFeatures::Grey ? 1 : 2; }

    // Where the face detector's keypoints put the face: the mean training shape in the frame of
    // the detector's eye centres and mouth corners (see initialShapeFromDetection). Corrects the
    // systematic offset between the detector's keypoints and the 23 points. Empty if the model
    // was built without a detector.
    Eigen::VectorXd detectorShape;
    // Linear regression of the shape on all five detector keypoints in that frame: the start is
    // detectorShape + detectorRegression (k - detectorKeypointMean), with k the 5 keypoints
    // (eyes, nose tip, mouth corners; 10 values) mapped into the frame. The nose and the residual
    // positions of the eyes and mouth corners say where the face turns and how its proportions
    // differ from the mean. Empty when not calibrated (then the mean detectorShape is the start).
    Eigen::MatrixXd detectorRegression; // 2k x 10
    Eigen::VectorXd detectorKeypointMean; // 10

    // Exemplar detail: the fine structure the model's synthesis misses on E of its training images
    // (teeth, lip highlights, skin grain: textureDetail() in AamBuilder.h), kept so that synthesis
    // puts real detail back on the model's smooth texture (AamSynthesizer).
    // Column i: that image's combined parameters and its residual, quantised to 8 bits with the
    // scale exemplarScales[i]. Empty for models built without exemplars.
    Eigen::MatrixXd exemplarParams; // nc x E
    Eigen::Matrix<std::int8_t, Eigen::Dynamic, Eigen::Dynamic> exemplarDetail; // 3N x E
    Eigen::VectorXd exemplarScales; // E
    int exemplarCount() const { return int(exemplarParams.cols()); }

    // The texture bases (colour and every fitting level) hold single-precision values, and the
    // file stores them in 4 bytes each (version 4): half the size of a model, whose bases are
    // nearly all of it. The builder rounds its bases so; the values stay doubles in memory, so a
    // model and the file written from it agree exactly.
    bool singlePrecisionBases = false;

    int trainingImages = 0;
    // Stable identifier of this model (hash of its contents); dynamic models record it.
    std::string identifier;

    int pointCount() const { return int(meanShape.size() / 2); }
    int shapeModes() const { return int(shapeBasis.cols()); }
    int textureModes() const { return int(textureBasis.cols()); }
    int combinedModes() const { return int(combinedBasis.cols()); }

    // The mean shape in pixel coordinates of the reference frame of `level` (and the similarity
    // from normalised to that frame).
    Similarity referenceTransform(int level) const;
    Eigen::VectorXd referenceShape(int level) const;

    // Builds the warps of every level; called by the builder and by load().
    void prepare();
    const PiecewiseAffineWarp &warp(int level) const { return m_warps.at(size_t(level)); }

    // Combined parameters <-> shape and texture parameters.
    Eigen::VectorXd combinedFromParts(const Eigen::VectorXd &shapeParams,
                                      const Eigen::VectorXd &textureParams) const;
    void partsFromCombined(const Eigen::VectorXd &combined, Eigen::VectorXd &shapeParams,
                           Eigen::VectorXd &textureParams) const;

    // Versioned binary file, written atomically. load() throws lipsync::Error naming the file for a
    // wrong magic, version or truncated/corrupt content.
    void save(const std::string &path) const;
    static AamModel load(const std::string &path);
    // The same from the file's bytes; `pathForErrors` only names the source in errors.
    static AamModel fromBytes(const std::string &data, const std::string &pathForErrors = {});
    // Whether a file's first bytes are an AAM file's magic (what load() checks first).
    static bool hasMagic(std::string_view firstBytes);
    // Hash of the model contents (what `identifier` holds after building).
    std::string computeIdentifier() const;

private:
    std::string serialise(bool withIdentifier) const;
    std::vector<PiecewiseAffineWarp> m_warps;
};

} // namespace lipsync
