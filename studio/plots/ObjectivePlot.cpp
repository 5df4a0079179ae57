#include "plots/ObjectivePlot.h"

namespace lipsync::studio {

ObjectivePlot::ObjectivePlot(QWidget *parent) : LineChartView(parent)
{
    setTitle(tr("Training objective"));
    setAxisTitles(tr("iteration"), tr("objective"));
    // Each model's name and latest objective in the legend: in the title they were cut off at
    // both ends once three or four models trained in the narrow dock.
    setLegendVisible(true);
}

void ObjectivePlot::startRun(const QString &key, const QString &name, const QColor &color)
{
    if (!m_order.contains(key))
        m_order.append(key);
    m_runs[key] = Run{name, color, {}, {}};
    redraw();
}

void ObjectivePlot::addIteration(const QString &key, int iteration, double objective)
{
    auto it = m_runs.find(key);
    if (it == m_runs.end())
        return;
    it->iterations.append(iteration);
    it->objectives.append(objective);
    redraw();
}

void ObjectivePlot::clearRuns()
{
    m_runs.clear();
    m_order.clear();
    redraw();
}

int ObjectivePlot::iterationCount(const QString &key) const
{
    return int(m_runs.value(key).iterations.size());
}

int ObjectivePlot::totalIterations() const
{
    int n = 0;
    for (const Run &r : m_runs)
        n += int(r.iterations.size());
    return n;
}

void ObjectivePlot::redraw()
{
    clearSeries();
    // Models trained in closed form (Brand, HMM-mean) report no iterations and draw no line.
    for (const QString &key : m_order) {
        const Run &r = m_runs[key];
        if (!r.iterations.isEmpty())
            addSeries(tr("%1: %2").arg(r.name).arg(r.objectives.back(), 0, 'g', 6), r.iterations, r.objectives, r.color);
    }
}

} // namespace lipsync::studio
