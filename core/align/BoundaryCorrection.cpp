#include "align/BoundaryCorrection.h"

#include "align/ForcedAligner.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>
#include <stdexcept>

namespace lipsync {

namespace {

constexpr double kSameTime = 1e-6;
constexpr double kMinimumPhone = 0.010; // one 10 ms frame: what a corrected phone keeps at least
const char *const kKindNames[] = {"onset", "junction", "offset"};

bool isPause(const std::string &label)
{
    return PhoneSet::isSilence(label) || PhoneSet::isBreath(label);
}

// A word boundary of an alignment: the word-tier intervals on either side (-1: none) and the
// index among the non-pause words of the word it starts (onset, junction) or ends (offset).
struct Edge
{
    BoundaryKind kind;
    double time;
    int leftInterval, rightInterval;
    int word;
};

std::vector<Edge> edgesOf(const Tier &words)
{
    std::vector<Edge> edges;
    const auto &w = words.intervals;
    int word = -1;
    for (int i = 0; i < int(w.size()); ++i) {
        if (isPause(w[size_t(i)].label))
            continue;
        ++word;
        const bool joined = i > 0 && !isPause(w[size_t(i - 1)].label)
                            && std::abs(w[size_t(i - 1)].end - w[size_t(i)].start) < kSameTime;
        edges.push_back({joined ? BoundaryKind::Junction : BoundaryKind::Onset, w[size_t(i)].start,
                         i > 0 ? i - 1 : -1, i, word});
        const bool joinsNext = i + 1 < int(w.size()) && !isPause(w[size_t(i + 1)].label)
                               && std::abs(w[size_t(i + 1)].start - w[size_t(i)].end) < kSameTime;
        if (!joinsNext)
            edges.push_back({BoundaryKind::Offset, w[size_t(i)].end, i, i + 1 < int(w.size()) ? i + 1 : -1, word});
    }
    return edges;
}

// The phone tier's intervals ending and starting at `t` (-1: none).
std::pair<int, int> phonesAt(const Tier &phones, double t)
{
    int left = -1, right = -1;
    const auto &p = phones.intervals;
    auto it = std::lower_bound(p.begin(), p.end(), t - kSameTime,
                               [](const Interval &i, double time) { return i.end < time; });
    for (; it != p.end() && it->start <= t + kSameTime; ++it) {
        if (std::abs(it->end - t) < kSameTime)
            left = int(it - p.begin());
        if (std::abs(it->start - t) < kSameTime)
            right = int(it - p.begin());
    }
    return {left, right};
}

std::string labelOr(const std::vector<Interval> &intervals, int index, BoundaryKind kind, bool leftSide)
{
    const bool pauseSide = (kind == BoundaryKind::Onset && leftSide) || (kind == BoundaryKind::Offset && !leftSide);
    if (pauseSide || index < 0)
        return "sil";
    return intervals[size_t(index)].label;
}

std::string lowerCase(std::string s)
{
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

// The boundary `e` of `r`, whose phones on either side are `phones` (phonesAt).
BoundaryError describe(const AlignmentResult &r, const Edge &e, std::pair<int, int> phones)
{
    BoundaryError b;
    b.kind = e.kind;
    b.leftWord = lowerCase(labelOr(r.words.intervals, e.leftInterval, e.kind, true));
    b.rightWord = lowerCase(labelOr(r.words.intervals, e.rightInterval, e.kind, false));
    const auto [lp, rp] = phones;
    b.leftPhone = labelOr(r.phones.intervals, lp, e.kind, true);
    b.rightPhone = labelOr(r.phones.intervals, rp, e.kind, false);
    return b;
}

std::string kindName(BoundaryKind k)
{
    return kKindNames[int(k)];
}

// The group keys of a boundary, the most specific first.
std::vector<std::string> keysOf(const BoundaryError &b)
{
    const std::string kind = kindName(b.kind);
    const std::string &ownPhone = b.kind == BoundaryKind::Offset ? b.leftPhone : b.rightPhone;
    return {kind + " words " + b.leftWord + " " + b.rightWord, kind + " phones " + b.leftPhone + " " + b.rightPhone,
            kind + " phone " + ownPhone, kind};
}

// The median, rounded to the microsecond (what the model file keeps exactly).
double median(std::vector<double> v)
{
    const size_t n = v.size();
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(n / 2), v.end());
    double m = v[n / 2];
    if (n % 2 == 0)
        m = 0.5 * (m + *std::max_element(v.begin(), v.begin() + std::ptrdiff_t(n / 2)));
    return std::round(m * 1e6) / 1e6;
}

using Groups = std::map<std::string, std::vector<double>>;

Groups groupsOf(const std::vector<std::vector<BoundaryError>> &recordings, const std::vector<int> &which)
{
    Groups groups;
    for (int r : which)
        for (const BoundaryError &b : recordings[size_t(r)])
            for (const std::string &key : keysOf(b))
                groups[key].push_back(b.target());
    return groups;
}

// Entries of the groups with at least `minimumCount` boundaries.
std::map<std::string, double> mediansOf(const Groups &groups, int minimumCount)
{
    std::map<std::string, double> out;
    for (const auto &[key, values] : groups)
        if (int(values.size()) >= minimumCount)
            out[key] = median(values);
    return out;
}

double lookup(const std::map<std::string, double> &medians, const BoundaryError &b)
{
    for (const std::string &key : keysOf(b))
        if (auto it = medians.find(key); it != medians.end())
            return it->second;
    return 0.0;
}

} // namespace

double BoundaryError::target() const
{
    return errors.empty() ? 0.0 : std::accumulate(errors.begin(), errors.end(), 0.0) / double(errors.size());
}

std::vector<BoundaryError> BoundaryCorrection::errors(const AlignmentResult &aligned, const Tier &reference)
{
    std::vector<const Interval *> ref;
    for (const Interval &i : reference.intervals)
        if (!isPause(i.label))
            ref.push_back(&i);
    const std::vector<Edge> edges = edgesOf(aligned.words);
    const int words = edges.empty() ? 0 : edges.back().word + 1;
    if (words != int(ref.size()) || words == 0)
        return {};
    std::vector<BoundaryError> out;
    for (const Edge &e : edges) {
        BoundaryError b = describe(aligned, e, phonesAt(aligned.phones, e.time));
        const Interval &own = *ref[size_t(e.word)];
        switch (e.kind) {
        case BoundaryKind::Onset:
            b.errors = {e.time - own.start};
            break;
        case BoundaryKind::Offset:
            b.errors = {e.time - own.end};
            break;
        case BoundaryKind::Junction:
            b.errors = {e.time - ref[size_t(e.word - 1)]->end, e.time - own.start};
            break;
        }
        out.push_back(std::move(b));
    }
    return out;
}

BoundaryCorrection BoundaryCorrection::learn(const std::vector<std::vector<BoundaryError>> &recordings,
                                             const Options &options, BoundaryCorrectionReport *report)
{
    std::vector<int> usable;
    int edges = 0;
    for (int r = 0; r < int(recordings.size()); ++r)
        if (!recordings[size_t(r)].empty()) {
            usable.push_back(r);
            for (const BoundaryError &b : recordings[size_t(r)])
                edges += int(b.errors.size());
        }
    BoundaryCorrectionReport rep;
    rep.utterances = int(usable.size());
    rep.skipped = int(recordings.size() - usable.size());
    rep.boundaries = edges;

    // Cross-validation over the recordings (a seeded random split): the share of held-out edges
    // within the tolerance, uncorrected and for each candidate minimum count.
    const int folds = std::clamp(options.folds, 2, std::max(2, int(usable.size())));
    std::vector<int> order = usable;
    std::mt19937 random(options.seed);
    std::shuffle(order.begin(), order.end(), random);
    std::vector<int> within(options.minimumCounts.size(), 0);
    int withinBefore = 0;
    auto inside = [&](double e) { return std::abs(e) <= options.tolerance + 1e-9; };
    if (usable.size() >= 2) {
        for (int f = 0; f < folds; ++f) {
            std::vector<int> train, test;
            for (size_t i = 0; i < order.size(); ++i)
                (int(i) % folds == f ? test : train).push_back(order[i]);
            const Groups groups = groupsOf(recordings, train);
            for (int r : test)
                for (const BoundaryError &b : recordings[size_t(r)])
                    for (double e : b.errors)
                        withinBefore += inside(e);
            for (size_t c = 0; c < options.minimumCounts.size(); ++c) {
                const auto medians = mediansOf(groups, options.minimumCounts[c]);
                for (int r : test)
                    for (const BoundaryError &b : recordings[size_t(r)]) {
                        const double shift = lookup(medians, b);
                        for (double e : b.errors)
                            within[c] += inside(e - shift);
                    }
            }
        }
    }
    int best = -1;
    for (size_t c = 0; c < within.size(); ++c)
        if (within[c] > withinBefore && (best < 0 || within[c] > within[size_t(best)]
                                          || (within[c] == within[size_t(best)]
                                              && options.minimumCounts[c] > options.minimumCounts[size_t(best)])))
            best = int(c);
    rep.withinBefore = edges ? double(withinBefore) / edges : 0.0;
    rep.withinAfter = best >= 0 && edges ? double(within[size_t(best)]) / edges : rep.withinBefore;

    BoundaryCorrection out;
    if (best >= 0) {
        out.m_minimumCount = options.minimumCounts[size_t(best)];
        for (const auto &[key, values] : groupsOf(recordings, usable))
            if (int(values.size()) >= out.m_minimumCount)
                out.m_entries[key] = {median(values), int(values.size())};
    }
    rep.minimumCount = out.m_minimumCount;
    rep.entries = out.entryCount();
    if (report)
        *report = rep;
    return out;
}

double BoundaryCorrection::offset(const BoundaryError &b) const
{
    for (const std::string &key : keysOf(b))
        if (auto it = m_entries.find(key); it != m_entries.end())
            return it->second.offset;
    return 0.0;
}

void BoundaryCorrection::apply(AlignmentResult &alignment, const std::vector<double> &keep) const
{
    if (empty())
        return;
    auto &words = alignment.words.intervals;
    auto &phones = alignment.phones.intervals;
    for (const Edge &e : edgesOf(alignment.words)) {
        if (std::any_of(keep.begin(), keep.end(), [&](double t) { return std::abs(t - e.time) < kSameTime; }))
            continue;
        const auto [lp, rp] = phonesAt(alignment.phones, e.time);
        const double shift = offset(describe(alignment, e, {lp, rp}));
        if (shift == 0.0)
            continue;
        // Within the phones (or, at the ends of the recording, the one phone) on either side.
        const double lo = lp >= 0 ? phones[size_t(lp)].start + kMinimumPhone : e.time;
        const double hi = rp >= 0 ? phones[size_t(rp)].end - kMinimumPhone : e.time;
        if (lo > hi)
            continue;
        const double t = std::clamp(e.time - shift, std::min(lo, e.time), std::max(hi, e.time));
        if (lp >= 0)
            phones[size_t(lp)].end = t;
        if (rp >= 0)
            phones[size_t(rp)].start = t;
        if (e.leftInterval >= 0)
            words[size_t(e.leftInterval)].end = t;
        if (e.rightInterval >= 0)
            words[size_t(e.rightInterval)].start = t;
    }
}

std::vector<std::string> BoundaryCorrection::lines() const
{
    std::vector<std::string> out;
    char number[64];
    for (const auto &[key, entry] : m_entries) {
        std::snprintf(number, sizeof number, " %.6f %d", entry.offset, entry.count);
        out.push_back(key + number);
    }
    return out;
}

void BoundaryCorrection::addLine(const std::string &line)
{
    std::istringstream in(line);
    std::vector<std::string> tokens;
    for (std::string t; in >> t;)
        tokens.push_back(t);
    if (tokens.size() < 3)
        throw std::invalid_argument("expected 'KIND [LEVEL LABELS] OFFSET COUNT'");
    const std::string &kind = tokens[0];
    if (std::find(std::begin(kKindNames), std::end(kKindNames), kind) == std::end(kKindNames))
        throw std::invalid_argument("unknown boundary kind '" + kind + "' (onset, junction, offset)");
    const size_t labels = tokens.size() - 2;
    const bool wellFormed = labels == 1 || (labels == 3 && tokens[1] == "phone")
                            || (labels == 4 && (tokens[1] == "words" || tokens[1] == "phones"));
    if (!wellFormed)
        throw std::invalid_argument("expected 'KIND', 'KIND phone P', 'KIND phones P P' or 'KIND words W W' before the offset and count");
    std::string key = kind;
    for (size_t i = 1; i < labels; ++i)
        key += " " + tokens[i];
    Entry entry;
    try {
        size_t used = 0;
        entry.offset = std::stod(tokens[labels], &used);
        if (used != tokens[labels].size())
            throw std::invalid_argument("");
        entry.count = std::stoi(tokens[labels + 1], &used);
        if (used != tokens[labels + 1].size())
            throw std::invalid_argument("");
    } catch (const std::exception &) {
        throw std::invalid_argument("expected an offset in seconds and a count after '" + key + "'");
    }
    if (!std::isfinite(entry.offset) || std::abs(entry.offset) > 1.0 || entry.count < 1)
        throw std::invalid_argument("offset of '" + key + "' out of range (|offset| <= 1 s, count >= 1)");
    if (!m_entries.emplace(key, entry).second)
        throw std::invalid_argument("'" + key + "' given twice");
}

} // namespace lipsync
