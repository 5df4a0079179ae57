#pragma once
// A 2-D line chart (vtkContextView + vtkChartXY) in a VtkWidget: one or more y(x) series plus a
// cursor. The Plots dock's audio envelope is one; the training objective plot (ObjectivePlot)
// builds on it.
#include "plots/VtkWidget.h"

#include <QColor>
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>

namespace lipsync::studio {

class LineChartView : public VtkWidget
{
    Q_OBJECT
public:
    explicit LineChartView(QWidget *parent = nullptr);
    ~LineChartView() override;

    void setTitle(const QString &title);
    void setAxisTitles(const QString &x, const QString &y);
    // A legend of the series' names in the bottom-right corner (where rising curves such as an
    // objective per iteration leave room), in the style of showCornerLegend.
    void setLegendVisible(bool visible);
    // Adds a series (x and y of equal length); returns its index.
    int addSeries(const QString &name, const QVector<double> &x, const QVector<double> &y,
                  const QColor &color, float width = 2.0f);
    void clearSeries();
    int seriesCount() const;
    // The series' names as the legend shows them, in order.
    QStringList seriesNames() const;
    // A vertical line at x (the current frame's time); hidden when x is NaN.
    void setCursor(double x);

private:
    void updateCursor();
    struct Impl;
    std::unique_ptr<Impl> c;
};

} // namespace lipsync::studio
