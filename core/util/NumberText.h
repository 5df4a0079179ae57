#pragma once
// Numbers in text files, with a point for the decimal separator whatever the locale (a studio
// run in German must not write "0,04"): std::from_chars and std::to_chars, not printf or streams.
#include <optional>
#include <string>
#include <string_view>

namespace lipsync {

// The whole of `text` as a finite number, or nullopt (empty, trailing characters, NaN, inf).
std::optional<double> parseFiniteNumber(std::string_view text);
// `value` with `decimals` digits after the point, as "%.2f" in the C locale.
std::string formatFixed(double value, int decimals);
// `value` to `significant` digits, as "%.6g" in the C locale.
std::string formatSignificant(double value, int significant);

} // namespace lipsync
