#include "align/PhoneErrorRate.h"

#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

std::vector<int> spokenPhones(const Tier &phones)
{
    std::vector<int> out;
    int previous = -1;
    for (const Interval &i : phones.intervals) {
        const int p = PhoneSet::index(i.label);
        if (p < 0 || PhoneSet::isSilence(i.label) || PhoneSet::isBreath(i.label)) {
            previous = -1;
            continue;
        }
        if (p != previous)
            out.push_back(p);
        previous = p;
    }
    return out;
}

double phoneErrorRate(const std::vector<int> &reference, const std::vector<int> &recognised)
{
    if (reference.empty())
        return NAN;
    // One row of the edit-distance table at a time.
    std::vector<size_t> row(recognised.size() + 1), next(row.size());
    for (size_t j = 0; j < row.size(); ++j)
        row[j] = j;
    for (size_t i = 1; i <= reference.size(); ++i) {
        next[0] = i;
        for (size_t j = 1; j <= recognised.size(); ++j)
            next[j] = std::min({row[j] + 1, next[j - 1] + 1,
                                row[j - 1] + (reference[i - 1] == recognised[j - 1] ? 0 : 1)});
        std::swap(row, next);
    }
    return double(row.back()) / double(reference.size());
}

} // namespace lipsync
