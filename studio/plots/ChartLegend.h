#pragma once
// The legend style of the studio's line charts (trajectory, training objective): in the right-hand
// corner the curves leave free, small and translucent so that the curves stay visible beneath.
class vtkChartXY;

namespace lipsync::studio {

// Shows `chart`'s legend at the right, top or bottom (vtkChartLegend::TOP / BOTTOM).
void showCornerLegend(vtkChartXY &chart, int verticalAlignment);

} // namespace lipsync::studio
