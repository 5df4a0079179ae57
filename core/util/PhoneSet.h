#pragma once
// The 41 phone labels of the paper (docs/models.md §0: P = 41): the 39 ARPAbet phonemes of the CMU
// pronouncing dictionary (without stress digits), silence "sil" and breath "br".
// Shared by the aligner (HMM states) and the dynamic models (labels 0..P-1 in this order).
#include <array>
#include <string>
#include <string_view>

namespace lipsync {

class PhoneSet
{
public:
    static constexpr int kCount = 41;
    static constexpr int kSilence = 39; // "sil"
    static constexpr int kBreath = 40;  // "br"

    // Labels in index order: AA AE AH ... ZH, sil, br.
    static const std::array<std::string_view, kCount> &labels();
    static std::string label(int index);
    // Index of an ARPAbet label; case-insensitive, stress digits (AH0, IY1) stripped; "sp",
    // "sil", "SIL", "" and "<sil>" give kSilence; "br", "spn", "noise" give kBreath. -1 if unknown.
    static int index(std::string_view label);
    static bool isSilence(std::string_view label) { return index(label) == kSilence; }
};

} // namespace lipsync
