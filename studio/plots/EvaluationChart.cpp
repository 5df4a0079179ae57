#include "plots/EvaluationChart.h"

#include "context/ModelKinds.h"

#include "eval/Evaluation.h"
#include "eval/RealismReport.h"

#include <vtkAxis.h>
#include <vtkChartMatrix.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotBar.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkVector.h>

#include <QColor>
#include <QCoreApplication>
#include <QString>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lipsync::studio {

// Each measure's texts (title, short label, description; null where it has none), marked for
// translation in this class's context.
const EvaluationChart::MetricText *EvaluationChart::metricText(const std::string &metric)
{
    static const char *const correlation = QT_TR_NOOP(
        "Pearson correlation of the rendered lip opening, read by dlib on the rendered frames, with the recording's; "
        "in speech: from the first to the last spoken phone, leaving out the silences every clip shares.");
    static const char *const control = QT_TR_NOOP(
        "The same correlation of each recording with another clip's render: a control that cannot be good. A "
        "method is only as good as its lead over this.");
    static const char *const observer = QT_TR_NOOP(
        "Held-out accuracy of a classifier on the mouth crop telling the render from the recording, both encoded by "
        "the same encoder. 0.5: it cannot tell them apart; the re-encoded recording shows the floor.");
    static const char *const observed = QT_TR_NOOP(
        "The share of frames the machine observer calls rendered: among the recording's (its false alarms), and "
        "among the render's where the recording's face was only moved, where it was only moved and its open mouth "
        "squeezed narrower, where a mouth's inside was drawn, and where closed lips were drawn. Well above the "
        "recording's share: that step gives frames away.");
    static const char *const falseClosures = QT_TR_NOOP(
        "Lip closures outside /p b m/, per second of speech (the recording's own count beside it).");
    static const char *const seam = QT_TR_NOOP(
        "CIE Lab ΔE across the edge of what the renderer drew: on the render, on the recording at the same pixels, "
        "and across a real edge there (for a drawn mouth inside: the recording's own inner-lip edge at that "
        "opening). A seam shows where the render's step exceeds a real one.");
    static const MetricText texts[] = {
        {"l1", QT_TR_NOOP("L1 error"), nullptr, nullptr},
        {"rms", QT_TR_NOOP("RMS error"), nullptr, nullptr},
        {"linf", QT_TR_NOOP("L-inf error"), nullptr, nullptr},
        {"loglik", QT_TR_NOOP("log-likelihood per frame"), nullptr, nullptr},
        {"correlation", QT_TR_NOOP("lip-opening correlation"), QT_TR_NOOP("r"), correlation},
        {"controlCorrelation", QT_TR_NOOP("lip-opening correlation, control"), QT_TR_NOOP("r, control"), control},
        {"speechCorrelation", QT_TR_NOOP("lip-opening correlation in speech"), QT_TR_NOOP("speech r"), correlation},
        {"controlSpeechCorrelation", QT_TR_NOOP("lip-opening correlation in speech, control"),
         QT_TR_NOOP("speech r, control"), control},
        {"shiftedSpeechCorrelation", QT_TR_NOOP("lip-opening correlation in speech, other footage"),
         QT_TR_NOOP("speech r, other footage"),
         QT_TR_NOOP("Correlation in speech with each frame drawn into the clip's footage half its length away, whose "
                    "mouth does not follow the recording: new speech put into other footage.")},
        {"observerFrames", QT_TR_NOOP("machine observer (0.5: fooled)"), QT_TR_NOOP("observer"), observer},
        {"observerVideos", QT_TR_NOOP("machine observer per video"), QT_TR_NOOP("observer, videos"), observer},
        {"observerRecorded", QT_TR_NOOP("called rendered: recorded frames"), QT_TR_NOOP("called rendered: recording"),
         observed},
        {"observerWarped", QT_TR_NOOP("called rendered: face moved only"), QT_TR_NOOP("… face moved"), observed},
        {"observerNarrowed", QT_TR_NOOP("called rendered: open mouth squeezed narrower"),
         QT_TR_NOOP("… mouth squeezed"), observed},
        {"observerInsides", QT_TR_NOOP("called rendered: inside drawn"), QT_TR_NOOP("… inside drawn"), observed},
        {"observerClosures", QT_TR_NOOP("called rendered: closed lips drawn"), QT_TR_NOOP("… closed lips drawn"),
         observed},
        {"articulation", QT_TR_NOOP("articulation (s.d. ratio)"), QT_TR_NOOP("articulation"),
         QT_TR_NOOP("Standard deviation of the rendered lip opening over the recording's: 1 articulates as much as "
                    "the speaker.")},
        {"closure", QT_TR_NOOP("/p b m/ closures (ratio)"), QT_TR_NOOP("closures"),
         QT_TR_NOOP("/p b m/ segments the render closes over those the recording closes: 1 closes as often as the "
                    "speaker does.")},
        {"closureRecall", QT_TR_NOOP("/p b m/ closure recall"), QT_TR_NOOP("closure recall"),
         QT_TR_NOOP("Of the /p b m/ segments the recording closes, the share the render closes too.")},
        {"falseClosures", QT_TR_NOOP("false closures per s of speech"), QT_TR_NOOP("false closures /s"), falseClosures},
        {"falseClosuresRecorded", QT_TR_NOOP("false closures per s, recording"), QT_TR_NOOP("… recording"),
         falseClosures},
        {"lag", QT_TR_NOOP("lag (frames)"), QT_TR_NOOP("lag (frames)"),
         QT_TR_NOOP("Frames by which the opening lags the sound's energy, render minus recording (negative: the "
                    "render leads).")},
        {"sharpness", QT_TR_NOOP("mouth sharpness (ratio)"), QT_TR_NOOP("sharpness"),
         QT_TR_NOOP("Mean squared Laplacian of the mouth box over the recording's: above 1 is crisper than the "
                    "video.")},
        {"seamDeltaE", QT_TR_NOOP("seam: colour step at the drawn edge (ΔE)"), QT_TR_NOOP("seam ΔE"), seam},
        {"seamDeltaERecorded", QT_TR_NOOP("seam: the recording's same pixels (ΔE)"), QT_TR_NOOP("… same pixels"), seam},
        {"seamDeltaENatural", QT_TR_NOOP("seam: a real edge there (ΔE)"), QT_TR_NOOP("… a real edge"), seam},
        {"shapeCorrelation", QT_TR_NOOP("mouth drawn as generated (correlation)"), QT_TR_NOOP("drawn as generated r"),
         QT_TR_NOOP("The method's own inner-lip gap, as the animation exports carry it, against the opening read on "
                    "its render.")},
    };
    for (const MetricText &t : texts)
        if (metric == t.id)
            return &t;
    return nullptr;
}

