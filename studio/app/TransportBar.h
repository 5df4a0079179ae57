#pragma once
// Frame navigation under the frame view: step/play buttons (the window's actions), a slider,
// a frame spin box and the current time.
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

    void setFrameCount(int count, double frameRate);
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
    double m_frameRate = 25.0;
    int m_count = 0;
};

} // namespace lipsync::studio
