#include "util/NumberText.h"

#include <charconv>
#include <cmath>

namespace lipsync {

std::optional<double> parseFiniteNumber(std::string_view text)
{
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

std::string formatFixed(double value, int decimals)
{
    char text[64];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed, decimals);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

std::string formatSignificant(double value, int significant)
{
    char text[64];
    const auto [end, error] = std::to_chars(text, text + sizeof text, value, std::chars_format::general, significant);
    return error == std::errc() ? std::string(text, end) : std::string("nan");
}

} // namespace lipsync
