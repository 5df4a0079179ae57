#pragma once
// What an animator reads off a mouth, measured on the AAM's synthesis of one frame's combined
// parameters (eq. 5 of Cootes et al. 2001: shape x = x0 + Qs c, texture g = g0 + Qg c). The shape
// is in the model's normalised frame (centred, unit size, eyes level), so every measure is free of
// head pose and distance to the camera. Left and right are as seen in the image (the scheme's).
#include "aam/AamModel.h"
#include "aam/AamSynthesizer.h"

#include <Eigen/Core>

#include <array>

namespace lipsync {

struct MouthMeasures
{
    // Face-size units (the normalised shape's): inner-lip gap; corner to corner; each corner's
    // distance from the face's midline (half-way between the eyes).
    double opening = 0, width = 0, leftCorner = 0, rightCorner = 0;
    // Outer-lip height over width: high for a rounded, pursed mouth.
    double rounding = 0;
    // Chin below the eyes.
    double jaw = 0;
    // Each side's upper-lip point above, and lower-lip point below, the line of the corners.
    double upperLeft = 0, upperRight = 0, lowerLeft = 0, lowerRight = 0;
    // How bright the inside of the mouth's outline is against the whole face (normalised texture
    // units): teeth showing raise it, and so do lips pressed together; a dark open mouth lowers it.
    double teeth = 0;

    static constexpr int kCount = 11;
    std::array<double, kCount> values() const;
    static MouthMeasures fromValues(const std::array<double, kCount> &v);
};

class MouthMeasurer
{
public:
    explicit MouthMeasurer(const AamModel &aam);
    // `shape`, when given, receives the 23 points the measures were taken on (shape()).
    MouthMeasures measure(const Eigen::VectorXd &combined, Eigen::VectorXd *shape = nullptr) const;
    // The 23 points of `combined` in the normalised frame (x0, y0, x1, y1, ...).
    Eigen::VectorXd shape(const Eigen::VectorXd &combined) const { return m_synth.shape(combined); }
    // The AAM's synthesis the measures are taken on (to draw a mouth of given parameters).
    const AamSynthesizer &synthesizer() const { return m_synth; }

private:
    AamSynthesizer m_synth;
    // The texture's mean inside the inner-mouth outline minus its mean over the face, linear in
    // the combined parameters: m_teethBase + m_teethGain . c (no mouth pixels: both zero).
    double m_teethBase = 0;
    Eigen::RowVectorXd m_teethGain;
};

} // namespace lipsync
