#pragma once
// A labelled interval tier (words or phones), times in seconds from the start of the media.
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

struct Interval
{
    double start = 0.0;
    double end = 0.0;
    std::string label;
    bool userEdited = false; // a user moved or relabelled it: re-alignment keeps it

    bool operator==(const Interval &) const = default;
};

// What makes a tier unsaveable: interval `index`'s `member` ("start" or "end") and why.
struct TierDefect
{
    int index = 0;
    std::string member;
    std::string message;
};

struct Tier
{
    std::string name;
    std::vector<Interval> intervals;

    bool isEmpty() const { return intervals.empty(); }
    double endTime() const { return intervals.empty() ? 0.0 : intervals.back().end; }
    // Index of the interval holding time t, or -1.
    int indexAt(double t) const;
    // The first violation of the tier's invariant, or nothing: every time is finite, no start is
    // negative, no end before its start, and the intervals are sorted without overlap (each
    // starts at or after the previous one's end; gaps are allowed). The project loader refuses
    // such a tier and the studio's document accepts no edit that makes one, so indexAt and the
    // timeline can rely on it.
    std::optional<TierDefect> defect() const;
    bool operator==(const Tier &) const = default;
};

} // namespace lipsync
