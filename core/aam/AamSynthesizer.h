#pragma once
// Synthesis from AAM parameters (Cootes et al. 2001, eq. 5; the paper's §4: "projecting those
// parameters back ... allows us to reconstruct the modelled part of the original image"):
// combined parameters c -> shape x = x0 + Qs c and texture g = g0 + Qg c -> the texture drawn
// through the piecewise-affine warp into a frame at a given pose, with its edge feathered so the
// face blends into the surrounding frame.
//
// By default only the lower face is drawn: the mouth, cheeks and jaw come from the model and the
// recording's own eyes, brows and upper face stay, blended over a band between the eyes and the
// upper lip (the articulators are all below it; an AAM re-synthesis of the eyes is blurred and
// half-closed). The synthesised colour is shifted by the mean difference to the frame along the
// blended seam, so the face's lighting matches the frame's. Everything per frame is precomputed
// matrices and one rasterisation of the face's pixels, so preview and export run it at video rate.
//
// A linear texture model reconstructs every frame as a blend of its modes, which smooths away
// what is particular to each image: teeth, specular highlights on the lips, skin grain. The
// synthesised texture gets that detail back from the model's exemplars (real training images):
// the fine part of what the synthesis missed on those nearest the parameters in the whitened
// combined space (AamModel::exemplarDetail), so it adds detail without moving the mouth's coarse
// shape, which the parameters set.
#include "aam/AamModel.h"
#include "aam/TextureNormalisation.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

enum class FaceRegion
{
    Lower, // mouth, cheeks and jaw; the frame's eyes and upper face kept
    Full,  // the whole modelled face (eyes included)
};

struct CompositeOptions
{
    FaceRegion region = FaceRegion::Lower;
    // Offset the synthesised colour (per channel) by the mean frame-minus-synthesis difference
    // over the blended seam, so the face's lighting follows the frame's.
    bool matchColour = true;
    // Add the exemplar detail of the training images nearest the parameters (teeth, lip
    // highlights, skin grain the texture modes smooth away; AamModel::exemplarDetail), when the
    // model has it.
    bool detail = true;
    // With the lower face: draw the AAM's synthesis of its skin too (the model's texture pasted
    // over the recording's), instead of moving the recording's own lower face to the generated
    // shape and drawing only the inside of the mouth (render/LowerFaceWarp, FaceRenderer).
    bool synthesizeSkin = false;
    // With the recording's own lower face: lips closed where the recording's are open are the
    // person's own closed lips from another moment of the background video
    // (render/MouthExemplars), when it has any; otherwise, and when false, the AAM's synthesis.
    bool recordedClosures = true;
    // With the recording's own lower face: the inside of a mouth opened wider than recorded is
    // the person's own open mouth from another moment of the background video, of about the
    // generated opening (render/MouthExemplars); otherwise, and when false, the AAM's synthesis.
    bool recordedInsides = true;

    // The paper's rendering (docs/models.md §7): the AAM's synthesis alone, no colour matching
    // and no exemplar detail.
    static CompositeOptions paper()
    {
        CompositeOptions o;
        o.matchColour = false;
        o.detail = false;
        o.recordedClosures = false;
        o.recordedInsides = false;
        return o;
    }

    // Whether the face is the AAM's synthesis (the whole face, or the lower face's skin) rather
    // than the recording's own lower face moved (render/LowerFaceWarp).
    bool synthesisesFace() const { return region == FaceRegion::Full || synthesizeSkin; }

    bool operator==(const CompositeOptions &) const = default;
};

class AamSynthesizer
{
public:
    // `featherPixels`: width of the blended edge in level-0 reference pixels.
    explicit AamSynthesizer(const AamModel &model, double featherPixels = 4.0);

    // Shape in normalised model coordinates.
    Eigen::VectorXd shape(const Eigen::VectorXd &combined) const;
    // Normalised colour texture (3 values per reference pixel), with the exemplar detail if
    // `detail` and the model has exemplars.
    Eigen::VectorXf texture(const Eigen::VectorXd &combined, bool detail = false) const;
    // The texture as a reference-frame BGR image (CV_32FC3, 0..255) with `photometric` undone;
    // the default photometric transform is the training average.
    cv::Mat textureImage(const Eigen::VectorXd &combined, PhotometricTransform photometric,
                         bool detail = false) const;
    // The exemplars whose detail texture(c, true) adds, and their weights: the two nearest c in
    // the whitened combined parameters, w_k = 1/d_k - 1/d_3 (continuous as exemplars trade
    // places, all on one exemplar at d = 0), scaled to unit Euclidean norm so a blend of two
    // uncorrelated residuals keeps the energy of one. Empty without exemplars.
    std::vector<std::pair<int, float>> detailWeights(const Eigen::VectorXd &combined) const;
    PhotometricTransform defaultPhotometric() const;

    // Draws the synthesised face into `frame` (CV_8UC3) at `pose` (model coordinates -> frame).
    void composite(const Eigen::VectorXd &combined, const Similarity &pose, cv::Mat &frame,
                   const CompositeOptions &options = {}) const;
    void composite(const Eigen::VectorXd &combined, const Similarity &pose, PhotometricTransform photometric,
                   cv::Mat &frame, const CompositeOptions &options = {}) const;
    // How much of each pixel of a `size` frame composite() replaces (CV_32F, 0..1).
    cv::Mat compositeWeight(const Eigen::VectorXd &combined, const Similarity &pose, cv::Size size,
                            FaceRegion region = FaceRegion::Lower) const;

private:
    // Calls visit(x, y, alpha, texel) for every frame pixel the face covers (alpha > 0), where
    // texel points at the bilinearly interpolated BGR value of `texture` (null when not wanted).
    template <class Visit>
    void rasterise(const Eigen::VectorXd &combined, const Similarity &pose, cv::Size size, const cv::Mat &alpha,
                   const cv::Mat *texture, Visit &&visit) const;
    const cv::Mat &alphaOf(FaceRegion region) const { return region == FaceRegion::Full ? m_alpha : m_alphaLower; }

    const AamModel &m_model;
    Eigen::MatrixXd m_shapeMatrix;   // 2k x nc
    Eigen::MatrixXf m_textureMatrix; // 3N x nc
    Eigen::VectorXf m_textureMean;
    Eigen::MatrixXd m_exemplarsWhite; // nc x E, exemplar parameters / sqrt(combined variances)
    Eigen::VectorXd m_invSd;          // nc
    cv::Mat m_alpha;                 // CV_32F feather mask of the reference frame
    cv::Mat m_alphaLower;            // the same times the lower-face ramp
    std::vector<std::pair<int, int>> m_borderFill; // outside pixel offset <- inside pixel index
};

} // namespace lipsync
