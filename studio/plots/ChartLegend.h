#pragma once
// The legend style of the studio's line charts (trajectory, training objective): small, at the
// right; inside the plot's corner (translucent, the curves visible beneath) or, for charts whose
// curves fill the plot (a trajectory), beside the plot where it hides nothing.
class vtkChartXY;

namespace lipsync::studio {

enum class LegendPlace { InsideCorner, BesidePlot };

// Shows `chart`'s legend at the right, top or bottom (vtkChartLegend::TOP / BOTTOM).
void showCornerLegend(vtkChartXY &chart, int verticalAlignment, LegendPlace place = LegendPlace::InsideCorner);

} // namespace lipsync::studio
