#pragma once
// Synthesis from AAM parameters (Cootes et al. 2001, eq. 5; the paper's §4: "projecting those
// parameters back ... allows us to reconstruct the modelled part of the original image"):
// combined parameters c -> shape x = x0 + Qs c and texture g = g0 + Qg c -> the texture drawn
// through the piecewise-affine warp into a frame at a given pose, with its edge feathered so the
// face blends into the surrounding frame. Everything per frame is precomputed matrices and one
// pass over the face's pixels, so preview and export can run it at video rate.
#include "aam/AamModel.h"
#include "aam/TextureNormalisation.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <vector>

namespace lipsync {

class AamSynthesizer
{
public:
    // `featherPixels`: width of the blended edge in level-0 reference pixels.
    explicit AamSynthesizer(const AamModel &model, double featherPixels = 4.0);

    // Shape in normalised model coordinates.
    Eigen::VectorXd shape(const Eigen::VectorXd &combined) const;
    // Normalised colour texture (3 values per reference pixel).
    Eigen::VectorXf texture(const Eigen::VectorXd &combined) const;
    // The texture as a reference-frame BGR image (CV_32FC3, 0..255) with `photometric` undone;
    // the default photometric transform is the training average.
    cv::Mat textureImage(const Eigen::VectorXd &combined, PhotometricTransform photometric) const;
    PhotometricTransform defaultPhotometric() const;

    // Draws the synthesised face into `frame` (CV_8UC3) at `pose` (model coordinates -> frame).
    void composite(const Eigen::VectorXd &combined, const Similarity &pose, cv::Mat &frame) const;
    void composite(const Eigen::VectorXd &combined, const Similarity &pose,
                   PhotometricTransform photometric, cv::Mat &frame) const;

private:
    const AamModel &m_model;
    Eigen::MatrixXd m_shapeMatrix;   // 2k x nc
    Eigen::MatrixXf m_textureMatrix; // 3N x nc
    Eigen::VectorXf m_textureMean;
    cv::Mat m_alpha;                 // CV_32F feather mask of the reference frame
    std::vector<std::pair<int, int>> m_borderFill; // outside pixel offset <- inside pixel index
};

} // namespace lipsync
