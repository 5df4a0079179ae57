#pragma once
// A page of the Plots dock for one kind of result, the k-fold evaluation (the paper's Figure 4)
// or the realism report: a line that says what is shown (or that it is being computed, or how
// to get it), the bar charts, and below them a table of mean ± 95 % interval, each cell with its
// folds' count in a tooltip. The evaluation's table holds what is charted (a row per model); the
// realism report's holds every measure (a row per measure, a column per method, the re-encoded
// recording included, each measure explained in its header's tooltip), as `lipsync evaluate
// --realism` prints it.
#include "plots/EvaluationChart.h"

#include <QString>
#include <QWidget>

#include <vector>

class QSplitter;
class QTableWidget;
class QTableWidgetItem;

namespace lipsync {
struct EvaluationResult;
struct RealismResult;
} // namespace lipsync

namespace lipsync::studio {

class ElidedLabel;

class ResultsPage : public QWidget
{
    Q_OBJECT
public:
    // `emptyText`: what the state line says before the first result ("Evaluate (k-fold) …").
    ResultsPage(const QString &emptyText, QWidget *parent = nullptr);

    void setResult(const EvaluationResult &result, const QString &state);
    void setRealism(const RealismResult &result, const QString &state);
    // A computation started: the last result stays, the state line says it is being replaced.
    void setComputing(const QString &what);
    // The last computation ended without a result (failed, canceled): the state line says so.
    void setStopped(const QString &why);
    void clear();

    EvaluationChart *chart() const { return m_chart; }
    QTableWidget *table() const { return m_table; }
    QString stateText() const;
    bool isComputing() const { return m_computing; }

private:
    void showDrawn(const QString &state); // what the chart now draws: its state line and table
    void fillTable();
    void fillMeasuresTable(); // the realism report's: a row per measure
    QTableWidgetItem *cell(const QString &method, const QString &measure, const MetricSummary *summary) const;

    QString m_emptyText;
    QString m_shownState; // what the result on show is
    bool m_computing = false;
    ElidedLabel *m_state;
    QSplitter *m_splitter;
    EvaluationChart *m_chart;
    QTableWidget *m_table;
    std::vector<EvaluationChart::Bars> m_realism; // the realism report's methods, when it is shown
};

} // namespace lipsync::studio
