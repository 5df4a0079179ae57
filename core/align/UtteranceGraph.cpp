#include "align/UtteranceGraph.h"

#include "align/AcousticModel.h"
#include "util/PhoneSet.h"

#include <cmath>

namespace lipsync {

namespace {
// Where a path may currently be: states it can leave from (-1 = entry) with the log weight of
// the route, and the fewest frames spent to get there.
struct Frontier
{
    std::vector<GraphEdge> exits;
    int minimumFrames = 0;
};
} // namespace

UtteranceGraph::UtteranceGraph(const std::vector<std::vector<Pronunciation>> &pronunciations,
                               const Options &options)
{
    int phoneInstance = 0;
    auto addPhone = [&](Frontier frontier, int phone, int word) {
        for (int position = 0; position < AcousticModel::kStatesPerPhone; ++position) {
            GraphState s;
            s.modelState = AcousticModel::stateIndex(phone, position);
            s.phone = phone;
            s.position = position;
            s.word = word;
            s.phoneInstance = phoneInstance;
            if (position == 0)
                s.in = frontier.exits;
            else
                s.in = {GraphEdge{int(m_states.size()) - 1, 0.0}};
            m_states.push_back(std::move(s));
        }
        ++phoneInstance;
        return Frontier{{GraphEdge{int(m_states.size()) - 1, 0.0}},
                        frontier.minimumFrames + AcousticModel::kStatesPerPhone};
    };
    auto addWeight = [](Frontier f, double logWeight) {
        for (GraphEdge &e : f.exits)
            e.extra += logWeight;
        return f;
    };
    const double logSil = std::log(options.silenceProbability);
    const double logSkip = std::log(1.0 - options.silenceProbability);
    auto optionalSilence = [&](const Frontier &frontier, bool optional) {
        if (!optional)
            return addPhone(frontier, PhoneSet::kSilence, -1);
        Frontier through = addPhone(addWeight(frontier, logSil), PhoneSet::kSilence, -1);
        Frontier skip = addWeight(frontier, logSkip);
        through.exits.insert(through.exits.end(), skip.exits.begin(), skip.exits.end());
        through.minimumFrames = skip.minimumFrames;
        return through;
    };

    Frontier frontier{{GraphEdge{-1, 0.0}}, 0};
    frontier = optionalSilence(frontier, options.optionalEdgeSilence || pronunciations.empty());
    for (size_t w = 0; w < pronunciations.size(); ++w) {
        const auto &variants = pronunciations[w];
        if (variants.empty())
            continue;
        const double logVariant = -std::log(double(variants.size()));
        Frontier joined;
        joined.minimumFrames = 1 << 30;
        for (const Pronunciation &variant : variants) {
            Frontier f = addWeight(frontier, logVariant);
            for (int phone : variant)
                f = addPhone(f, phone, int(w));
            joined.exits.insert(joined.exits.end(), f.exits.begin(), f.exits.end());
            joined.minimumFrames = std::min(joined.minimumFrames, f.minimumFrames);
        }
        frontier = joined;
        if (w + 1 < pronunciations.size())
            frontier = optionalSilence(frontier, true);
    }
    if (!pronunciations.empty())
        frontier = optionalSilence(frontier, options.optionalEdgeSilence);
    m_minimumFrames = frontier.minimumFrames;
    for (const GraphEdge &e : frontier.exits)
        if (e.from >= 0)
            m_states[size_t(e.from)].exitExtra = e.extra;
    if (options.openEnd)
        for (GraphState &s : m_states)
            s.exitExtra = std::isfinite(s.exitExtra) ? s.exitExtra : 0.0;
}

double UtteranceGraph::logSelf(const AcousticModel &model, int s) const
{
    return std::log(model.selfLoop(m_states[size_t(s)].modelState));
}

double UtteranceGraph::logEdge(const AcousticModel &model, const GraphEdge &edge) const
{
    if (edge.from < 0)
        return edge.extra;
    return std::log(1.0 - model.selfLoop(m_states[size_t(edge.from)].modelState)) + edge.extra;
}

double UtteranceGraph::logExit(const AcousticModel &model, int s) const
{
    const GraphState &state = m_states[size_t(s)];
    if (!std::isfinite(state.exitExtra))
        return -INFINITY;
    return std::log(1.0 - model.selfLoop(state.modelState)) + state.exitExtra;
}

} // namespace lipsync
