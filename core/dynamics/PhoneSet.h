#pragma once
// The label set of the dynamic models (models.md §0): P = 41 phones, the 39 ARPAbet phonemes
// plus silence and breath. Labels are integers 0..P-1 in the order of names().
#include <array>
#include <string>
#include <string_view>

namespace lipsync {

class PhoneSet
{
public:
    static constexpr int kSize = 41;
    static constexpr int kSilence = 39;
    static constexpr int kBreath = 40;

    static const std::array<std::string_view, kSize> &names();
    static std::string name(int label);
    // Index of a phone label as aligners write it: case-insensitive, ARPAbet stress digits
    // dropped ("AH0" -> AH); "sil", "sp", "spn", "" and "<eps>" are silence; "br"/"breath" breath.
    // Returns -1 for anything else.
    static int index(std::string_view label);
};

} // namespace lipsync
