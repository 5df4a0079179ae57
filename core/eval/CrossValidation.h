#pragma once
// k-fold cross-validation split by sequence count (docs/models.md §6.1): the sequence indices are
// permuted with a fixed seed (Fisher-Yates driven by std::mt19937_64, so the split is the same on
// every platform), then fold f gets the positions i with i mod k = f.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lipsync {

constexpr std::uint64_t kDefaultFoldSeed = 2007;

// Throws lipsync::Error when folds < 2 or there are fewer sequences than folds.
std::vector<std::vector<int>> makeFolds(int sequenceCount, int folds = 10,
                                        std::uint64_t seed = kDefaultFoldSeed);
// What trains when fold `heldOut` is held out: the members of every other fold, fold by fold.
std::vector<int> trainingMembers(const std::vector<std::vector<int>> &folds, std::size_t heldOut);

} // namespace lipsync
