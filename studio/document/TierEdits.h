#pragma once
// The edits of the timeline editor as pure functions on a sequence's word and phone tiers, so
// the undo commands only ever store "before" and "after" and the rules can be tested alone.
//
// Boundary b of a tier (1 <= b < size) is the start of interval b; when interval b - 1 ends
// there (the tiers the aligner and GRID produce are contiguous) both edges move together.
// Times snap to 10 ms (the aligner's frame shift); no interval becomes shorter than 10 ms, so a
// boundary never crosses its neighbours. Every interval an edit touches gets userEdited = true
// (re-alignment keeps it, the view marks it).
#include "annotation/Tier.h"
#include "project/TranscriptFit.h"

#include <QString>

#include <optional>
#include <string>

namespace lipsync::studio {

enum class TierKind { Words = 0, Phones = 1 };

struct TierPair
{
    Tier words{"words", {}};
    Tier phones{"phones", {}};
    // How well the transcript fits the sound by the alignment that made these tiers
    // (Sequence::transcriptFit); none when not measured.
    std::optional<TranscriptFit> transcriptFit;

    Tier &operator[](TierKind kind) { return kind == TierKind::Words ? words : phones; }
    const Tier &operator[](TierKind kind) const { return kind == TierKind::Words ? words : phones; }
    bool operator==(const TierPair &) const = default;
};

namespace tieredit {

constexpr double kSnap = 0.01;
// Two boundaries closer than this are the same boundary (word edges on phone edges).
constexpr double kSameTime = 1e-4;

double snap(double t);

// Time of boundary b (the start of interval b).
double boundaryTime(const Tier &tier, int boundary);
// The boundary (1..size-1) nearest to t within `tolerance` seconds, or -1.
int boundaryNear(const Tier &tier, double t, double tolerance);
// The range boundary b may move in: [lower, upper], including the coincident boundary of the
// other tier (which moves along).
void boundaryLimits(const TierPair &tiers, TierKind kind, int boundary, double *lower, double *upper);

// Moves boundary b of `kind` to t (snapped, clamped to its limits); a boundary of the other
// tier at the same time moves with it. False if nothing changed.
bool moveBoundary(TierPair &tiers, TierKind kind, int boundary, double t);
// Splits the interval holding t at t (snapped) into two with the same label.
bool split(TierPair &tiers, TierKind kind, double t);
// Joins interval `index` with the next one. Phones keep the first's label (a silence gives way
// to the other); words join their labels with a space, silence giving way likewise.
bool mergeWithNext(TierPair &tiers, TierKind kind, int index);
// The word ending where phone `index` ends, if phone index + 1 starts another (spoken) word: a
// merge of the two phones would join phones of two words. -1 when both lie in one word or a
// silence is involved.
int wordBetweenPhones(const TierPair &tiers, int index);
// Sets the label of interval `index` (label validated by the caller: see validLabel).
bool relabel(TierPair &tiers, TierKind kind, int index, const std::string &label);
// Carves [a, b) (snapped) out of the tier as one interval labelled `label` ("sil" or "br"):
// intervals overlapping it are trimmed, those inside it removed.
bool insertInterval(TierPair &tiers, TierKind kind, double a, double b, const std::string &label);

// The canonical label for user input, or empty if it is not acceptable: a phone of PhoneSet
// (case-insensitive, stress digits dropped; "sil", "br") or a single word.
std::string validLabel(TierKind kind, const QString &text);

} // namespace tieredit

} // namespace lipsync::studio
