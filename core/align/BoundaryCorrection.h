#pragma once
// Word-boundary correction: the systematic offsets between an HMM aligner's word boundaries and
// reference ones, learned from recordings whose word timings are known and subtracted from every
// alignment after the Viterbi pass (boundary-specific statistical correction of HMM segmentation,
// Toledano, Hernández Gómez & Villarrubia, "Automatic phonetic segmentation", IEEE Trans. Speech
// and Audio Processing 11(6), 2003).
//
// An HMM puts a boundary where its states' likelihoods cross, which for a given pair of sounds
// lands consistently early or late against where a person (or the corpus' reference) marks it:
// the first fricative of an utterance half-eaten by the silence model, a word's release absorbed
// into the following /r/. Each boundary is one of three kinds — an onset (silence to word), a
// junction (word to word, no pause) or an offset (word to silence) — and its offset is the median
// signed error (aligned minus reference) of the training boundaries that share, from the most to
// the least specific: the kind and both words; the kind and the two phones that meet; the kind and
// the phone on the word's side; the kind alone. The most specific group with at least
// `minimumCount` examples decides; `minimumCount` itself is chosen by cross-validation over the
// training recordings, and no correction is kept when it does not help there.
//
// Applied to an alignment, each word boundary moves by minus its offset (word and phone tiers
// together), leaving the phones on either side at least one 10 ms frame.
#include "annotation/Tier.h"

#include <map>
#include <string>
#include <vector>

namespace lipsync {

struct AlignmentResult;

enum class BoundaryKind { Onset = 0, Junction = 1, Offset = 2 };

// One word boundary of an alignment against a reference.
struct BoundaryError
{
    BoundaryKind kind = BoundaryKind::Junction;
    std::string leftWord, rightWord;   // "sil" on the silence side
    std::string leftPhone, rightPhone; // PhoneSet labels, "sil" on the silence side
    // Aligned minus reference time, seconds: one value, and for a junction two (the reference
    // may leave a pause between the words): against the left word's end and the right word's start.
    std::vector<double> errors;
    double target() const; // what the correction learns: the mean of `errors`
};

struct BoundaryCorrectionReport
{
    int utterances = 0;        // with matching words
    int skipped = 0;           // whose aligned words differ from the reference's
    int boundaries = 0;        // edges scored (a junction with a gap counts twice)
    int minimumCount = 0;      // chosen; 0 when no correction is kept
    double withinBefore = 0;   // cross-validated share of edges within the tolerance, uncorrected
    double withinAfter = 0;    // ... corrected with the chosen minimum count
    int entries = 0;
};

class BoundaryCorrection
{
public:
    struct Options
    {
        double tolerance = 0.040;                    // seconds; what cross-validation maximises the share within
        std::vector<int> minimumCounts{5, 10, 20, 40}; // candidates
        int folds = 5;
        unsigned seed = 2007;
    };

    bool empty() const { return m_entries.empty(); }
    int minimumCount() const { return m_minimumCount; }
    int entryCount() const { return int(m_entries.size()); }

    // The boundaries of `aligned` (its words and phones tiers) scored against `reference` (word
    // intervals, silences labelled as io/Transcript leaves them). Empty when the non-silence words
    // differ in number.
    static std::vector<BoundaryError> errors(const AlignmentResult &aligned, const Tier &reference);
    // Learns from the errors of each training recording (one vector per recording).
    static BoundaryCorrection learn(const std::vector<std::vector<BoundaryError>> &recordings,
                                    const Options &options, BoundaryCorrectionReport *report = nullptr);
    static BoundaryCorrection learn(const std::vector<std::vector<BoundaryError>> &recordings)
    {
        return learn(recordings, Options{});
    }

    // The offset (seconds, aligned minus reference) for a boundary like `b` (its kind, words and
    // phones); 0 when nothing was learned for it.
    double offset(const BoundaryError &b) const;
    // Moves the word boundaries of `alignment` by minus their offsets. Boundaries at `keep` (times,
    // seconds; a re-alignment's fixed ones) stay.
    void apply(AlignmentResult &alignment, const std::vector<double> &keep = {}) const;

    // Lines of the aligner model file (AcousticModel) and back; parse throws a message for the
    // caller to name its file and line.
    std::vector<std::string> lines() const;
    void addLine(const std::string &line);
    void setMinimumCount(int count) { m_minimumCount = count; }

    bool operator==(const BoundaryCorrection &o) const
    {
        return m_minimumCount == o.m_minimumCount && m_entries == o.m_entries;
    }

private:
    struct Entry
    {
        double offset = 0;
        int count = 0;
        bool operator==(const Entry &) const = default;
    };
    std::map<std::string, Entry> m_entries; // key (kind, level, labels) -> median
    int m_minimumCount = 0;
};

} // namespace lipsync
