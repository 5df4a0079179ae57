#pragma once
// The Timeline dock: the waveform view with a scroll bar and zoom buttons.
#include <QWidget>

class QScrollBar;

namespace lipsync::studio {

class WaveformView;

class TimelinePanel : public QWidget
{
    Q_OBJECT
public:
    explicit TimelinePanel(QWidget *parent = nullptr);
    WaveformView *waveform() const { return m_waveform; }

private:
    void syncScrollBar();

    WaveformView *m_waveform;
    QScrollBar *m_scroll;
    bool m_syncing = false;
};

} // namespace lipsync::studio