QString EvaluationChart::metricTitle(const std::string &metric)
{
    const MetricText *t = metricText(metric);
    return t ? tr(t->title) : QString::fromStdString(metric);
}

QString EvaluationChart::metricLabel(const std::string &metric)
{
    const MetricText *t = metricText(metric);
    return t && t->label ? tr(t->label) : metricTitle(metric);
}

QString EvaluationChart::metricDescription(const std::string &metric)
{
    const MetricText *t = metricText(metric);
    return t && t->description ? tr(t->description) : QString();
}

struct EvaluationChart::Impl
{
    vtkNew<vtkContextView> view;
    vtkNew<vtkChartMatrix> matrix;
    std::vector<vtkSmartPointer<vtkTable>> tables;
    int models = 0;
    int metrics = 0;
    QStringList names;
    std::vector<Bars> bars;
    std::vector<std::string> metricIds;
};

EvaluationChart::EvaluationChart(QWidget *parent) : VtkWidget(parent), e(std::make_unique<Impl>())
{
    e->view->SetRenderWindow(renderWindow());
    e->view->SetInteractor(interactor());
    e->view->GetRenderer()->SetBackground(1.0, 1.0, 1.0);
    e->view->GetScene()->AddItem(e->matrix);
    setMinimumSize(240, 140);
}

EvaluationChart::~EvaluationChart() = default;

int EvaluationChart::modelCount() const
{
    return e->models;
}

QStringList EvaluationChart::modelNames() const
{
    return e->names;
}

int EvaluationChart::metricCount() const
{
    return e->metrics;
}

const std::vector<EvaluationChart::Bars> &EvaluationChart::bars() const
{
    return e->bars;
}

const std::vector<std::string> &EvaluationChart::metrics() const
{
    return e->metricIds;
}

