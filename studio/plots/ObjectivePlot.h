#pragma once
// The live training plot: the objective per iteration (Task::iterationReported) of each model
// being trained, one series per model, redrawn as iterations arrive.
#include "plots/LineChartView.h"

#include <QMap>

namespace lipsync::studio {

class ObjectivePlot : public LineChartView
{
    Q_OBJECT
public:
    explicit ObjectivePlot(QWidget *parent = nullptr);

    // Starts (or restarts) the series `key`, drawn in `color` and named `name` in the title.
    void startRun(const QString &key, const QString &name, const QColor &color);
    void addIteration(const QString &key, int iteration, double objective);
    void clearRuns();
    // Iterations received for `key` (tests, status).
    int iterationCount(const QString &key) const;
    int totalIterations() const;

private:
    void redraw();
    struct Run
    {
        QString name;
        QColor color;
        QVector<double> iterations;
        QVector<double> objectives;
    };
    QMap<QString, Run> m_runs;
    QStringList m_order;
};

} // namespace lipsync::studio
