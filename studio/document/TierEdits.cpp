#include "document/TierEdits.h"

#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lipsync::studio::tieredit {

namespace {

TierKind other(TierKind kind)
{
    return kind == TierKind::Words ? TierKind::Phones : TierKind::Words;
}

// The boundary of `tier` at time t (within kSameTime), or -1.
int boundaryAt(const Tier &tier, double t)
{
    return boundaryNear(tier, t, kSameTime);
}

void limitsOf(const Tier &tier, int b, double *lower, double *upper)
{
    const Interval &before = tier.intervals[size_t(b - 1)];
    const Interval &after = tier.intervals[size_t(b)];
    const bool shared = std::abs(before.end - after.start) < kSameTime;
    *lower = std::max(*lower, shared ? before.start + kSnap : before.end);
    *upper = std::min(*upper, after.end - kSnap);
}

void setBoundary(Tier &tier, int b, double t)
{
    Interval &before = tier.intervals[size_t(b - 1)];
    Interval &after = tier.intervals[size_t(b)];
    if (std::abs(before.end - after.start) < kSameTime) {
        before.end = t;
        before.userEdited = true;
    }
    after.start = t;
    after.userEdited = true;
}

bool validBoundary(const Tier &tier, int b)
{
    return b >= 1 && b < int(tier.intervals.size());
}

} // namespace

double snap(double t)
{
    return std::round(t / kSnap) * kSnap;
}

double boundaryTime(const Tier &tier, int boundary)
{
    return tier.intervals.at(size_t(boundary)).start;
}

int boundaryNear(const Tier &tier, double t, double tolerance)
{
    int best = -1;
    double bestDistance = tolerance;
    for (int b = 1; b < int(tier.intervals.size()); ++b) {
        const double d = std::abs(tier.intervals[size_t(b)].start - t);
        if (d <= bestDistance) {
            bestDistance = d;
            best = b;
        }
    }
    return best;
}

void boundaryLimits(const TierPair &tiers, TierKind kind, int boundary, double *lower, double *upper)
{
    *lower = -std::numeric_limits<double>::infinity();
    *upper = std::numeric_limits<double>::infinity();
    const Tier &tier = tiers[kind];
    if (!validBoundary(tier, boundary))
        return;
    limitsOf(tier, boundary, lower, upper);
    const Tier &linked = tiers[other(kind)];
    const int b = boundaryAt(linked, boundaryTime(tier, boundary));
    if (b > 0)
        limitsOf(linked, b, lower, upper);
}

bool moveBoundary(TierPair &tiers, TierKind kind, int boundary, double t)
{
    Tier &tier = tiers[kind];
    if (!validBoundary(tier, boundary))
        return false;
    double lower = 0, upper = 0;
    boundaryLimits(tiers, kind, boundary, &lower, &upper);
    if (lower > upper)
        return false; // no room at all (a 10 ms neighbour)
    const double old = boundaryTime(tier, boundary);
    const double target = std::clamp(snap(t), lower, upper);
    if (std::abs(target - old) < 1e-9)
        return false;
    Tier &linked = tiers[other(kind)];
    const int b = boundaryAt(linked, old);
    setBoundary(tier, boundary, target);
    if (b > 0)
        setBoundary(linked, b, target);
    return true;
}

bool split(TierPair &tiers, TierKind kind, double t)
{
    Tier &tier = tiers[kind];
    t = snap(t);
    const int i = tier.indexAt(t);
    if (i < 0)
        return false;
    Interval &iv = tier.intervals[size_t(i)];
    if (t - iv.start < kSnap - 1e-9 || iv.end - t < kSnap - 1e-9)
        return false;
    Interval second = iv;
    second.start = t;
    second.userEdited = true;
    iv.end = t;
    iv.userEdited = true;
    tier.intervals.insert(tier.intervals.begin() + i + 1, second);
    return true;
}

