#include "align/FrameLabels.h"

#include "util/Error.h"
#include "util/PhoneSet.h"

#include <cmath>
#include <map>

namespace lipsync {

namespace {
std::string labelAt(const Tier &phones, double t)
{
    // The first interval holding t ([start, end)), by a scan rather than Tier::indexAt's
    // binary search: tiers read from outside files (TextGrid, .lab) are voted before anything
    // has checked that they are sorted without overlap (Tier::defect).
    for (const Interval &interval : phones.intervals)
        if (t >= interval.start && t < interval.end)
            return interval.label.empty() ? std::string(PhoneSet::kSilenceLabel) : interval.label;
    return std::string(PhoneSet::kSilenceLabel);
}
} // namespace

std::vector<std::string> voteFrameLabels(const Tier &phones, const FrameClock &frames, const MfccOptions &o)
{
    return voteFrameLabels(phones, frames, 0, frames.count(), o);
}

std::vector<std::string> voteFrameLabels(const Tier &phones, const FrameClock &frames, int firstFrame,
                                         int frameCount, const MfccOptions &o)
{
    if (!(frames.rate() > 0))
        throw Error("frame voting needs a positive video frame rate");
    std::vector<std::string> labels(size_t(std::max(frameCount, 0)));
    const double end = phones.endTime();
    for (int n = 0; n < frameCount; ++n) {
        const int i = firstFrame + n;
        const double from = frames.time(i), to = frames.endTime(i), centre = 0.5 * (from + to);
        // Audio frames j with c_j in [from, to).
        int j = std::max(0, int(std::ceil((from - o.windowSeconds / 2) / o.shiftSeconds - 1e-9)));
        struct Vote
        {
            int count = 0;
            double nearest = INFINITY; // distance of its nearest audio frame centre
            int nearestFrame = 0;
        };
        std::map<std::string, Vote> votes;
        for (;; ++j) {
            const double c = mfccFrameCentre(j, o);
            if (c < from - 1e-12)
                continue;
            if (c >= to - 1e-12 || c >= end)
                break;
            Vote &v = votes[labelAt(phones, c)];
            ++v.count;
            // Strictly nearer only: equally near keeps the earlier frame.
            if (std::abs(c - centre) < v.nearest - 1e-12) {
                v.nearest = std::abs(c - centre);
                v.nearestFrame = j;
            }
        }
        if (votes.empty()) {
            labels[size_t(n)] = labelAt(phones, centre);
            continue;
        }
        const std::string *best = nullptr;
        Vote bestVote;
        for (const auto &[label, v] : votes)
            if (!best || v.count > bestVote.count
                || (v.count == bestVote.count
                    && (v.nearest < bestVote.nearest - 1e-12
                        || (std::abs(v.nearest - bestVote.nearest) <= 1e-12 && v.nearestFrame < bestVote.nearestFrame)))) {
                best = &label;
                bestVote = v;
            }
        labels[size_t(n)] = *best;
    }
    return labels;
}

} // namespace lipsync
