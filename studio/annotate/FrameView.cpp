#include "annotate/FrameView.h"

#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace lipsync::studio {

namespace {
constexpr double kMinZoom = 0.25;
constexpr double kMaxZoom = 16.0;
const QColor kBackground(0x26, 0x28, 0x2b);
} // namespace

FrameView::FrameView(QWidget *parent) : QWidget(parent)
{
    setMinimumSize(200, 160);
    setFocusPolicy(Qt::ClickFocus);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void FrameView::setImage(const QImage &image)
{
    const bool sizeChanged = image.size() != m_image.size();
    m_image = image;
    if (sizeChanged)
        fitToView();
    update();
}

void FrameView::setLandmarks(const std::optional<LandmarkSet> &landmarks)
{
    m_landmarks = landmarks;
    update();
}

void FrameView::setPlaceholderText(const QString &text)
{
    m_placeholder = text;
    update();
}

QColor FrameView::stateColor(PointState state)
{
    switch (state) {
    case PointState::Placed: return QColor(255, 214, 0);
    case PointState::Automatic: return QColor(0, 229, 255);
    case PointState::Fixed: return QColor(118, 255, 3);
    case PointState::Undefined: break;
    }
    return QColor(158, 158, 158);
}

double FrameView::scale() const
{
    if (m_image.isNull())
        return 1.0;
    const double fit = std::min(double(width()) / m_image.width(), double(height()) / m_image.height());
    return fit * m_zoom;
}

QPointF FrameView::offset() const
{
    const double s = scale();
    return QPointF((width() - m_image.width() * s) / 2.0, (height() - m_image.height() * s) / 2.0) + m_pan;
}

void FrameView::setZoom(double zoom, const QPointF &anchor)
{
    zoom = std::clamp(zoom, kMinZoom, kMaxZoom);
    if (m_image.isNull() || zoom == m_zoom)
        return;
    // Keep the image point under `anchor` where it is.
    const QPointF imagePoint = (anchor - offset()) / scale();
    m_zoom = zoom;
    const QPointF centred = offset() - m_pan;
    m_pan = anchor - imagePoint * scale() - centred;
    update();
    emit zoomChanged(m_zoom);
}

void FrameView::fitToView()
{
    m_zoom = 1.0;
    m_pan = {};
    update();
    emit zoomChanged(m_zoom);
}

void FrameView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.fillRect(rect(), kBackground);
    if (m_image.isNull()) {
        p.setPen(QColor(190, 190, 190));
        p.drawText(rect(), Qt::AlignCenter | Qt::TextWordWrap, m_placeholder);
        return;
    }
    const double s = scale();
    const QPointF o = offset();
    p.setRenderHint(QPainter::SmoothPixmapTransform, m_zoom < 3.0);
    p.drawImage(QRectF(o, QSizeF(m_image.width() * s, m_image.height() * s)), m_image);

    if (!m_landmarks)
        return;
    p.setRenderHint(QPainter::Antialiasing);
    const double r = std::clamp(2.0 + s, 3.0, 7.0);
    for (int i = 0; i < LandmarkSet::kPointCount; ++i) {
        const LandmarkPoint &pt = m_landmarks->points[std::size_t(i)];
        if (!pt.isDefined())
            continue;
        const QPointF w = o + QPointF(pt.x, pt.y) * s;
        p.setPen(QPen(Qt::black, 1.0));
        p.setBrush(stateColor(pt.state));
        p.drawEllipse(w, r, r);
    }
}

void FrameView::wheelEvent(QWheelEvent *event)
{
    const double steps = event->angleDelta().y() / 120.0;
    setZoom(m_zoom * std::pow(1.25, steps), event->position());
    event->accept();
}

void FrameView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton) {
        m_dragging = true;
        m_dragStart = event->position();
        m_panAtDragStart = m_pan;
        setCursor(Qt::ClosedHandCursor);
    }
}

void FrameView::mouseMoveEvent(QMouseEvent *event)
{
    if (!m_dragging)
        return;
    m_pan = m_panAtDragStart + (event->position() - m_dragStart);
    update();
}

void FrameView::mouseReleaseEvent(QMouseEvent *)
{
    m_dragging = false;
    unsetCursor();
}

void FrameView::mouseDoubleClickEvent(QMouseEvent *)
{
    fitToView();
}

} // namespace lipsync::studio
