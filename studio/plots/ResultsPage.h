#pragma once
// A page of the Plots dock for one kind of result, the k-fold evaluation (the paper's Figure 4)
// or the realism report: a line that says what is shown (or that it is being computed, or how
// to get it), the bar charts, and below them the same values as a table of mean ± 95 % interval,
// each cell with its folds' count in a tooltip.
#include <QString>
#include <QWidget>

class QSplitter;
class QTableWidget;

namespace lipsync {
struct EvaluationResult;
struct RealismResult;
} // namespace lipsync

namespace lipsync::studio {

class ElidedLabel;
class EvaluationChart;

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

    QString m_emptyText;
    QString m_shownState; // what the result on show is
    bool m_computing = false;
    ElidedLabel *m_state;
    QSplitter *m_splitter;
    EvaluationChart *m_chart;
    QTableWidget *m_table;
};

} // namespace lipsync::studio