QString EvaluationChart::hoverText(int metric, int bar) const
{
    if (metric < 0 || metric >= e->metrics)
        return {};
    const int rows = (e->metrics + 1) / 2;
    auto *chart = vtkChartXY::SafeDownCast(e->matrix->GetChart(vtkVector2i(metric % 2, rows - 1 - metric / 2)));
    vtkPlot *plot = chart && chart->GetNumberOfPlots() > 0 ? chart->GetPlot(0) : nullptr;
    if (!plot || !plot->GetInput() || bar < 0 || bar >= plot->GetInput()->GetNumberOfRows())
        return {};
    const double y = plot->GetInput()->GetValue(bar, 1).ToDouble();
    return QString::fromStdString(plot->GetTooltipLabel(vtkVector2d(bar, y), bar, 0));
}

void EvaluationChart::clear()
{
    e->matrix->SetSize(vtkVector2i(0, 0));
    e->tables.clear();
    e->models = e->metrics = 0;
    e->names.clear();
    e->bars.clear();
    e->metricIds.clear();
    update();
}

void EvaluationChart::setResult(const EvaluationResult &result)
{
    std::vector<Bars> bars;
    for (const ModelEvaluation &model : result.models)
        bars.push_back({ModelKinds::name(model.kind), ModelKinds::colour(model.kind), model.metrics});
    draw(bars, evaluationMetrics());
}

std::vector<EvaluationChart::Bars> EvaluationChart::realismColumns(const RealismResult &result, bool withReencoded)
{
    std::vector<Bars> columns;
    for (const RealismMethod &method : result.methods) {
        if (method.kind == RealismMethod::kReencoded) {
            if (withReencoded)
                columns.push_back({tr("recording, re-encoded"), QColor(0x30, 0x30, 0x30), method.metrics});
        } else if (method.kind == "tracked") {
            columns.push_back({tr("tracked"), QColor(0x75, 0x75, 0x75), method.metrics});
        } else {
            columns.push_back({ModelKinds::name(method.kind), ModelKinds::colour(method.kind), method.metrics});
        }
    }
    return columns;
}

void EvaluationChart::setRealism(const RealismResult &result)
{
    // The four a viewer sees first (ResultsPage's table lists every measure): four charts stay
    // legible in a docked panel, as Figure 4's do. The re-encoded recording has no lips to chart.
    draw(realismColumns(result, false), {"speechCorrelation", "articulation", "closure", "observerFrames"});
}

