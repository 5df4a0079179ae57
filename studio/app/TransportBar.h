#pragma once
// Frame navigation under the frame view: step/play buttons (the window's actions), a slider,
// a frame spin box and the current time.
#include "annotation/FrameClock.h"

#include <QWidget>

class QLabel;
class QSlider;
class QSpinBox;

namespace lipsync::studio {

struct StudioActions;

class TransportBar : public QWidget
{
    Q_OBJECT
public:
    TransportBar(const StudioActions &actions, QWidget *parent = nullptr);

    // The frames to step through and when each is shown (its time is displayed).
    void setClock(const FrameClock &clock);
    void setFrame(int frame);
    int frame() const;
    QSlider *slider() const { return m_slider; }
    QSpinBox *spinBox() const { return m_spin; }

signals:
    void frameRequested(int frame);

private:
    void updateTime();

    QSlider *m_slider;
    QSpinBox *m_spin;
    QLabel *m_time;
    FrameClock m_clock;
};

} // namespace lipsync::studio
