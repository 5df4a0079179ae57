#include "plots/LineChartView.h"

#include "plots/ChartLegend.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>

#include <cmath>
#include <limits>
#include <vector>

namespace lipsync::studio {

namespace {

vtkSmartPointer<vtkTable> makeTable(const QString &name, const QVector<double> &x, const QVector<double> &y)
{
    auto table = vtkSmartPointer<vtkTable>::New();
    vtkNew<vtkDoubleArray> xs;
    xs->SetName("x");
    vtkNew<vtkDoubleArray> ys;
    ys->SetName(name.isEmpty() ? "y" : name.toUtf8().constData());
    table->AddColumn(xs);
    table->AddColumn(ys);
    const qsizetype n = std::min(x.size(), y.size());
    table->SetNumberOfRows(vtkIdType(n));
    for (qsizetype i = 0; i < n; ++i) {
        table->SetValue(vtkIdType(i), 0, x[i]);
        table->SetValue(vtkIdType(i), 1, y[i]);
    }
    return table;
}

} // namespace

struct LineChartView::Impl
{
    vtkNew<vtkContextView> view;
    vtkNew<vtkChartXY> chart;
    std::vector<vtkSmartPointer<vtkTable>> tables; // kept alive while plotted
    vtkSmartPointer<vtkTable> cursorTable;
    vtkPlot *cursorPlot = nullptr;
    double cursorX = std::numeric_limits<double>::quiet_NaN();
    double yMin = 0.0;
    double yMax = 1.0;
    int seriesCount = 0;
    QStringList names;
};

LineChartView::LineChartView(QWidget *parent) : VtkWidget(parent), c(std::make_unique<Impl>())
{
    c->view->SetRenderWindow(renderWindow());
    c->view->SetInteractor(interactor());
    c->view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    c->view->GetScene()->AddItem(c->chart);
    c->chart->SetShowLegend(false);
    c->chart->GetTitleProperties()->SetFontSize(13);
    for (int axis : {vtkAxis::BOTTOM, vtkAxis::LEFT}) {
        c->chart->GetAxis(axis)->GetTitleProperties()->SetFontSize(12);
        c->chart->GetAxis(axis)->GetLabelProperties()->SetFontSize(11);
    }
    setMinimumSize(160, 120);
}

LineChartView::~LineChartView() = default;

void LineChartView::setTitle(const QString &title)
{
    c->chart->SetTitle(title.toUtf8().constData());
    update();
}

void LineChartView::setLegendVisible(bool visible)
{
    if (visible)
        showCornerLegend(*c->chart, vtkChartLegend::BOTTOM);
    else
        c->chart->SetShowLegend(false);
    update();
}

void LineChartView::setAxisTitles(const QString &x, const QString &y)
{
    c->chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(x.toUtf8().constData());
    c->chart->GetAxis(vtkAxis::LEFT)->SetTitle(y.toUtf8().constData());
    update();
}

int LineChartView::addSeries(const QString &name, const QVector<double> &x, const QVector<double> &y,
                             const QColor &color, float width)
{
    vtkSmartPointer<vtkTable> table = makeTable(name, x, y);
    vtkPlot *plot = c->chart->AddPlot(vtkChart::LINE);
    plot->SetInputData(table, 0, 1);
    plot->SetColor(static_cast<unsigned char>(color.red()), static_cast<unsigned char>(color.green()),
                   static_cast<unsigned char>(color.blue()), static_cast<unsigned char>(color.alpha()));
    plot->SetWidth(width);
    c->tables.push_back(table);
    for (qsizetype i = 0; i < y.size(); ++i) {
        if (c->seriesCount == 0 && i == 0)
            c->yMin = c->yMax = y[i];
        c->yMin = std::min(c->yMin, y[i]);
        c->yMax = std::max(c->yMax, y[i]);
    }
    ++c->seriesCount;
    c->names.append(name);
    updateCursor();
    update();
    return c->seriesCount - 1;
}

void LineChartView::clearSeries()
{
    c->chart->ClearPlots();
    c->tables.clear();
    c->cursorPlot = nullptr;
    c->cursorTable = nullptr;
    c->seriesCount = 0;
    c->names.clear();
    c->yMin = 0.0;
    c->yMax = 1.0;
    update();
}

int LineChartView::seriesCount() const
{
    return c->seriesCount;
}

QStringList LineChartView::seriesNames() const
{
    return c->names;
}

void LineChartView::setCursor(double x)
{
    c->cursorX = x;
    updateCursor();
    update();
}

void LineChartView::updateCursor()
{
    if (c->cursorPlot) {
        c->chart->RemovePlotInstance(c->cursorPlot);
        c->cursorPlot = nullptr;
        c->cursorTable = nullptr;
    }
    if (std::isnan(c->cursorX) || c->seriesCount == 0)
        return;
    // Drawn as a two-point series so it scales with the axes like the data does.
    c->cursorTable = makeTable(QStringLiteral("cursor"), {c->cursorX, c->cursorX}, {c->yMin, c->yMax});
    c->cursorPlot = c->chart->AddPlot(vtkChart::LINE);
    c->cursorPlot->SetInputData(c->cursorTable, 0, 1);
    c->cursorPlot->SetColor(229, 57, 53, 255);
    c->cursorPlot->SetWidth(1.5f);
    c->cursorPlot->SetLegendVisibility(false);
}

} // namespace lipsync::studio
