#pragma once
// A video frame, large, with the 23 landmarks and their connections drawn over it, and the
// landmark editor on it. Wheel zooms about the cursor, middle-drag, a left-drag with Space held
// (as in image editors) or a left-drag on empty space once every point is placed pans,
// double-click fits the frame to the view again.
// When editable: a click places the next undefined point (scheme order; its name is shown), a
// drag moves a point (reported once, at release: one undo step), Delete undefines the selected
// point. Edits are reported through landmarksEdited; the owner turns them into undoable document
// edits and sets the result back with setLandmarks.
#include "annotation/LandmarkSet.h"

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
    const std::optional<LandmarkSet> &landmarks() const { return m_landmarks; }
    // The previous frame's points, drawn faintly when the onion skin is on.
    // Draws every point in `colour` instead of its state's colour, without the state legend
    // (the preview's panes: tracked or generated, named by the pane's title); nullopt: by state.
    void setPointColour(const std::optional<QColor> &colour);
    std::optional<QColor> pointColour() const { return m_pointColour; }
    void setOnionSkin(const std::optional<LandmarkSet> &landmarks);
    void setOnionSkinVisible(bool visible);
    bool isOnionSkinVisible() const { return m_onionVisible; }
    // Shown when there is no image ("Loading…", an error).
    void setPlaceholderText(const QString &text);
    QString placeholderText() const { return m_placeholder; }
    // A line over the frame's top-left corner (fit error, ...).
    void setInfoText(const QString &text);

    void setEditable(bool editable);
    bool isEditable() const { return m_editable; }
    int selectedPoint() const { return m_selected; }
    void setSelectedPoint(int index);
    // The first undefined point in scheme order, or -1.
    int nextUndefinedPoint() const;

    // 1 = the frame fits the view; zoom multiplies that.
    double zoom() const { return m_zoom; }
    void setZoom(double zoom, const QPointF &anchor);
    void fitToView();

    // Image <-> widget coordinates.
    QPointF imageToWidget(const QPointF &image) const;
    QPointF widgetToImage(const QPointF &widget) const;

    // Colour used for a landmark in the given state.
    static QColor stateColor(PointState state);
    // Human-readable (translated) name of point `index` of the 23-point scheme.
    static QString pointName(int index);

signals:
    void zoomChanged(double zoom);
    // The user changed the points (`what` names the edit for the undo stack).
    void landmarksEdited(const lipsync::LandmarkSet &landmarks, const QString &what);

protected:
    void paintEvent(QPaintEvent *event) override;
    void wheelEvent(QWheelEvent *event) override;
    void mousePressEvent(QMouseEvent *event) override;
    void mouseMoveEvent(QMouseEvent *event) override;
    void mouseReleaseEvent(QMouseEvent *event) override;
    void mouseDoubleClickEvent(QMouseEvent *event) override;
    void keyPressEvent(QKeyEvent *event) override;
    void keyReleaseEvent(QKeyEvent *event) override;
    void focusOutEvent(QFocusEvent *event) override;
    bool event(QEvent *event) override;

private:
    // Image-to-widget mapping: widget = offset + image * scale.
    double scale() const;
    QPointF offset() const;
    double pointRadius() const;
    int pointAt(const QPointF &widget) const;
    QPointF clampToImage(const QPointF &image) const;
    void drawShape(QPainter &p, const LandmarkSet &set, bool onion) const;

    QImage m_image;
    std::optional<LandmarkSet> m_landmarks;
    std::optional<LandmarkSet> m_onion;
    bool m_onionVisible = false;
    std::optional<QColor> m_pointColour;
    QString m_placeholder;
    QString m_info;
    bool m_editable = false;
    int m_selected = -1;
    int m_dragPoint = -1;
    bool m_dragMoved = false;
    double m_zoom = 1.0;
    QPointF m_pan; // widget pixels, added to the centred position
    QPointF m_dragStart;
    QPointF m_panAtDragStart;
    bool m_dragging = false;
    bool m_spaceHeld = false; // Space down: a left-drag pans instead of editing
};

} // namespace lipsync::studio
