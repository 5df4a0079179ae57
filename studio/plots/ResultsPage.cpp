#include "plots/ResultsPage.h"

#include "plots/EvaluationChart.h"
#include "widgets/ElidedLabel.h"

#include "eval/Evaluation.h"
#include "eval/RealismReport.h"

#include <QHeaderView>
#include <QSplitter>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace lipsync::studio {

ResultsPage::ResultsPage(const QString &emptyText, QWidget *parent)
    : QWidget(parent), m_emptyText(emptyText), m_state(new ElidedLabel(this)),
      m_splitter(new QSplitter(Qt::Vertical, this)), m_chart(new EvaluationChart(m_splitter)),
      m_table(new QTableWidget(m_splitter))
{
    m_state->setObjectName(QStringLiteral("resultsState"));
    m_table->setObjectName(QStringLiteral("resultsTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    m_table->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    // Least heights no larger than the trajectory page's: the Plots dock must not take the
    // timeline's room (the charts and table share what the dock is given).
    m_table->setMinimumHeight(2 * fontMetrics().height());
    m_chart->setMinimumHeight(100);
    m_splitter->addWidget(m_chart);
    m_splitter->addWidget(m_table);
    m_splitter->setStretchFactor(0, 3);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setChildrenCollapsible(false);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(2, 2, 2, 2);
    layout->setSpacing(2);
    layout->addWidget(m_state);
    layout->addWidget(m_splitter, 1);
    clear();
}

QString ResultsPage::stateText() const
{
    return m_state->text();
}

void ResultsPage::clear()
{
    m_chart->clear();
    m_realism.clear();
    m_shownState.clear();
    m_computing = false;
    fillTable();
    m_state->setText(m_emptyText);
}

void ResultsPage::setComputing(const QString &what)
{
    m_computing = true;
    m_state->setText(m_shownState.isEmpty() ? tr("Computing: %1…").arg(what)
                                            : tr("Computing: %1… (shown until then: %2)").arg(what, m_shownState));
}

void ResultsPage::setStopped(const QString &why)
{
    m_computing = false;
    m_state->setText(m_shownState.isEmpty() ? why : tr("%1 Shown: %2").arg(why, m_shownState));
}

void ResultsPage::setResult(const EvaluationResult &result, const QString &state)
{
    m_chart->setResult(result);
    m_realism.clear();
    showDrawn(state);
}

void ResultsPage::setRealism(const RealismResult &result, const QString &state)
{
    m_chart->setRealism(result);
    m_realism = EvaluationChart::realismColumns(result, true);
    showDrawn(state);
}

void ResultsPage::showDrawn(const QString &state)
{
    m_shownState = state;
    m_computing = false;
    m_state->setText(state);
    fillTable();
}

void ResultsPage::fillTable()
{
    if (!m_realism.empty()) {
        fillMeasuresTable();
        return;
    }
    // Rows: the charts' methods; columns: their metrics; "mean ± 95 % interval" as drawn.
    const auto &bars = m_chart->bars();
    const auto &metrics = m_chart->metrics();
    m_table->clear();
    m_table->setRowCount(int(bars.size()));
    m_table->setColumnCount(int(metrics.size()));
    QStringList columns;
    for (const std::string &m : metrics)
        columns << EvaluationChart::metricTitle(m);
    m_table->setHorizontalHeaderLabels(columns);
    for (int r = 0; r < int(bars.size()); ++r) {
        auto *name = new QTableWidgetItem(bars[size_t(r)].name);
        name->setForeground(bars[size_t(r)].colour.darker(120));
        m_table->setVerticalHeaderItem(r, name);
        for (int c = 0; c < int(metrics.size()); ++c) {
            const auto found = bars[size_t(r)].metrics.find(metrics[size_t(c)]);
            m_table->setItem(r, c, cell(bars[size_t(r)].name, columns[c],
                                        found == bars[size_t(r)].metrics.end() ? nullptr : &found->second));
        }
    }
}

void ResultsPage::fillMeasuresTable()
{
    // The measures some method has a figure for (the seam's only where something was drawn, the
    // exports' shape only for models), in the report's order.
    std::vector<std::string> measures;
    for (const std::string &measure : realismMetrics())
        for (const EvaluationChart::Bars &method : m_realism) {
            const auto found = method.metrics.find(measure);
            if (found != method.metrics.end() && std::isfinite(found->second.mean)) {
                measures.push_back(measure);
                break;
            }
        }
    m_table->clear();
    m_table->setRowCount(int(measures.size()));
    m_table->setColumnCount(int(m_realism.size()));
    for (int c = 0; c < int(m_realism.size()); ++c) {
        auto *name = new QTableWidgetItem(m_realism[size_t(c)].name);
        name->setForeground(m_realism[size_t(c)].colour.darker(120));
        m_table->setHorizontalHeaderItem(c, name);
    }
    for (int r = 0; r < int(measures.size()); ++r) {
        const QString title = EvaluationChart::metricTitle(measures[size_t(r)]);
        auto *header = new QTableWidgetItem(EvaluationChart::metricLabel(measures[size_t(r)]));
        header->setToolTip(QStringLiteral("<b>%1</b><br>%2").arg(title.toHtmlEscaped(),
                                                            EvaluationChart::metricDescription(measures[size_t(r)]).toHtmlEscaped()));
        m_table->setVerticalHeaderItem(r, header);
        for (int c = 0; c < int(m_realism.size()); ++c) {
            const auto &metrics = m_realism[size_t(c)].metrics;
            const auto found = metrics.find(measures[size_t(r)]);
            m_table->setItem(r, c, cell(m_realism[size_t(c)].name, title, found == metrics.end() ? nullptr : &found->second));
        }
    }
}

// "mean ± 95 % interval" (or "–" without a figure), its folds in the tooltip.
QTableWidgetItem *ResultsPage::cell(const QString &method, const QString &measure, const MetricSummary *summary) const
{
    QString text = QStringLiteral("–");
    QString tip;
    if (summary && std::isfinite(summary->mean)) {
        const MetricSummary &s = *summary;
        text = std::isfinite(s.ci95) ? QStringLiteral("%1 ± %2").arg(s.mean, 0, 'g', 4).arg(s.ci95, 0, 'g', 2)
                                     : QString::number(s.mean, 'g', 4);
        tip = tr("%1, %2: mean %3 over %4 folds, 95 % interval ± %5")
                  .arg(method, measure)
                  .arg(s.mean, 0, 'g', 6)
                  .arg(s.folds.size())
                  .arg(s.ci95, 0, 'g', 3);
    }
    auto *item = new QTableWidgetItem(text);
    item->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
    item->setToolTip(tip);
    return item;
}

} // namespace lipsync::studio
