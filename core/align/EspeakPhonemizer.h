#pragma once
// Pronunciations for words outside the dictionary from espeak-ng (libespeak-ng,
// espeak_TextToPhonemes with the en-us voice), mapped from espeak's ASCII phoneme mnemonics
// ("h_@_l_'oU") to ARPAbet.
#include "align/PronunciationDictionary.h"

#include <optional>
#include <string>

namespace lipsync {

class EspeakPhonemizer
{
public:
    // espeak-ng's mnemonics for `word`, phonemes separated by '_' (e.g. "w_'I_z_3_d"), or
    // nullopt if espeak-ng cannot be initialised. Serialised: espeak-ng is not thread-safe.
    static std::optional<std::string> phonemes(const std::string &word);
    // ARPAbet for `word`, or nullopt (espeak-ng missing, or nothing pronounceable).
    static std::optional<Pronunciation> pronounce(const std::string &word);
    // Maps espeak mnemonics (as phonemes() returns them) to PhoneSet indices; unknown
    // mnemonics are skipped.
    static Pronunciation toArpabet(const std::string &espeakPhonemes);
};

} // namespace lipsync
