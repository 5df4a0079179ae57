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

    static constexpr std::string_view kSilenceLabel = "sil";
    static constexpr std::string_view kBreathLabel = "br";

    // Labels in index order: AA AE AH ... ZH, sil, br.
    static const std::array<std::string_view, kCount> &labels();
    static std::string label(int index);
    // Index of an ARPAbet label; case-insensitive, stress digits (AH0, IY1) stripped; silence and
    // breath labels as isSilence and isBreath say. -1 if unknown (also for digits alone: "2" is a
    // word, not a phone).
    static int index(std::string_view label);
    // The one silence test of every tier, phone or word (aligners, readers, editors, views):
    // "", "sil", "sp", "<sil>", "<eps>", "silence", "sil!", case-insensitive, so what aligners,
    // HTK, GRID and Praat write for a pause.
    static bool isSilence(std::string_view label) { return index(label) == kSilence; }
    // A breath or other non-speech noise: "br", "breath", "<br>", "spn", "noise".
    static bool isBreath(std::string_view label) { return index(label) == kBreath; }
    // A phone of speech: a known index that is neither silence nor breath.
    static bool isSpeech(int index) { return index >= 0 && index < kCount && index != kSilence && index != kBreath; }
    // /p b m/: the phones whose articulation closes the lips (BilabialClosure, the realism
    // report's closure measure).
    static bool isBilabial(int index) { return index == kB || index == kM || index == kP; }
    static bool isBilabial(std::string_view label) { return isBilabial(index(label)); }
    static constexpr int kB = 6, kM = 21, kP = 26;
};

} // namespace lipsync
