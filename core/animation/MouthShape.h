#pragma once
// The nine mouth shapes of Rhubarb Lip Sync (its README, "Mouth shapes"), the vocabulary of the
// 2D animation tools and plug-ins that read its output:
//   A  closed mouth, lips pressed: P, B, M          E  slightly rounded: AO (off), ER (bird)
//   B  slightly open, teeth clenched: most           F  puckered lips: UW (you), OW (show), W
//      consonants (K, S, T), EE (bee)               G  upper teeth on the lower lip: F, V
//   C  open: EH (men), AE (bat)                      H  tongue raised behind the upper teeth: long L
//   D  wide open: AA (father)                        X  rest: pauses in speech
// The Preston Blair names (MBP, etc, E, AI, O, U, FV, L, rest) are what Moho and OpenToonz switch
// layers match by name in a .dat file.
#include <optional>
#include <string_view>

namespace lipsync {

enum class MouthShape { A, B, C, D, E, F, G, H, X };
constexpr int kMouthShapeCount = 9;

char mouthShapeLetter(MouthShape shape);
std::optional<MouthShape> parseMouthShape(std::string_view letter);
const char *prestonBlairName(MouthShape shape);
std::optional<MouthShape> parsePrestonBlairName(std::string_view name);
// Rhubarb's description of the shape, in English (the studio translates its own).
const char *mouthShapeDescription(MouthShape shape);

// The shape Rhubarb's documentation gives a phone (PhoneSet index): where learning starts, and
// the prior of MouthMapping::classify. Silence and breath: X.
MouthShape seedShapeOfPhone(int phone);

} // namespace lipsync
