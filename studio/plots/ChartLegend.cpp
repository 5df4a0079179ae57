#include "plots/ChartLegend.h"

#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkTextProperty.h>

namespace lipsync::studio {

void showCornerLegend(vtkChartXY &chart, int verticalAlignment, LegendPlace place)
{
    chart.SetShowLegend(true);
    vtkChartLegend *legend = chart.GetLegend();
    // Not inline: vtkChartXY reserves the legend's width beside the plot.
    legend->SetInline(place == LegendPlace::InsideCorner);
    legend->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    legend->SetVerticalAlignment(verticalAlignment);
    legend->GetLabelProperties()->SetFontSize(9);
    legend->GetBrush()->SetOpacity(170);
}

} // namespace lipsync::studio
