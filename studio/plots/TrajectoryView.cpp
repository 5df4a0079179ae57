#include "plots/TrajectoryView.h"

#include "plots/ChartLegend.h"

#include "annotation/Tier.h"
#include "util/PhoneSet.h"

#include <vtkAxis.h>
#include <vtkBrush.h>
#include <vtkCallbackCommand.h>
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
#include <vtkPlotArea.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkVariant.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lipsync::studio {

namespace {

vtkSmartPointer<vtkTable> makeTable(const std::vector<const char *> &names, vtkIdType rows)
{
    auto table = vtkSmartPointer<vtkTable>::New();
    for (const char *name : names) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(name);
        table->AddColumn(column);
    }
    table->SetNumberOfRows(rows);
    return table;
}

} // namespace

struct TrajectoryView::Impl
{
    vtkNew<vtkContextView> view;
    vtkNew<vtkChartXY> chart;
    std::vector<vtkSmartPointer<vtkTable>> tables;
    vtkSmartPointer<vtkTable> cursorTable;
    vtkPlot *cursorPlot = nullptr;
    vtkNew<vtkCallbackCommand> syncAxes;

    QString title;
    FrameClock frames; // when each value's frame is shown: value i is drawn at its centre
    std::vector<Interval> phones;
    QVector<Series> series;
    int currentFrame = -1;
    double yMin = 0.0, yMax = 1.0;
    // The phonemes' names over the plot, at their segments' centres, and which are written: in a
    // narrow chart or a long sequence neighbours would run into each other ("BHNBLUW"), so a name
    // is left out where it would touch the last one written (labelPhones).
    std::vector<double> phoneCentres;
    std::vector<std::string> phoneNames;
    std::vector<bool> phoneShown;

    void labelPhones();
};

void TrajectoryView::Impl::labelPhones()
{
    vtkAxis *top = chart->GetAxis(vtkAxis::TOP);
    const double from = top->GetMinimum(), to = top->GetMaximum();
    double pixels = std::abs(double(top->GetPoint2()[0] - top->GetPoint1()[0]));
    if (!(pixels > 0)) // not laid out yet (the first drawing): most of the window's width
        pixels = 0.6 * view->GetRenderWindow()->GetSize()[0];
    if (!(to > from) || !(pixels > 0))
        return;
    const double perSecond = pixels / (to - from);
    const double charWidth = 0.6 * top->GetLabelProperties()->GetFontSize();
    std::vector<bool> shown(phoneCentres.size(), false);
    double lastRight = -1e300;
    for (size_t i = 0; i < phoneCentres.size(); ++i) {
        const double x = (phoneCentres[i] - from) * perSecond;
        const double half = 0.5 * charWidth * double(phoneNames[i].size()) + 2.0;
        if (x - half >= lastRight) {
            shown[i] = true;
            lastRight = x + half;
        }
    }
    if (shown == phoneShown)
        return;
    phoneShown = shown;
    vtkNew<vtkDoubleArray> positions;
    vtkNew<vtkStringArray> labels;
    for (size_t i = 0; i < phoneCentres.size(); ++i) {
        positions->InsertNextValue(phoneCentres[i]);
        labels->InsertNextValue(shown[i] ? phoneNames[i] : std::string());
    }
    top->SetCustomTickPositions(positions, labels);
}

