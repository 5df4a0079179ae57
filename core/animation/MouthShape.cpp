#include "animation/MouthShape.h"

#include "util/PhoneSet.h"

#include <array>
#include <string>

namespace lipsync {

namespace {

constexpr std::array<const char *, kMouthShapeCount> kPrestonBlair{"MBP", "etc", "E", "AI", "O", "U", "FV", "L", "rest"};

} // namespace

char mouthShapeLetter(MouthShape shape)
{
    return "ABCDEFGHX"[int(shape)];
}

std::optional<MouthShape> parseMouthShape(std::string_view letter)
{
    if (letter.size() != 1)
        return std::nullopt;
    const std::string_view letters = "ABCDEFGHX";
    const size_t i = letters.find(letter[0]);
    return i == std::string_view::npos ? std::nullopt : std::optional<MouthShape>(MouthShape(i));
}

const char *prestonBlairName(MouthShape shape)
{
    return kPrestonBlair[size_t(shape)];
}

std::optional<MouthShape> parsePrestonBlairName(std::string_view name)
{
    for (size_t i = 0; i < kPrestonBlair.size(); ++i)
        if (name == kPrestonBlair[i])
            return MouthShape(i);
    return std::nullopt;
}

const char *mouthShapeDescription(MouthShape shape)
{
    switch (shape) {
    case MouthShape::A: return "Closed mouth, lips pressed together: P, B, M";
    case MouthShape::B: return "Slightly open mouth, teeth clenched: most consonants (K, S, T) and EE";
    case MouthShape::C: return "Open mouth: EH as in men, AE as in bat";
    case MouthShape::D: return "Wide open mouth: AA as in father";
    case MouthShape::E: return "Slightly rounded mouth: AO as in off, ER as in bird";
    case MouthShape::F: return "Puckered lips: UW as in you, OW as in show, W";
    case MouthShape::G: return "Upper teeth touching the lower lip: F, V";
    case MouthShape::H: return "Tongue raised behind the upper teeth: long L";
    case MouthShape::X: return "Rest: pauses in speech";
    }
    return "";
}

MouthShape seedShapeOfPhone(int phone)
{
    if (phone < 0 || phone == PhoneSet::kSilence || phone == PhoneSet::kBreath)
        return MouthShape::X;
    const std::string label = PhoneSet::label(phone);
    static const std::array<std::pair<const char *, MouthShape>, 19> kVowelsAndSpecial{{
        {"P", MouthShape::A}, {"B", MouthShape::A}, {"M", MouthShape::A},
        {"EH", MouthShape::C}, {"AE", MouthShape::C}, {"AH", MouthShape::C}, {"EY", MouthShape::C},
        {"AY", MouthShape::C}, {"HH", MouthShape::C},
        {"AA", MouthShape::D}, {"AW", MouthShape::D},
        {"AO", MouthShape::E}, {"ER", MouthShape::E}, {"OY", MouthShape::E},
        {"UW", MouthShape::F}, {"OW", MouthShape::F}, {"W", MouthShape::F}, {"UH", MouthShape::F},
        {"L", MouthShape::H},
    }};
    for (const auto &[name, shape] : kVowelsAndSpecial)
        if (label == name)
            return shape;
    if (label == "F" || label == "V")
        return MouthShape::G;
    return MouthShape::B; // the other consonants, IY and IH
}

} // namespace lipsync
