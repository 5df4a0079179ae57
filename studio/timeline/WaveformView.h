#pragma once
// The timeline of one sequence: a time ruler, a strip of video thumbnails, the audio waveform
// (drawn per pixel column from the min/max peak pyramid, so any zoom costs the same), the words
// and phones tiers and the per-video-frame phone label strip, with a cursor at the current time.
// Optionally a spectrogram lane (core/audio/Spectrogram, log power, 70 dB range below the
// loudest bin) shares the waveform's height, under it.
// Wheel zooms about the mouse, Shift+wheel scrolls. Clicking sets the cursor; dragging over the
// waveform selects a stretch; dragging in the ruler scrubs.
//
// Editing (when setEditable): in a tier lane a click selects the interval, dragging near a
// boundary moves it (Aegisub's audio timing: the grab offset is kept, the controller snaps and
// clamps), a double-click asks to relabel. Keys while the view has focus: Space plays the
// selection, Tab / Shift+Tab select the next / previous interval, Esc clears the selection.
// The view only reports intentions (signals); TimelinePanel turns them into document edits.
// Intervals the user edited are drawn with an orange marker and orange boundaries.
#include "annotation/FrameClock.h"
#include "annotation/Tier.h"
#include "audio/Spectrogram.h"
#include "audio/WaveformPeaks.h"
#include "document/TierEdits.h"

#include <QImage>
#include <QVector>
#include <QWidget>

#include <memory>
#include <string>
#include <vector>

namespace lipsync::studio {

class WaveformView : public QWidget
{
    Q_OBJECT
public:
    enum class Lane { Ruler, Thumbnails, Waveform, Spectrogram, Words, Phones, FrameLabels };

    explicit WaveformView(QWidget *parent = nullptr);

    void setPeaks(std::shared_ptr<const WaveformPeaks> peaks);
    // The sequence's spectrogram (null: none); drawn while spectrogramVisible.
    void setSpectrogram(std::shared_ptr<const Spectrogram> spectrogram);
    void setSpectrogramVisible(bool visible);
    bool isSpectrogramVisible() const { return m_showSpectrogram; }
    void setWords(const Tier &words);
    void setPhones(const Tier &phones);
    // One phone label per video frame (FrameLabels voting), each drawn where `frames` shows it.
    void setFrameLabels(const std::vector<std::string> &labels, const FrameClock &frames);
    // Small frames, one per video frame, shown at the times of `frames`.
    void setThumbnails(const QVector<QImage> &thumbnails, const FrameClock &frames);
    void setDuration(double seconds);
    void setPlaceholderText(const QString &text);
    void setEditable(bool editable);
    void clear();

    const Tier &words() const { return m_words; }
    const Tier &phones() const { return m_phones; }
    const Tier &tier(TierKind kind) const { return kind == TierKind::Words ? m_words : m_phones; }
    const std::vector<std::string> &frameLabels() const { return m_frameLabels; }

    double duration() const { return m_duration; }
    double cursorTime() const { return m_cursor; }
    void setCursorTime(double seconds);
    // Reports `seconds` as if clicked (the main window moves the current frame there).
    void requestTime(double seconds);

    // Selection: one interval of a tier, or a stretch of time (hasRange), or nothing.
    TierKind activeTier() const { return m_activeTier; }
    int selectedInterval() const { return m_selectedIndex; }
    void selectInterval(TierKind kind, int index);
    bool hasRange() const { return m_rangeEnd - m_rangeStart > 1e-6; }
    double rangeStart() const { return m_rangeStart; }
    double rangeEnd() const { return m_rangeEnd; }
    void setRange(double start, double end);
    void clearSelection();
    // The selected stretch: the range, else the selected interval; false if none.
    bool selection(double *start, double *end) const;

    // The visible window: its start and the seconds one pixel covers.
    double viewStart() const { return m_start; }
    double secondsPerPixel() const { return m_secondsPerPixel; }
    double visibleDuration() const { return m_secondsPerPixel * width(); }
    void setViewStart(double seconds);
    void zoomBy(double factor, double anchorX);
    void zoomToFit();

    QRect laneRect(Lane lane) const;
    double timeAt(double x) const { return m_start + x * m_secondsPerPixel; }
    double xAt(double t) const { return (t - m_start) / m_secondsPerPixel; }

    static QColor waveformColor();
    static QColor editedColor();

signals:
    void timeClicked(double seconds);
    void viewChanged();
    void selectionChanged();
    // A boundary drag: `time` is where the mouse puts the boundary (unsnapped); `drag` numbers
    // the drag so its moves can merge into one undo step.
    void boundaryDragStarted(lipsync::studio::TierKind tier, int boundary, int drag);
    void boundaryDragged(lipsync::studio::TierKind tier, int boundary, double time, int drag);
    void boundaryDragFinished(lipsync::studio::TierKind tier, int boundary, int drag);
    void relabelRequested(lipsync::studio::TierKind tier, int index);
    void playRequested();

protected:
    bool event(QEvent *event) override;
    void paintEvent(QPaintEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    bool focusNextPrevChild(bool next) override;

private:
    double fitSecondsPerPixel() const;
    void clampView();
    bool tierAt(const QPointF &pos, TierKind *kind) const;
    int boundaryAtX(TierKind kind, double x) const;
    void drawRuler(QPainter &p, const QRect &r) const;
    void drawThumbnails(QPainter &p, const QRect &r) const;
    void drawWaveform(QPainter &p, const QRect &r) const;
    void drawSpectrogram(QPainter &p, const QRect &r) const;
    void drawTier(QPainter &p, const QRect &r, TierKind kind) const;
    void drawFrameLabels(QPainter &p, const QRect &r) const;
    void drawLaneName(QPainter &p, const QRect &r, const QString &name) const;

    std::shared_ptr<const WaveformPeaks> m_peaks;
    std::shared_ptr<const Spectrogram> m_spectrogram;
    QImage m_spectrogramImage; // one column per frame, low frequencies at the bottom
    bool m_showSpectrogram = false;
    Tier m_words;
    Tier m_phones;
    std::vector<std::string> m_frameLabels;
    FrameClock m_labelFrames;
    QVector<QImage> m_thumbnails;
    FrameClock m_thumbnailFrames;
    double m_duration = 0.0;
    double m_cursor = 0.0;
    double m_start = 0.0;
    double m_secondsPerPixel = 0.01;
    bool m_fitted = true; // follows the width until the user zooms
    QString m_placeholder;
    bool m_editable = false;

    TierKind m_activeTier = TierKind::Phones;
    int m_selectedIndex = -1;
    double m_rangeStart = 0.0;
    double m_rangeEnd = 0.0;

    enum class Gesture { None, Scrub, Range, Boundary };
    Gesture m_gesture = Gesture::None;
    double m_pressTime = 0.0;
    double m_pressX = 0.0;
    double m_boundaryStart = 0.0;
    TierKind m_dragTier = TierKind::Phones;
    int m_dragBoundary = -1;
    int m_dragCount = 0;
};

} // namespace lipsync::studio