TrajectoryView::TrajectoryView(QWidget *parent) : VtkWidget(parent), t(std::make_unique<Impl>())
{
    t->view->SetRenderWindow(renderWindow());
    t->view->SetInteractor(interactor());
    t->view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    t->view->GetScene()->AddItem(t->chart);
    showCornerLegend(*t->chart, vtkChartLegend::TOP, LegendPlace::BesidePlot);
    t->chart->GetTitleProperties()->SetFontSize(13);
    for (int axis : {vtkAxis::BOTTOM, vtkAxis::LEFT, vtkAxis::TOP}) {
        t->chart->GetAxis(axis)->GetTitleProperties()->SetFontSize(12);
        t->chart->GetAxis(axis)->GetLabelProperties()->SetFontSize(11);
    }
    // The top axis carries the phone labels at the segment centres; it follows the bottom axis
    // through zoom and pan (synchronised before every render).
    t->chart->SetAutoAxes(false);
    t->chart->GetAxis(vtkAxis::TOP)->SetVisible(true);
    t->chart->GetAxis(vtkAxis::TOP)->SetBehavior(vtkAxis::FIXED);
    t->chart->GetAxis(vtkAxis::TOP)->SetGridVisible(false);
    t->chart->GetAxis(vtkAxis::RIGHT)->SetVisible(false);
    t->syncAxes->SetClientData(t.get());
    t->syncAxes->SetCallback([](vtkObject *, unsigned long, void *clientData, void *) {
        auto *impl = static_cast<Impl *>(clientData);
        vtkAxis *bottom = impl->chart->GetAxis(vtkAxis::BOTTOM);
        vtkAxis *top = impl->chart->GetAxis(vtkAxis::TOP);
        if (top->GetMinimum() != bottom->GetMinimum() || top->GetMaximum() != bottom->GetMaximum())
            top->SetRange(bottom->GetMinimum(), bottom->GetMaximum());
        impl->labelPhones(); // for the range and width about to be drawn
    });
    t->view->GetRenderer()->AddObserver(vtkCommand::StartEvent, t->syncAxes);
    setMinimumSize(200, 140);
}

TrajectoryView::~TrajectoryView() = default;

void TrajectoryView::setData(const QString &title, const FrameClock &frames, const Tier &phones,
                             const QVector<Series> &series)
{
    t->title = title;
    t->frames = frames.rate() > 0 ? frames : FrameClock::uniform(25.0, frames.count());
    t->phones = phones.intervals;
    t->series = series;
    rebuild();
}

void TrajectoryView::clear()
{
    t->title.clear();
    t->phones.clear();
    t->series.clear();
    rebuild();
}

int TrajectoryView::seriesCount() const
{
    return int(t->series.size());
}

QStringList TrajectoryView::seriesNames() const
{
    QStringList names;
    for (const Series &s : t->series)
        names.append(s.name);
    return names;
}

int TrajectoryView::phoneBandCount() const
{
    return int(t->phones.size());
}

int TrajectoryView::phoneLabelsShown() const
{
    return int(std::count(t->phoneShown.begin(), t->phoneShown.end(), true));
}

