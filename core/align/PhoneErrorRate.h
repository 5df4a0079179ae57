#pragma once
// How far recognised phones are from reference ones (live recognition, docs/performance.md):
// the phone error rate of speech recognition, (substitutions + deletions + insertions) / reference
// phones, from the Levenshtein alignment of the two phone sequences; silences and breaths are not
// phones here.
#include "annotation/Tier.h"

#include <vector>

namespace lipsync {

// The phones of a tier in order, silence and breath left out, runs of one phone merged.
std::vector<int> spokenPhones(const Tier &phones);
// NaN when the reference is empty.
double phoneErrorRate(const std::vector<int> &reference, const std::vector<int> &recognised);

} // namespace lipsync
