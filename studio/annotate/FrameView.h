#pragma once
// A video frame, large, with the 23 landmarks drawn over it. Wheel zooms about the cursor,
// dragging pans, double-click fits the frame to the view again. The landmark editing tools of
// the faces feature will hook in here.
#include "project/LandmarkSet.h"

#include <QImage>
#include <QWidget>

#include <optional>

namespace lipsync::studio {

class FrameView : public QWidget
{
    Q_OBJECT
public:
    explicit FrameView(QWidget *parent = nullptr);

    void setImage(const QImage &image);
    const QImage &image() const { return m_image; }
    void setLandmarks(const std::optional<LandmarkSet> &landmarks);
    // Shown when there is no image ("Loading…", an error).
    void setPlaceholderText(const QString &text);

    // 1 = the frame fits the view; zoom multiplies that.
    double zoom() const { return m_zoom; }
    void setZoom(double zoom, const QPointF &anchor);
    void fitToView();

    // Colour used for a landmark in the given state.
    static QColor stateColor(PointState state);

signals:
    void zoomChanged(double zoom);

protected:
    void paintEvent(QPaintEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;

private:
    // Image-to-widget mapping: widget = offset + image * scale.
    double scale() const;
    QPointF offset() const;

    QImage m_image;
    std::optional<LandmarkSet> m_landmarks;
    QString m_placeholder;
    double m_zoom = 1.0;
    QPointF m_pan; // widget pixels, added to the centred position
    QPointF m_dragStart;
    QPointF m_panAtDragStart;
    bool m_dragging = false;
};

} // namespace lipsync::studio
