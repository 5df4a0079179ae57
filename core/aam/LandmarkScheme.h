#pragma once
// The studio's 23-point face scheme (the paper's §4 model: "23 points on key features on the eyes,
// mouth and jaw-line", Fig. 2) and its mapping from the iBUG 68-point scheme used by 300-W and
// dlib. The same table ships as resources/aam/landmarks23.json for other tools; a test keeps the
// two in sync. The choice of points (see resources/aam/README.md):
//   eyes  (8): per eye the two corners and the lid centres (mean of the two iBUG lid points),
//   mouth (10): the corners, three points on each outer lip, the inner-lip centres,
//   jaw   (5): iBUG 2, 5, 8 (chin), 11, 14 — the lower face below the eyes.
// "left"/"right" are as seen in the image (iBUG 36 is the image-left eye's outer corner).
#include "aam/Procrustes.h"

#include <Eigen/Core>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace lipsync {

enum class LandmarkFeature { Eyes, Mouth, Jaw };

const char *landmarkFeatureName(LandmarkFeature feature);

struct LandmarkDefinition
{
    const char *name;
    LandmarkFeature feature;
    // iBUG 68-point indices (0-based) averaged to give this point; ibugB == -1: ibugA alone.
    int ibugA;
    int ibugB;
};

namespace scheme23 {
constexpr int kPointCount = 23;
constexpr int kLeftEyeOuter = 0;  // outer eye corners: the NME normaliser
constexpr int kRightEyeOuter = 6;
constexpr int kLeftEyeInner = 2;
constexpr int kRightEyeInner = 4;
// The four eye corners, which speech does not move (alignByEyes).
constexpr int kEyeCorners[] = {kLeftEyeOuter, kLeftEyeInner, kRightEyeInner, kRightEyeOuter};
// The mouth: its corners, three points on each outer lip (the upper left to right, the lower
// right to left) and the inner lips' centres.
constexpr int kMouthLeft = 8;
constexpr int kUpperLipLeft = 9;
constexpr int kUpperLipCentre = 10;
constexpr int kUpperLipRight = 11;
constexpr int kMouthRight = 12;
constexpr int kLowerLipRight = 13;
constexpr int kLowerLipCentre = 14;
constexpr int kLowerLipLeft = 15;
constexpr int kInnerLipTop = 16;
constexpr int kInnerLipBottom = 17;
// The jaw line, image left to right: its upper ends (iBUG 2 and 14) and the chin (iBUG 8).
constexpr int kJawLeft = 18;
constexpr int kChin = 20;
constexpr int kJawRight = 22;
constexpr int kIbugPointCount = 68;
} // namespace scheme23

const std::array<LandmarkDefinition, scheme23::kPointCount> &landmarkDefinitions();
// Drawing connectivity (pairs of indices): eye outlines, outer and inner lips, the jaw line.
const std::vector<std::pair<int, int>> &landmarkConnections();
// Indices of the points of one feature group, in scheme order.
std::vector<int> landmarkIndices(LandmarkFeature feature);
// The scheme as JSON (what resources/aam/landmarks23.json holds).
std::string landmarkSchemeJson();

// Shapes in core/aam are flat interleaved vectors (x0, y0, x1, y1, ...).
// The point a horizontal mirror image maps point `index` to (left and right swap; points on the
// face's midline map to themselves): the scheme's own symmetric permutation.
int mirroredLandmark(int index);
// The shape of the mirrored image (x -> imageWidth - 1 - x, 0-based pixels) with the points
// renumbered by mirroredLandmark(), so it is again a valid 23-point shape; mirroring twice with the
// same width is the identity. imageWidth 0 mirrors about x = -0.5 (for centred, normalised shapes
// use mirrorShape(shape, 0) and translate).
Eigen::VectorXd mirrorShape(const Eigen::VectorXd &shape, int imageWidth);

// The similarity laying the eye corners of 23-point shape `from` on those of `to` (least squares;
// speech does not move them): how a generated face's shape is drawn into a frame whose tracked
// shape is `to` (FaceRenderer::drawnPose, CameraCompositor). The model's shapes are aligned on
// all their points, so placed at the tracked face's pose a mouth opened or closed more than
// recorded would move their eyes, and the lips and chin with them, off the recording's.
// Falls back on all points for shapes of another scheme.
Similarity alignByEyes(const Eigen::VectorXd &from, const Eigen::VectorXd &to);

// Maps 68 iBUG points (flat, 136 values) to the 23-point scheme (46 values).
Eigen::VectorXd mapIbug68To23(const Eigen::VectorXd &ibug68);

// A typical frontal face in the scheme (centred, unit size, eyes level): the mean of the Procrustes
// -aligned Helen training shapes. Seeds the editor and places points when no AAM exists yet.
Eigen::VectorXd templateShape();

// Mean point-to-point error over the points divided by the outer-eye-corner distance of `truth`.
double normalisedMeanError(const Eigen::VectorXd &shape, const Eigen::VectorXd &truth);

} // namespace lipsync
