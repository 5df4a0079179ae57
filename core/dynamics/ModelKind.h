#pragma once
// The four dynamic model kinds (docs/models.md §1-§5) and their ids, the vocabulary of model files
// ("kind"), project model references, `lipsync train --kind` and `lipsync evaluate --kinds`.
// createDynamicModel (ModelFile.h) builds a model of each kind; the studio's user-visible names and
// colours are in studio/context/ModelKinds.h.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lipsync {

enum class ModelKind
{
    HmmMean, // "hmm": one Gaussian per phone (§1)
    Brand,   // "brand": Brand's Voice Puppetry (§2)
    Slds,    // "slds": switching linear dynamical system (§3)
    Dpds,    // "dpds": the paper's deterministic process dynamical system (§4)
};

// Every kind, from the baseline to the paper's model.
const std::vector<ModelKind> &allModelKinds();
// Their ids in the same order: "hmm", "brand", "slds", "dpds".
const std::vector<std::string> &dynamicModelKinds();

const char *modelKindId(ModelKind kind);
// The kind of an id (exact, lower case), or nothing.
std::optional<ModelKind> parseModelKind(std::string_view id);
bool isDynamicModelKind(std::string_view id);
// Whether the kind has per-phone means a prior learnt from other speakers can move
// (DynamicModel::setMeanShift): HMM-mean and Brand.
bool modelKindTakesPrior(ModelKind kind);
// The ids for messages, the paper's model first: "dpds, slds, brand or hmm" (`lastSeparator`
// " or "), "dpds, slds, brand, hmm" (", ") or "dpds|slds|brand|hmm" ("|" with `separator` "|").
std::string modelKindIdList(std::string_view lastSeparator = " or ", std::string_view separator = ", ");

} // namespace lipsync
