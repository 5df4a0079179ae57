#include "util/PhoneSet.h"

#include <algorithm>
#include <cctype>

namespace lipsync {

const std::array<std::string_view, PhoneSet::kCount> &PhoneSet::labels()
{
    static const std::array<std::string_view, kCount> list{
        "AA", "AE", "AH", "AO", "AW", "AY", "B",  "CH", "D",  "DH", "EH", "ER", "EY", "F",
        "G",  "HH", "IH", "IY", "JH", "K",  "L",  "M",  "N",  "NG", "OW", "OY", "P",  "R",
        "S",  "SH", "T",  "TH", "UH", "UW", "V",  "W",  "Y",  "Z",  "ZH", "sil", "br"};
    return list;
}

std::string PhoneSet::label(int index)
{
    if (index < 0 || index >= kCount)
        return {};
    return std::string(labels()[size_t(index)]);
}

int PhoneSet::index(std::string_view label)
{
    std::string s;
    for (char c : label)
        if (!std::isdigit(static_cast<unsigned char>(c)))
            s += char(std::tolower(static_cast<unsigned char>(c)));
    if (s.empty() && !label.empty())
        return -1;
    if (s.empty() || s == "sil" || s == "sp" || s == "<sil>" || s == "<eps>" || s == "silence" || s == "sil!")
        return kSilence;
    if (s == "br" || s == "spn" || s == "noise" || s == "breath" || s == "<br>")
        return kBreath;
    const auto &list = labels();
    for (int i = 0; i < kSilence; ++i) {
        const std::string_view l = list[size_t(i)];
        if (l.size() == s.size()
            && std::equal(l.begin(), l.end(), s.begin(),
                          [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; }))
            return i;
    }
    return -1;
}

} // namespace lipsync
