#include "eval/CrossValidation.h"

#include "util/Error.h"

#include <numeric>
#include <random>
#include <string>

namespace lipsync {

std::vector<std::vector<int>> makeFolds(int sequenceCount, int folds, std::uint64_t seed)
{
    if (folds < 2)
        throw Error("cross-validation needs at least 2 folds, got " + std::to_string(folds));
    if (sequenceCount < folds)
        throw Error(std::to_string(folds) + "-fold cross-validation needs at least " + std::to_string(folds)
                    + " sequences, got " + std::to_string(sequenceCount));
    std::vector<int> order(static_cast<size_t>(sequenceCount));
    std::iota(order.begin(), order.end(), 0);
    std::mt19937_64 rng(seed);
    for (size_t i = order.size() - 1; i > 0; --i) {
        const size_t j = size_t(rng() % (i + 1)); // bias ~ 2^-50: irrelevant here
        std::swap(order[i], order[j]);
    }
    std::vector<std::vector<int>> out(static_cast<size_t>(folds));
    for (size_t i = 0; i < order.size(); ++i)
        out[i % size_t(folds)].push_back(order[i]);
    return out;
}

std::vector<int> trainingMembers(const std::vector<std::vector<int>> &folds, size_t heldOut)
{
    std::vector<int> out;
    for (size_t g = 0; g < folds.size(); ++g)
        if (g != heldOut)
            out.insert(out.end(), folds[g].begin(), folds[g].end());
    return out;
}

} // namespace lipsync
