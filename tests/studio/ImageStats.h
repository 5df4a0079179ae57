#pragma once
// Measures of a rendered image for the GUI tests.
#include <QImage>

#include <algorithm>
#include <cmath>

namespace lipsync::studio::testing {

// Standard deviation of the grey levels: near 0 for a blank panel, tens for a drawn face.
inline double greyStdDev(const QImage &image)
{
    const QImage g = image.convertToFormat(QImage::Format_Grayscale8);
    double s = 0, s2 = 0;
    for (int r = 0; r < g.height(); ++r)
        for (int c = 0; c < g.width(); ++c) {
            const double v = g.constScanLine(r)[c];
            s += v;
            s2 += v * v;
        }
    const double n = double(g.width()) * g.height();
    return std::sqrt(std::max(0.0, s2 / n - (s / n) * (s / n)));
}

} // namespace lipsync::studio::testing
