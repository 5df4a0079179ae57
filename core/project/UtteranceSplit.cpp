#include "project/UtteranceSplit.h"

#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

namespace {

bool isSilence(const Interval &i)
{
    return PhoneSet::isSilence(i.label);
}

// The part of `tier` inside [start, end], moved to start at 0.
Tier excerpt(const Tier &tier, double start, double end)
{
    Tier out{tier.name, {}};
    for (const Interval &i : tier.intervals) {
        if (i.end <= start + 1e-9 || i.start >= end - 1e-9)
            continue;
        out.intervals.push_back(Interval{std::max(i.start, start) - start, std::min(i.end, end) - start, i.label,
                                         i.userEdited});
    }
    return out;
}

} // namespace

std::vector<UtteranceSpan> splitAtPauses(const Tier &words, const Tier &phones, double duration,
                                         const UtteranceSplitOptions &options)
{
    // Groups of consecutive word intervals: a group ends at a pause once it is long enough, or
    // at the best place before it grows too long.
    const std::vector<Interval> &all = words.intervals;
    std::vector<std::pair<size_t, size_t>> groups; // [first, last] word intervals (non-silent ends)
    size_t first = all.size();
    for (size_t i = 0; i < all.size(); ++i) {
        if (isSilence(all[i]))
            continue;
        if (first == all.size()) {
            first = i;
            continue;
        }
        // Word i follows word `previous`; the gap between them is a pause if a silence lies there.
        size_t previous = i - 1;
        while (previous > first && isSilence(all[previous]))
            --previous;
        const double gap = all[i].start - all[previous].end;
        const double sofar = all[previous].end - all[first].start;
        if (gap >= options.minimumPause && sofar >= options.shortest) {
            groups.push_back({first, previous});
            first = i;
            continue;
        }
        if (all[i].end - all[first].start > options.longest) {
            // Too long with word i: end before it, at the longest gap since `first` (a word
            // boundary if there is no silence at all).
            size_t cut = previous;
            double widest = -1.0;
            for (size_t j = first + 1; j <= previous; ++j) {
                if (isSilence(all[j]))
                    continue;
                size_t k = j - 1;
                while (k > first && isSilence(all[k]))
                    --k;
                if (all[j].start - all[k].end > widest && all[k].end - all[first].start >= options.shortest / 2) {
                    widest = all[j].start - all[k].end;
                    cut = k;
                }
            }
            groups.push_back({first, cut});
            first = cut + 1;
            while (first < i && isSilence(all[first]))
                ++first;
        }
    }
    if (first < all.size())
        groups.push_back({first, all.size() - 1});

    std::vector<UtteranceSpan> out;
    auto snapDown = [&](double t) { return options.frames.boundaryAtOrBefore(t); };
    auto snapUp = [&](double t) { return options.frames.boundaryAtOrAfter(t); };
    for (size_t g = 0; g < groups.size(); ++g) {
        size_t last = groups[g].second;
        while (last > groups[g].first && isSilence(all[last]))
            --last;
        const double wordsStart = all[groups[g].first].start;
        const double wordsEnd = all[last].end;
        // Half the pause either side at most, so that neighbours never overlap.
        const double before = g == 0 ? 0.0 : 0.5 * (out.back().end + wordsStart);
        const double after =
            g + 1 < groups.size() ? 0.5 * (wordsEnd + all[groups[g + 1].first].start) : duration;
        UtteranceSpan span;
        span.start = std::max(0.0, snapDown(std::max(before, wordsStart - options.margin)));
        span.end = std::min(snapUp(duration), snapUp(std::min(after, wordsEnd + options.margin)));
        if (g > 0)
            span.start = std::max(span.start, out.back().end);
        span.words = excerpt(words, span.start, span.end);
        span.phones = excerpt(phones, span.start, span.end);
        for (const Interval &i : span.words.intervals)
            if (!isSilence(i))
                span.transcript += (span.transcript.empty() ? "" : " ") + i.label;
        out.push_back(std::move(span));
    }
    return out;
}

} // namespace lipsync
