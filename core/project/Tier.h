#pragma once
// A labelled interval tier (words or phones), times in seconds from the start of the media.
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

struct Tier
{
    std::string name;
    std::vector<Interval> intervals;

    bool isEmpty() const { return intervals.empty(); }
    double endTime() const { return intervals.empty() ? 0.0 : intervals.back().end; }
    // Index of the interval holding time t, or -1.
    int indexAt(double t) const;
    bool operator==(const Tier &) const = default;
};

} // namespace lipsync
