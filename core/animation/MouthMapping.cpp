#include "animation/MouthMapping.h"

#include "animation/MouthTrack.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

namespace {

// Where a shape sits before any frame taught it (opening, width, rounding, teeth on the 0..1
// scales): Rhubarb's drawings read as measures.
constexpr std::array<std::array<double, 4>, kMouthShapeCount> kDrawnShapes{{
    {0.00, 0.45, 0.30, 0.20}, // A closed
    {0.20, 0.55, 0.35, 0.60}, // B teeth clenched
    {0.55, 0.55, 0.50, 0.50}, // C open
    {0.90, 0.60, 0.60, 0.40}, // D wide open
    {0.45, 0.35, 0.60, 0.40}, // E rounded
    {0.25, 0.10, 0.70, 0.30}, // F puckered
    {0.15, 0.50, 0.30, 0.70}, // G teeth on the lower lip
    {0.50, 0.50, 0.50, 0.50}, // H tongue raised
    {0.05, 0.45, 0.35, 0.30}, // X rest
}};
constexpr int kShapeFramesNeeded = 5; // fewer: the drawn shape stays
constexpr double kPhonePrior = 0.5;   // the phone's own shape; the other speech shapes share the rest
constexpr double kSmallestSpread = 0.05;

// The measures behind the cue features (MouthMeasures::values() order).
constexpr int kOpening = 0, kWidth = 1, kRounding = 4, kTeeth = 10;

double percentile(std::vector<double> values, double q)
{
    const size_t k = size_t(std::clamp(q * double(values.size() - 1), 0.0, double(values.size() - 1)));
    std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
    return values[k];
}

bool isSpeechShape(MouthShape s)
{
    return s != MouthShape::A && s != MouthShape::X;
}

} // namespace

MouthMapping MouthMapping::learn(const std::vector<MouthTrack> &tracks)
{
    std::array<std::vector<double>, MouthMeasures::kCount> columns;
    for (const MouthTrack &t : tracks)
        for (const MouthMeasures &m : t.measures) {
            const auto v = m.values();
            for (int k = 0; k < MouthMeasures::kCount; ++k)
                columns[size_t(k)].push_back(v[size_t(k)]);
        }
    int speech = 0;
    for (const MouthTrack &t : tracks)
        for (int p : t.phones)
            speech += seedShapeOfPhone(p) != MouthShape::X ? 1 : 0;
    if (speech < kMinimumFrames)
        throw Error("mouth cues are learned from the project's tracked and aligned speech, and it has "
                    + std::to_string(speech) + " frames of it; at least " + std::to_string(kMinimumFrames)
                    + " are needed");
    MouthMapping mapping;
    for (int k = 0; k < MouthMeasures::kCount; ++k) {
        mapping.m_low[size_t(k)] = percentile(columns[size_t(k)], 0.02);
        mapping.m_high[size_t(k)] = std::max(percentile(columns[size_t(k)], 0.98), mapping.m_low[size_t(k)] + 1e-9);
    }
    // Each shape's mean over the frames its phones give it, and the pooled spread within shapes.
    std::array<CueFeatures, kMouthShapeCount> sum{};
    std::array<CueFeatures, kMouthShapeCount> sumSq{};
    sum.fill(CueFeatures::Zero());
    sumSq.fill(CueFeatures::Zero());
    for (const MouthTrack &t : tracks)
        for (size_t i = 0; i < t.measures.size(); ++i) {
            const size_t s = size_t(seedShapeOfPhone(t.phones[i]));
            const CueFeatures f = mapping.cueFeatures(t.measures[i]);
            sum[s] += f;
            sumSq[s] += f.cwiseProduct(f);
            ++mapping.m_frames[s];
        }
    CueFeatures within = CueFeatures::Zero();
    int pooled = 0;
    for (size_t s = 0; s < kMouthShapeCount; ++s) {
        const int n = mapping.m_frames[s];
        if (n < kShapeFramesNeeded) {
            mapping.m_shapes[s] = Eigen::Map<const CueFeatures>(kDrawnShapes[s].data());
            mapping.m_frames[s] = 0;
            continue;
        }
        mapping.m_shapes[s] = sum[s] / n;
        within += sumSq[s] - n * mapping.m_shapes[s].cwiseProduct(mapping.m_shapes[s]);
        pooled += n;
    }
    mapping.m_spread = (within / std::max(1, pooled)).cwiseMax(0.0).cwiseSqrt().cwiseMax(kSmallestSpread);
    return mapping;
}

double MouthMapping::normalised(int index, double value) const
{
    const double low = m_low[size_t(index)], high = m_high[size_t(index)];
    return std::clamp((value - low) / (high - low), 0.0, 1.0);
}

MouthMapping::CueFeatures MouthMapping::cueFeatures(const MouthMeasures &m) const
{
    const auto v = m.values();
    CueFeatures f;
    f << normalised(kOpening, v[kOpening]), normalised(kWidth, v[kWidth]), normalised(kRounding, v[kRounding]),
        normalised(kTeeth, v[kTeeth]);
    return f;
}

MouthShape MouthMapping::classify(const MouthMeasures &m, int phone) const
{
    const MouthShape seed = seedShapeOfPhone(phone);
    if (!isSpeechShape(seed))
        return seed; // X in silence and breath, A on /p b m/
    const CueFeatures f = cueFeatures(m);
    MouthShape best = seed;
    double bestScore = -INFINITY;
    for (int s = 0; s < kMouthShapeCount; ++s) {
        const MouthShape shape = MouthShape(s);
        if (!isSpeechShape(shape))
            continue;
        const double prior = shape == seed ? kPhonePrior : (1.0 - kPhonePrior) / 6.0;
        const double score =
            -0.5 * (f - m_shapes[size_t(s)]).cwiseQuotient(m_spread).squaredNorm() + std::log(prior);
        if (score > bestScore) {
            bestScore = score;
            best = shape;
        }
    }
    return best;
}

void MouthMapping::applyUserShapes(const std::map<std::string, std::array<double, 4>> &shapes)
{
    for (const auto &[letter, values] : shapes)
        if (const std::optional<MouthShape> s = parseMouthShape(letter); s && *s != MouthShape::X) {
            m_shapes[size_t(*s)] = Eigen::Map<const CueFeatures>(values.data());
            m_users[size_t(*s)] = true;
        }
}

} // namespace lipsync
