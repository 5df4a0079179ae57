#pragma once
// How well a model's training footage covers the phones (docs/models.md §0, "Rare phones"): the
// frames of each of the 39 speech phones; those never seen, whose face the model can only guess
// (the global statistics stand in), and those seen in fewer than kMinimumVarianceFrames frames,
// whose variance is the global one. With the number of context states a phones-in-context model
// made (docs/models.md §5.2), it says in plain words when the footage is too short for the
// chosen options.
#include "dynamics/LabelledSequence.h"

#include <QJsonObject>

#include <array>
#include <string>
#include <vector>

namespace lipsync {

class DynamicModel;

struct PhoneCoverage
{
    std::array<long long, PhoneSet::kCount> frames{};
    std::vector<std::string> unseen; // speech phones without a frame
    std::vector<std::string> rare;   // speech phones with 1 .. kMinimumVarianceFrames - 1 frames
    double speechSeconds = 0;        // frames labelled with a speech phone, in seconds
    // Phones in context: the tied states trained (0: not asked for).
    int contextStates = 0;
    // Whether the model could start from other speakers' mouths (docs/models.md §5.4): false for
    // kinds without per-phone means; `prior` whether it did; `priorTried` whether it was asked to
    // (and weighed the prior, maybe at 0 frames: then it is not offered again).
    bool takesPrior = false, prior = false, priorTried = false;

    static PhoneCoverage of(const std::vector<LabelledSequence> &sequences);
    // The same for a model trained on them: its context states, whether its kind takes a prior
    // and whether it started from one.
    static PhoneCoverage of(const std::vector<LabelledSequence> &sequences, const DynamicModel &trained);
    static constexpr int kSpeechPhones = PhoneSet::kCount - 2; // without silence and breath

    // What the footage lacks for these options, one or two sentences, or empty when it covers
    // them: phones never seen, phones too rare for a variance of their own, and phones in context
    // that made no state beyond the phones themselves; for a model that could start from other
    // speakers' mouths and did not, that it may.
    std::string advice() const;
    // {"speechSeconds", "unseen": [..], "rare": [..], "contextStates", "prior", "advice"}
    QJsonObject toJson() const;
};

} // namespace lipsync
