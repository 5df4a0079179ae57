#pragma once
// The paper's Figure 4 as VTK bar charts: per metric (L1, RMS, L-infinity error, log-likelihood
// per frame) one chart with a bar per model at the mean over the cross-validation folds and an
// error bar of the 95 % confidence interval.
#include "plots/VtkWidget.h"

#include <QStringList>

#include <memory>

namespace lipsync {
struct EvaluationResult;
}

namespace lipsync::studio {

class EvaluationChart : public VtkWidget
{
    Q_OBJECT
public:
    explicit EvaluationChart(QWidget *parent = nullptr);
    ~EvaluationChart() override;

    void setResult(const EvaluationResult &result);
    void clear();
    // Models and metrics drawn (0 when empty).
    int modelCount() const;
    int metricCount() const;
    // The models' names under their bars, in order.
    QStringList modelNames() const;

private:
    struct Impl;
    std::unique_ptr<Impl> e;
};

} // namespace lipsync::studio
