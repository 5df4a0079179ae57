#include "align/Realignment.h"

#include "align/Lexicon.h"
#include "util/PhoneSet.h"

#include <algorithm>

namespace lipsync {

namespace {

constexpr double kEps = 1e-6;

// The aligner's words for one word-tier label (a merged interval may hold several).
std::vector<std::string> wordsOf(const std::string &label)
{
    if (PhoneSet::isSilence(label))
        return {};
    if (PhoneSet::isBreath(label))
        return {"[" + label + "]"};
    return Lexicon::splitWords(label);
}

// Replaces [a, b] of `tier` by `replacement` clipped to it. An interval reaching into [a, b]
// from outside keeps only its outside part(s), so the result stays sorted without overlap
// (Tier::defect): a phone ending at the aligner's 95 x 0.01 = 0.9500000000000001 beside a GRID
// word edge at 0.95 reaches an ulp into a stretch starting there, and a phone the user merged
// across a word edge straddles it.
void splice(Tier &tier, double a, double b, const Tier &replacement)
{
    std::vector<Interval> out;
    for (const Interval &iv : tier.intervals) {
        if (iv.end <= a || iv.start >= b) {
            out.push_back(iv); // outside, touching at most
            continue;
        }
        if (iv.start < a - kEps) {
            Interval before = iv;
            before.end = a;
            out.push_back(before);
        }
        if (iv.end > b + kEps) {
            Interval after = iv;
            after.start = b;
            out.push_back(after);
        }
    }
    for (Interval iv : replacement.intervals) {
        iv.start = std::max(a, iv.start);
        iv.end = std::min(b, iv.end);
        if (iv.end > iv.start + kEps)
            out.push_back(iv);
    }
    std::stable_sort(out.begin(), out.end(), [](const Interval &x, const Interval &y) { return x.start < y.start; });
    tier.intervals = std::move(out);
}

} // namespace

std::vector<Realignment::Stretch> Realignment::freeStretches(const Tier &words, const Tier &phones, double a, double b)
{
    std::vector<Stretch> out;
    if (b < a)
        std::swap(a, b);
    bool open = false;
    bool spoken = false;
    double runStart = 0, runEnd = 0;
    auto close = [&] {
        if (open && spoken)
            out.emplace_back(runStart, runEnd);
        open = spoken = false;
    };
    for (const Interval &w : words.intervals) {
        if (w.end <= a + 1e-9 || w.start >= b - 1e-9) {
            close();
            continue;
        }
        bool fixed = w.userEdited;
        for (const Interval &p : phones.intervals)
            if (p.userEdited && p.end > w.start + kEps && p.start < w.end - kEps)
                fixed = true;
        if (fixed) {
            close();
            continue;
        }
        if (!open) {
            open = true;
            runStart = w.start;
        }
        runEnd = w.end;
        spoken = spoken || !PhoneSet::isSilence(w.label);
    }
    close();
    return out;
}

Realignment::Realignment(const Tier &words, const Tier &phones, std::vector<Stretch> stretches)
    : m_wordTier(words), m_phoneTier(phones), m_stretches(std::move(stretches))
{
    const double tierEnd = words.endTime();
    auto kept = [this, tierEnd](double t) {
        if (t <= kEps || t >= tierEnd - kEps)
            return false; // the recording's own edges need no constraint
        return std::none_of(m_stretches.begin(), m_stretches.end(),
                            [t](const Stretch &s) { return t > s.first + kEps && t < s.second - kEps; });
    };
    for (const Interval &iv : words.intervals) {
        const std::vector<std::string> inside = wordsOf(iv.label);
        if (inside.empty())
            continue; // a silence's edges are its neighbours' edges
        const int first = int(m_words.size());
        m_words.insert(m_words.end(), inside.begin(), inside.end());
        m_wordSpans.insert(m_wordSpans.end(), inside.size(), {iv.start, iv.end});
        const int last = int(m_words.size()) - 1;
        if (kept(iv.start))
            m_fixed.push_back(FixedBoundary{first, FixedBoundary::Side::Start, iv.start});
        if (kept(iv.end))
            m_fixed.push_back(FixedBoundary{last, FixedBoundary::Side::End, iv.end});
    }
}

namespace {

void unbracketBreaths(Tier &words)
{
    for (Interval &iv : words.intervals)
        if (iv.label.size() > 2 && iv.label.front() == '[' && PhoneSet::index(iv.label.substr(1, iv.label.size() - 2)) == PhoneSet::kBreath)
            iv.label = iv.label.substr(1, iv.label.size() - 2);
}

} // namespace

AlignmentResult Realignment::run(const ForcedAligner &aligner, const Eigen::MatrixXf &features,
                                 const std::vector<std::vector<Pronunciation>> &pronunciations,
                                 double audioDuration) const
{
    AlignmentResult aligned = aligner.align(features, m_words, pronunciations, audioDuration, m_fixed);
    unbracketBreaths(aligned.words);
    AlignmentResult out;
    out.words = m_wordTier;
    out.phones = m_phoneTier;
    for (const auto &[a, b] : m_stretches) {
        splice(out.words, a, b, aligned.words);
        splice(out.phones, a, b, aligned.phones);
    }
    out.words.name = "words";
    out.phones.name = "phones";
    out.logLikelihood = aligned.logLikelihood;
    out.frames = aligned.frames;
    return out;
}

AlignmentResult Realignment::runPiecewise(const SphinxAligner &aligner, const std::vector<float> &samples,
                                          const std::vector<std::vector<Pronunciation>> &pronunciations,
                                          Feedback &feedback) const
{
    AlignmentResult out;
    out.words = m_wordTier;
    out.phones = m_phoneTier;
    const double rate = SphinxAligner::kSampleRate;
    for (const auto &[a, b] : m_stretches) {
        std::vector<std::string> words;
        std::vector<std::vector<Pronunciation>> prons;
        for (size_t i = 0; i < m_words.size(); ++i)
            if (m_wordSpans[i].first >= a - kEps && m_wordSpans[i].second <= b + kEps) {
                words.push_back(m_words[i]);
                prons.push_back(pronunciations.at(i));
            }
        if (words.empty())
            continue;
        const size_t from = std::min(samples.size(), size_t(std::max(0.0, a * rate)));
        const size_t to = std::min(samples.size(), size_t(std::max(0.0, b * rate)));
        const std::vector<float> piece(samples.begin() + long(from), samples.begin() + long(to));
        AlignmentResult aligned = aligner.align(piece, words, prons, b - a, feedback);
        unbracketBreaths(aligned.words);
        for (Tier *tier : {&aligned.words, &aligned.phones})
            for (Interval &iv : tier->intervals) {
                iv.start += a;
                iv.end += a;
            }
        // The piece's own edges are the stretch's (no rounding drift at the kept neighbours).
        aligned.words.intervals.front().start = aligned.phones.intervals.front().start = a;
        aligned.words.intervals.back().end = aligned.phones.intervals.back().end = b;
        splice(out.words, a, b, aligned.words);
        splice(out.phones, a, b, aligned.phones);
        out.logLikelihood += aligned.logLikelihood;
        out.frames += aligned.frames;
    }
    out.words.name = "words";
    out.phones.name = "phones";
    return out;
}

} // namespace lipsync
