#pragma once
// The trajectory plot: one AAM parameter over time — the real features of a sequence and each
// trained model's generation for the sequence's frame labels — over alternating shaded bands of the
// phoneme segments (labelled along the top axis), with a cursor at the current frame. Zoom (wheel)
// and pan (drag) are vtkChartXY's own interaction.
#include "annotation/FrameClock.h"
#include "plots/VtkWidget.h"

#include <QColor>
#include <QString>
#include <QStringList>
#include <QVector>

#include <memory>

namespace lipsync {
struct Tier;
}

namespace lipsync::studio {

class TrajectoryView : public VtkWidget
{
    Q_OBJECT
public:
    struct Series
    {
        QString name;
        QVector<double> values; // one per frame
        QColor color;
    };

    explicit TrajectoryView(QWidget *parent = nullptr);
    ~TrajectoryView() override;

    // Replaces everything: frame rate, phone segments and the series (first = the real features).
    // Values of frame i are drawn at the centre of the time `frames` shows it.
    void setData(const QString &title, const FrameClock &frames, const Tier &phones, const QVector<Series> &series);
    void clear();
    int seriesCount() const;
    // The series' names as the legend shows them, in order.
    QStringList seriesNames() const;
    int phoneBandCount() const;
    // The phonemes' names written over the plot (those that fit without touching a neighbour).
    int phoneLabelsShown() const;
    // The cursor at frame `frame` (its centre); hidden for a negative frame.
    void setCurrentFrame(int frame);
    // Time (s) of the cursor line, NaN when hidden.
    double cursorTime() const;
    // The visible time range of the bottom axis.
    void visibleRange(double &from, double &to) const;

private:
    void rebuild();
    struct Impl;
    std::unique_ptr<Impl> t;
};

} // namespace lipsync::studio
