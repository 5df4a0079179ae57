#pragma once
// The timeline of one sequence: a time ruler, a strip of video thumbnails, the audio waveform
// (drawn per pixel column from the min/max peak pyramid, so any zoom costs the same) and the
// words tier under it, with a cursor at the current frame's time.
// Wheel zooms about the mouse, Shift+wheel scrolls, clicking or dragging moves the cursor.
#include "audio/WaveformPeaks.h"
#include "project/Tier.h"

#include <QImage>
#include <QVector>
#include <QWidget>

#include <memory>

namespace lipsync::studio {

class WaveformView : public QWidget
{
    Q_OBJECT
public:
    explicit WaveformView(QWidget *parent = nullptr);

    void setPeaks(std::shared_ptr<const WaveformPeaks> peaks);
    void setWords(const Tier &words);
    // Small frames at `frameRate`, one per video frame.
    void setThumbnails(const QVector<QImage> &thumbnails, double frameRate);
    void setDuration(double seconds);
    void setPlaceholderText(const QString &text);
    void clear();

    double duration() const { return m_duration; }
    double cursorTime() const { return m_cursor; }
    void setCursorTime(double seconds);

    // The visible window: its start and the seconds one pixel covers.
    double viewStart() const { return m_start; }
    double secondsPerPixel() const { return m_secondsPerPixel; }
    double visibleDuration() const { return m_secondsPerPixel * width(); }
    void setViewStart(double seconds);
    void zoomBy(double factor, double anchorX);
    void zoomToFit();

    static QColor waveformColor();

signals:
    void timeClicked(double seconds);
    void viewChanged();

protected:
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;

private:
    double timeAt(double x) const { return m_start + x * m_secondsPerPixel; }
    double xAt(double t) const { return (t - m_start) / m_secondsPerPixel; }
    double fitSecondsPerPixel() const;
    void clampView();
    void drawRuler(QPainter &p, const QRect &r) const;
    void drawThumbnails(QPainter &p, const QRect &r) const;
    void drawWaveform(QPainter &p, const QRect &r) const;
    void drawWords(QPainter &p, const QRect &r) const;

    std::shared_ptr<const WaveformPeaks> m_peaks;
    Tier m_words;
    QVector<QImage> m_thumbnails;
    double m_frameRate = 25.0;
    double m_duration = 0.0;
    double m_cursor = 0.0;
    double m_start = 0.0;
    double m_secondsPerPixel = 0.01;
    bool m_fitted = true; // follows the width until the user zooms
    QString m_placeholder;
};

} // namespace lipsync::studio