bool mergeWithNext(TierPair &tiers, TierKind kind, int index)
{
    Tier &tier = tiers[kind];
    if (index < 0 || index + 1 >= int(tier.intervals.size()))
        return false;
    Interval &first = tier.intervals[size_t(index)];
    const Interval &next = tier.intervals[size_t(index + 1)];
    std::string label;
    if (PhoneSet::isSilence(first.label))
        label = next.label;
    else if (PhoneSet::isSilence(next.label) || kind == TierKind::Phones)
        label = first.label;
    else
        label = first.label + ' ' + next.label;
    first.end = next.end;
    first.label = label;
    first.userEdited = true;
    tier.intervals.erase(tier.intervals.begin() + index + 1);
    return true;
}

int wordBetweenPhones(const TierPair &tiers, int index)
{
    const Tier &phones = tiers.phones;
    if (index < 0 || index + 1 >= int(phones.intervals.size()))
        return -1;
    const Interval &a = phones.intervals[size_t(index)];
    const Interval &b = phones.intervals[size_t(index + 1)];
    const int wa = tiers.words.indexAt(0.5 * (a.start + a.end));
    const int wb = tiers.words.indexAt(0.5 * (b.start + b.end));
    if (wa < 0 || wb < 0 || wa == wb)
        return -1;
    const auto spoken = [&](int w) { return !PhoneSet::isSilence(tiers.words.intervals[size_t(w)].label); };
    return spoken(wa) && spoken(wb) ? wa : -1;
}

bool relabel(TierPair &tiers, TierKind kind, int index, const std::string &label)
{
    Tier &tier = tiers[kind];
    if (index < 0 || index >= int(tier.intervals.size()) || label.empty()
        || tier.intervals[size_t(index)].label == label)
        return false;
    tier.intervals[size_t(index)].label = label;
    tier.intervals[size_t(index)].userEdited = true;
    return true;
}

bool insertInterval(TierPair &tiers, TierKind kind, double a, double b, const std::string &label)
{
    Tier &tier = tiers[kind];
    const double lo = snap(std::min(a, b));
    const double hi = snap(std::max(a, b));
    a = lo;
    b = hi;
    if (b - a < kSnap - 1e-9 || tier.intervals.empty())
        return false;
    a = std::max(a, tier.intervals.front().start);
    b = std::min(b, tier.intervals.back().end);
    if (b - a < kSnap - 1e-9)
        return false;
    // A snapped time within rounding of an existing edge is that edge (166 x 0.01 is
    // 1.6600000000000001, a GRID edge 1.66): the neighbour kept whole must not overlap.
    auto onEdge = [&tier](double t) {
        for (const Interval &iv : tier.intervals)
            for (double edge : {iv.start, iv.end})
                if (std::abs(edge - t) <= 1e-9)
                    return edge;
        return t;
    };
    a = onEdge(a);
    b = onEdge(b);
    std::vector<Interval> out;
    out.reserve(tier.intervals.size() + 2);
    bool inserted = false;
    for (const Interval &iv : tier.intervals) {
        if (iv.end <= a + 1e-9 || iv.start >= b - 1e-9) {
            if (!inserted && iv.start >= b - 1e-9) {
                out.push_back(Interval{a, b, label, true});
                inserted = true;
            }
            out.push_back(iv);
            continue;
        }
        if (iv.start < a - 1e-9) {
            Interval left = iv;
            left.end = a;
            left.userEdited = true;
            out.push_back(left);
        }
        if (!inserted) {
            out.push_back(Interval{a, b, label, true});
            inserted = true;
        }
        if (iv.end > b + 1e-9) {
            Interval right = iv;
            right.start = b;
            right.userEdited = true;
            out.push_back(right);
        }
    }
    if (!inserted)
        out.push_back(Interval{a, b, label, true});
    if (out == tier.intervals)
        return false;
    tier.intervals = std::move(out);
    return true;
}

std::string validLabel(TierKind kind, const QString &text)
{
    const QString trimmed = text.trimmed();
    if (trimmed.isEmpty())
        return {};
    if (kind == TierKind::Phones) {
        const int index = PhoneSet::index(trimmed.toStdString());
        return index < 0 ? std::string() : PhoneSet::label(index);
    }
    if (trimmed.contains(QLatin1Char(' ')) || trimmed.contains(QLatin1Char('\t')))
        return {};
    return trimmed.toStdString();
}

} // namespace lipsync::studio::tieredit