void EvaluationChart::draw(const std::vector<Bars> &bars, const std::vector<std::string> &metrics)
{
    clear();
    const int n = int(bars.size());
    if (n == 0)
        return;
    for (const Bars &b : bars)
        e->names.append(b.name);
    e->matrix->SetSize(vtkVector2i(2, (int(metrics.size()) + 1) / 2));
    e->matrix->SetGutter(vtkVector2f(50.0f, 34.0f));
    for (size_t m = 0; m < metrics.size(); ++m) {
        const int rows = (int(metrics.size()) + 1) / 2;
        auto *chart = vtkChartXY::SafeDownCast(e->matrix->GetChart(vtkVector2i(int(m) % 2, rows - 1 - int(m) / 2)));
        if (!chart)
            continue;
        chart->SetTitle(metricTitle(metrics[m]).toUtf8().constData());
        chart->GetTitleProperties()->SetFontSize(12);
        chart->SetShowLegend(false);
        vtkNew<vtkDoubleArray> ticks;
        vtkNew<vtkStringArray> labels;
        double lo = 0.0, hi = 0.0;
        // One bar plot per chart (vtkChartXY puts several bar plots side by side), coloured per
        // model through a lookup table on the model index.
        auto table = vtkSmartPointer<vtkTable>::New();
        vtkNew<vtkDoubleArray> bx;
        bx->SetName("model");
        vtkNew<vtkDoubleArray> by;
        by->SetName("mean");
        vtkNew<vtkDoubleArray> bc;
        bc->SetName("colour");
        table->AddColumn(bx);
        table->AddColumn(by);
        table->AddColumn(bc);
        vtkNew<vtkLookupTable> colours;
        colours->SetNumberOfTableValues(n);
        colours->SetRange(0.0, std::max(1.0, double(n - 1)));
        for (int i = 0; i < n; ++i) {
            const Bars &model = bars[size_t(i)];
            colours->SetTableValue(i, model.colour.redF(), model.colour.greenF(), model.colour.blueF(), 1.0);
            const auto found = model.metrics.find(metrics[m]);
            if (found == model.metrics.end() || !std::isfinite(found->second.mean))
                continue;
            const double mean = found->second.mean, ci = found->second.ci95;
            lo = std::min({lo, mean - ci, mean});
            hi = std::max({hi, mean + ci, mean});
            ticks->InsertNextValue(i);
            labels->InsertNextValue(e->names[i].toStdString());
            bx->InsertNextValue(i);
            by->InsertNextValue(mean);
            bc->InsertNextValue(i);
        }
        colours->Build();
        auto *plot = vtkPlotBar::SafeDownCast(chart->AddPlot(vtkChart::BAR));
        plot->SetInputData(table, 0, 1);
        // Hovering a bar says whose it is and its value (the names are not written under the bars).
        plot->SetIndexedLabels(labels);
        plot->SetTooltipLabelFormat("%i: %y");
        plot->SetLookupTable(colours);
        plot->SelectColorArray("colour");
        plot->ScalarVisibilityOn();
        plot->SetWidth(0.6f);
        e->tables.push_back(table);
        for (int i = 0; i < n; ++i) {
            const Bars &model = bars[size_t(i)];
            const auto found = model.metrics.find(metrics[m]);
            if (found == model.metrics.end() || !std::isfinite(found->second.mean))
                continue;
            const double mean = found->second.mean;
            const double ci = std::isfinite(found->second.ci95) ? found->second.ci95 : 0.0;
            // Error bar: cap, stem, cap as one polyline.
            const double w = 0.15;
            const double xs[] = {i - w, i + w, double(i), double(i), i - w, i + w};
            const double ys[] = {mean + ci, mean + ci, mean + ci, mean - ci, mean - ci, mean - ci};
            auto whisker = vtkSmartPointer<vtkTable>::New();
            vtkNew<vtkDoubleArray> wx;
            wx->SetName("x");
            vtkNew<vtkDoubleArray> wy;
            wy->SetName("ci95");
            whisker->AddColumn(wx);
            whisker->AddColumn(wy);
            whisker->SetNumberOfRows(6);
            for (int k = 0; k < 6; ++k) {
                whisker->SetValue(k, 0, xs[k]);
                whisker->SetValue(k, 1, ys[k]);
            }
            vtkPlot *line = chart->AddPlot(vtkChart::LINE);
            line->SetInputData(whisker, 0, 1);
            line->SetColor(20, 20, 20, 255);
            line->SetWidth(1.5f);
            e->tables.push_back(whisker);
        }
        vtkAxis *x = chart->GetAxis(vtkAxis::BOTTOM);
        x->SetCustomTickPositions(ticks, labels);
        x->SetBehavior(vtkAxis::FIXED);
        x->SetRange(-0.6, n - 0.4);
        x->SetTitle("");
        vtkAxis *y = chart->GetAxis(vtkAxis::LEFT);
        y->SetTitle("");
        // Small enough that the value axis gets more than its zero tick.
        x->GetLabelProperties()->SetFontSize(9);
        // No names under the bars: in a docked chart they run into each other ("SLDSHMM-mean").
        // The bars' colours name them, as the table below the charts does (ResultsPage), and
        // the bars keep the height the names would take.
        x->SetLabelsVisible(false);
        y->GetLabelProperties()->SetFontSize(9);
        // Three value ticks (bottom, middle, top) whatever the height: VTK's automatic spacing
        // leaves only the zero tick in a docked chart, so the bars would have no scale.
        y->SetNumberOfTicks(3);
        y->SetNotation(vtkAxis::PRINTF_NOTATION);
        y->SetLabelFormat("%.3g");
        const double pad = 0.08 * std::max(hi - lo, 1e-9);
        y->SetBehavior(vtkAxis::FIXED);
        y->SetRange(lo < 0 ? lo - pad : 0.0, hi > 0 ? hi + pad : 0.0);
    }
    e->models = n;
    e->metrics = int(metrics.size());
    e->bars = bars;
    e->metricIds = metrics;
    update();
}

} // namespace lipsync::studio