void TrajectoryView::rebuild()
{
    t->chart->ClearPlots();
    t->tables.clear();
    t->cursorPlot = nullptr;
    t->cursorTable = nullptr;
    t->chart->SetTitle(t->title.toUtf8().constData());
    t->chart->GetAxis(vtkAxis::BOTTOM)->SetTitle(tr("time (s)").toUtf8().constData());
    t->chart->GetAxis(vtkAxis::LEFT)->SetTitle(tr("parameter value").toUtf8().constData());
    t->chart->GetAxis(vtkAxis::TOP)->SetTitle("");

    bool first = true;
    double duration = 0.0;
    for (const Series &s : t->series) {
        for (double v : s.values) {
            if (!std::isfinite(v))
                continue;
            t->yMin = first ? v : std::min(t->yMin, v);
            t->yMax = first ? v : std::max(t->yMax, v);
            first = false;
        }
        duration = std::max(duration, t->frames.endTime(int(s.values.size()) - 1));
    }
    if (first) {
        t->yMin = 0.0;
        t->yMax = 1.0;
    }
    const double margin = 0.05 * std::max(t->yMax - t->yMin, 1e-9);
    const double lo = t->yMin - margin, hi = t->yMax + margin;

    // Phoneme segments: every other one shaded, so neighbours stay distinguishable.
    t->phoneCentres.clear();
    t->phoneNames.clear();
    t->phoneShown.clear();
    {
        vtkNew<vtkDoubleArray> none;
        vtkNew<vtkStringArray> noLabels;
        t->chart->GetAxis(vtkAxis::TOP)->SetCustomTickPositions(none, noLabels);
    }
    if (!t->phones.empty() && !t->series.isEmpty()) {
        auto bands = makeTable({"t", "lo", "hi"}, vtkIdType(2 * t->phones.size()));
        for (size_t i = 0; i < t->phones.size(); ++i) {
            const Interval &p = t->phones[i];
            const double top = i % 2 == 0 ? hi : lo;
            bands->SetValue(vtkIdType(2 * i), 0, p.start);
            bands->SetValue(vtkIdType(2 * i), 1, lo);
            bands->SetValue(vtkIdType(2 * i), 2, top);
            bands->SetValue(vtkIdType(2 * i + 1), 0, p.end);
            bands->SetValue(vtkIdType(2 * i + 1), 1, lo);
            bands->SetValue(vtkIdType(2 * i + 1), 2, top);
            t->phoneCentres.push_back(0.5 * (p.start + p.end));
            t->phoneNames.push_back(p.label.empty() ? std::string(PhoneSet::kSilenceLabel) : p.label);
            duration = std::max(duration, p.end);
        }
        auto *area = vtkPlotArea::SafeDownCast(t->chart->AddPlot(vtkChart::AREA));
        area->SetInputData(bands);
        area->SetInputArray(0, "t");
        area->SetInputArray(1, "lo");
        area->SetInputArray(2, "hi");
        area->GetBrush()->SetColor(225, 232, 240, 255);
        area->GetPen()->SetLineType(vtkPen::NO_PEN);
        area->SetLabel(tr("phonemes").toUtf8().constData());
        t->tables.push_back(bands);
    }
    t->labelPhones();

    for (const Series &s : t->series) {
        auto table = makeTable({"t", "y"}, vtkIdType(s.values.size()));
        for (qsizetype i = 0; i < s.values.size(); ++i) {
            table->SetValue(vtkIdType(i), 0, t->frames.centre(int(i)));
            table->SetValue(vtkIdType(i), 1, s.values[i]);
        }
        vtkPlot *plot = t->chart->AddPlot(vtkChart::LINE);
        plot->SetInputData(table, 0, 1);
        plot->SetColor(static_cast<unsigned char>(s.color.red()), static_cast<unsigned char>(s.color.green()),
                       static_cast<unsigned char>(s.color.blue()), 255);
        plot->SetWidth(2.0f);
        plot->SetLabel(s.name.toUtf8().constData());
        t->tables.push_back(table);
    }

    t->cursorTable = makeTable({"t", "y"}, 2);
    t->cursorTable->SetValue(0, 1, lo);
    t->cursorTable->SetValue(1, 1, hi);
    t->cursorPlot = t->chart->AddPlot(vtkChart::LINE);
    t->cursorPlot->SetInputData(t->cursorTable, 0, 1);
    t->cursorPlot->SetColor(33, 33, 33, 255);
    t->cursorPlot->SetWidth(1.5f);
    t->cursorPlot->SetLegendVisibility(false);
    setCurrentFrame(t->currentFrame);

    t->chart->RecalculateBounds();
    vtkAxis *bottom = t->chart->GetAxis(vtkAxis::BOTTOM);
    bottom->SetBehavior(vtkAxis::FIXED);
    bottom->SetRange(0.0, duration > 0 ? duration : 1.0);
    vtkAxis *left = t->chart->GetAxis(vtkAxis::LEFT);
    left->SetBehavior(vtkAxis::FIXED);
    left->SetRange(lo, hi);
    t->chart->GetAxis(vtkAxis::TOP)->SetRange(bottom->GetMinimum(), bottom->GetMaximum());
    update();
}

void TrajectoryView::setCurrentFrame(int frame)
{
    t->currentFrame = frame;
    if (!t->cursorPlot)
        return;
    const bool visible = frame >= 0 && !t->series.isEmpty();
    const double x = visible ? t->frames.centre(frame) : 0.0;
    t->cursorTable->SetValue(0, 0, x);
    t->cursorTable->SetValue(1, 0, x);
    t->cursorTable->Modified();
    t->cursorPlot->SetVisible(visible);
    update();
}

double TrajectoryView::cursorTime() const
{
    if (!t->cursorPlot || !t->cursorPlot->GetVisible())
        return std::numeric_limits<double>::quiet_NaN();
    return t->cursorTable->GetValue(0, 0).ToDouble();
}

void TrajectoryView::visibleRange(double &from, double &to) const
{
    from = t->chart->GetAxis(vtkAxis::BOTTOM)->GetMinimum();
    to = t->chart->GetAxis(vtkAxis::BOTTOM)->GetMaximum();
}

} // namespace lipsync::studio
