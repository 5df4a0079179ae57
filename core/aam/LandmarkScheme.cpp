#include "aam/LandmarkScheme.h"

#include <cmath>
#include <sstream>

namespace lipsync {

using enum LandmarkFeature;

const char *landmarkFeatureName(LandmarkFeature feature)
{
    switch (feature) {
    case Eyes: return "eyes";
    case Mouth: return "mouth";
    case Jaw: return "jaw";
    }
    return "?";
}

const std::array<LandmarkDefinition, scheme23::kPointCount> &landmarkDefinitions()
{
    static constexpr std::array<LandmarkDefinition, scheme23::kPointCount> table{{
        {"left_eye_outer", Eyes, 36, -1},
        {"left_eye_top", Eyes, 37, 38},
        {"left_eye_inner", Eyes, 39, -1},
        {"left_eye_bottom", Eyes, 40, 41},
        {"right_eye_inner", Eyes, 42, -1},
        {"right_eye_top", Eyes, 43, 44},
        {"right_eye_outer", Eyes, 45, -1},
        {"right_eye_bottom", Eyes, 46, 47},
        {"mouth_left", Mouth, 48, -1},
        {"upper_lip_left", Mouth, 50, -1},
        {"upper_lip_centre", Mouth, 51, -1},
        {"upper_lip_right", Mouth, 52, -1},
        {"mouth_right", Mouth, 54, -1},
        {"lower_lip_right", Mouth, 56, -1},
        {"lower_lip_centre", Mouth, 57, -1},
        {"lower_lip_left", Mouth, 58, -1},
        {"inner_lip_top", Mouth, 62, -1},
        {"inner_lip_bottom", Mouth, 66, -1},
        {"jaw_left", Jaw, 2, -1},
        {"jaw_left_lower", Jaw, 5, -1},
        {"chin", Jaw, 8, -1},
        {"jaw_right_lower", Jaw, 11, -1},
        {"jaw_right", Jaw, 14, -1},
    }};
    return table;
}

const std::vector<std::pair<int, int>> &landmarkConnections()
{
    static const std::vector<std::pair<int, int>> connections{
        // eyes: closed outlines
        {0, 1}, {1, 2}, {2, 3}, {3, 0},
        {4, 5}, {5, 6}, {6, 7}, {7, 4},
        // outer lip: closed outline
        {8, 9}, {9, 10}, {10, 11}, {11, 12}, {12, 13}, {13, 14}, {14, 15}, {15, 8},
        // inner lip: corner - top - corner - bottom
        {8, 16}, {16, 12}, {12, 17}, {17, 8},
        // jaw line
        {18, 19}, {19, 20}, {20, 21}, {21, 22},
    };
    return connections;
}

int mirroredLandmark(int index)
{
    // Eyes swap corner for corner and lid for lid, the mouth corners and the off-centre lip
    // points swap, the lip centres and the chin stay, the jaw points swap in pairs.
    static constexpr std::array<int, scheme23::kPointCount> mirror{
        6, 5, 4, 7, 2, 1, 0, 3, 12, 11, 10, 9, 8, 15, 14, 13, 16, 17, 22, 21, 20, 19, 18};
    return index >= 0 && index < scheme23::kPointCount ? mirror[size_t(index)] : -1;
}

Eigen::VectorXd mirrorShape(const Eigen::VectorXd &shape, int imageWidth)
{
    Eigen::VectorXd out(shape.size());
    const int n = int(shape.size() / 2);
    for (int i = 0; i < n; ++i) {
        const int j = n == scheme23::kPointCount ? mirroredLandmark(i) : i;
        out[2 * j] = double(imageWidth - 1) - shape[2 * i];
        out[2 * j + 1] = shape[2 * i + 1];
    }
    return out;
}

std::vector<int> landmarkIndices(LandmarkFeature feature)
{
    std::vector<int> out;
    const auto &defs = landmarkDefinitions();
    for (int i = 0; i < int(defs.size()); ++i)
        if (defs[size_t(i)].feature == feature)
            out.push_back(i);
    return out;
}

std::string landmarkSchemeJson()
{
    std::ostringstream s;
    s << "{\n  \"scheme\": \"lipsync-23\",\n  \"version\": 1,\n  \"points\": [\n";
    const auto &defs = landmarkDefinitions();
    for (size_t i = 0; i < defs.size(); ++i) {
        const auto &d = defs[i];
        s << "    {\"index\": " << i << ", \"name\": \"" << d.name << "\", \"feature\": \""
          << landmarkFeatureName(d.feature) << "\", \"ibug68\": [" << d.ibugA;
        if (d.ibugB >= 0)
            s << ", " << d.ibugB;
        s << "], \"mirror\": " << mirroredLandmark(int(i)) << "}" << (i + 1 < defs.size() ? "," : "")
          << "\n";
    }
    s << "  ],\n  \"connections\": [";
    const auto &con = landmarkConnections();
    for (size_t i = 0; i < con.size(); ++i)
        s << (i ? ", " : "") << "[" << con[i].first << ", " << con[i].second << "]";
    s << "],\n  \"eye_corners\": [" << scheme23::kLeftEyeOuter << ", " << scheme23::kRightEyeOuter
      << "]\n}\n";
    return s.str();
}

Eigen::VectorXd mapIbug68To23(const Eigen::VectorXd &ibug68)
{
    Eigen::VectorXd out(2 * scheme23::kPointCount);
    const auto &defs = landmarkDefinitions();
    for (int i = 0; i < scheme23::kPointCount; ++i) {
        const auto &d = defs[size_t(i)];
        Eigen::Vector2d p = ibug68.segment<2>(2 * d.ibugA);
        if (d.ibugB >= 0)
            p = 0.5 * (p + ibug68.segment<2>(2 * d.ibugB));
        out.segment<2>(2 * i) = p;
    }
    return out;
}

Eigen::VectorXd templateShape()
{
    static constexpr double mean[scheme23::kPointCount][2] = {
        {-0.17532, -0.20853}, {-0.11903, -0.22348}, {-0.06622, -0.19405}, {-0.12310, -0.19078},
        {0.09331, -0.18267}, {0.15008, -0.20515}, {0.20262, -0.18237}, {0.15169, -0.17209},
        {-0.12627, 0.07382}, {-0.03267, 0.05047}, {-0.00491, 0.05992}, {0.02803, 0.05488},
        {0.11339, 0.08910}, {0.02280, 0.14823}, {-0.01184, 0.14944}, {-0.04272, 0.14451},
        {-0.00671, 0.08169}, {-0.00893, 0.10911}, {-0.29003, -0.04738}, {-0.20683, 0.17187},
        {-0.01782, 0.28519}, {0.18066, 0.19457}, {0.28983, -0.00628}};
    Eigen::VectorXd shape(2 * scheme23::kPointCount);
    for (int i = 0; i < scheme23::kPointCount; ++i)
        shape.segment<2>(2 * i) << mean[i][0], mean[i][1];
    // Level the eyes.
    const Eigen::Vector2d d = shape.segment<2>(2 * scheme23::kRightEyeOuter)
                              - shape.segment<2>(2 * scheme23::kLeftEyeOuter);
    const double angle = -std::atan2(d.y(), d.x());
    const double c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < scheme23::kPointCount; ++i) {
        const Eigen::Vector2d p = shape.segment<2>(2 * i);
        shape.segment<2>(2 * i) << c * p.x() - s * p.y(), s * p.x() + c * p.y();
    }
    return shape;
}

double normalisedMeanError(const Eigen::VectorXd &shape, const Eigen::VectorXd &truth)
{
    const int n = int(truth.size() / 2);
    double sum = 0.0;
    for (int i = 0; i < n; ++i)
        sum += (shape.segment<2>(2 * i) - truth.segment<2>(2 * i)).norm();
    const double eyes = (truth.segment<2>(2 * scheme23::kLeftEyeOuter)
                         - truth.segment<2>(2 * scheme23::kRightEyeOuter))
                            .norm();
    return eyes > 0 ? sum / n / eyes : std::numeric_limits<double>::infinity();
}

Similarity alignByEyes(const Eigen::VectorXd &from, const Eigen::VectorXd &to)
{
    if (from.size() != 2 * scheme23::kPointCount || to.size() != from.size())
        return alignSimilarity(from, to);
    Eigen::VectorXd corners = Eigen::VectorXd::Zero(scheme23::kPointCount);
    for (int i : scheme23::kEyeCorners)
        corners[i] = 1.0;
    return alignSimilarity(from, to, corners);
}

} // namespace lipsync
