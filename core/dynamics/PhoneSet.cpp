#include "dynamics/PhoneSet.h"

#include <cctype>

namespace lipsync {

const std::array<std::string_view, PhoneSet::kSize> &PhoneSet::names()
{
    static const std::array<std::string_view, kSize> list{
        "AA", "AE", "AH", "AO", "AW", "AY", "B",  "CH", "D",  "DH", "EH", "ER", "EY", "F",
        "G",  "HH", "IH", "IY", "JH", "K",  "L",  "M",  "N",  "NG", "OW", "OY", "P",  "R",
        "S",  "SH", "T",  "TH", "UH", "UW", "V",  "W",  "Y",  "Z",  "ZH", "sil", "br"};
    return list;
}

std::string PhoneSet::name(int label)
{
    if (label < 0 || label >= kSize)
        return "?";
    return std::string(names()[size_t(label)]);
}

int PhoneSet::index(std::string_view label)
{
    std::string upper;
    for (char c : label)
        if (!std::isspace(static_cast<unsigned char>(c)))
            upper += char(std::toupper(static_cast<unsigned char>(c)));
    while (!upper.empty() && std::isdigit(static_cast<unsigned char>(upper.back())))
        upper.pop_back();
    if (upper.empty() || upper == "SIL" || upper == "SP" || upper == "SPN" || upper == "<EPS>"
        || upper == "PAU" || upper == "H#")
        return kSilence;
    if (upper == "BR" || upper == "BREATH")
        return kBreath;
    for (int i = 0; i < kSilence; ++i)
        if (names()[size_t(i)] == upper)
            return i;
    return -1;
}

} // namespace lipsync
