#pragma once
// The paper's Figure 4 as VTK bar charts: per metric (L1, RMS, L-infinity error, log-likelihood
// per frame) one chart with a bar per model at the mean over the cross-validation folds and an
// error bar of the 95 % confidence interval; the realism report (docs/models.md §6.5) the same way.
#include "eval/Evaluation.h"
#include "plots/VtkWidget.h"

#include <QColor>
#include <QStringList>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace lipsync {
struct RealismResult;
}

namespace lipsync::studio {

class EvaluationChart : public VtkWidget
{
    Q_OBJECT
public:
    explicit EvaluationChart(QWidget *parent = nullptr);
    ~EvaluationChart() override;

    void setResult(const EvaluationResult &result);
    // The realism report the same way: per metric (opening correlation, articulation, closures,
    // sharpness) a bar per method, "tracked" (the AAM's re-synthesis) first.
    void setRealism(const RealismResult &result);
    void clear();
    // Models and metrics drawn (0 when empty).
    int modelCount() const;
    int metricCount() const;
    // The models' names under their bars, in order.
    QStringList modelNames() const;

    // What is drawn: a bar per method (its name and colour) with its metrics' means and 95 %
    // intervals, and the metrics charted, in order (ResultsPage lists the same in a table).
    struct Bars
    {
        QString name;
        QColor colour;
        std::map<std::string, MetricSummary> metrics;
    };
    const std::vector<Bars> &bars() const;
    // What hovering bar `bar` of the chart of metric `metric` shows ("Brand: 36.3").
    QString hoverText(int metric, int bar) const;
    const std::vector<std::string> &metrics() const;
    static QString metricTitle(const std::string &metric);
    // A measure's name in a few words, for a table's row in a docked panel ("speech r").
    static QString metricLabel(const std::string &metric);
    // What a measure means, in a sentence (the tables' tooltips; empty when unknown).
    static QString metricDescription(const std::string &metric);
    // Every method of a realism report as a column: "tracked", the models, and with
    // `withReencoded` the recording re-encoded (the machine observer's floor, no lips of its own).
    static std::vector<Bars> realismColumns(const RealismResult &result, bool withReencoded);

private:
    struct MetricText
    {
        const char *id, *title, *label, *description;
    };
    static const MetricText *metricText(const std::string &metric);
    void draw(const std::vector<Bars> &bars, const std::vector<std::string> &metrics);
    struct Impl;
    std::unique_ptr<Impl> e;
};

} // namespace lipsync::studio
