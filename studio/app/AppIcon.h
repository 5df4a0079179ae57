#pragma once
// The application icon (a pair of lips over a waveform), painted in code: Debian's Qt needs an
// extra package (libqt6svg6) to read SVG icons, and a painted icon is sharp at every size.
#include <QIcon>

namespace lipsync::studio {

QIcon appIcon();

} // namespace lipsync::studio
