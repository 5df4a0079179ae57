#include "annotate/FrameView.h"

#include "aam/LandmarkScheme.h"

#include <QCoreApplication>
#include <QKeyEvent>
#include <QKeySequence>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
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
    m_dragPoint = -1;
    if (m_selected >= 0 && (!m_landmarks || !m_landmarks->points[std::size_t(m_selected)].isDefined()))
        m_selected = -1;
    update();
}

void FrameView::setPointColour(const std::optional<QColor> &colour)
{
    m_pointColour = colour;
    update();
}

void FrameView::setOnionSkin(const std::optional<LandmarkSet> &landmarks)
{
    m_onion = landmarks;
    update();
}

void FrameView::setOnionSkinVisible(bool visible)
{
    m_onionVisible = visible;
    update();
}

void FrameView::setPlaceholderText(const QString &text)
{
    m_placeholder = text;
    update();
}

void FrameView::setInfoText(const QString &text)
{
    m_info = text;
    update();
}

void FrameView::setEditable(bool editable)
{
    m_editable = editable;
    if (!editable) {
        m_selected = -1;
        m_dragPoint = -1;
    }
    update();
}

void FrameView::setSelectedPoint(int index)
{
    m_selected = index;
    update();
}

int FrameView::nextUndefinedPoint() const
{
    for (int i = 0; i < LandmarkSet::kPointCount; ++i)
        if (!m_landmarks || !m_landmarks->points[std::size_t(i)].isDefined())
            return i;
    return -1;
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

QString FrameView::pointName(int index)
{
    static const char *const names[LandmarkSet::kPointCount] = {
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "left eye, outer corner"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "left eye, upper lid"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "left eye, inner corner"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "left eye, lower lid"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "right eye, inner corner"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "right eye, upper lid"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "right eye, outer corner"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "right eye, lower lid"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "mouth, left corner"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "upper lip, left"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "upper lip, centre"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "upper lip, right"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "mouth, right corner"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "lower lip, right"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "lower lip, centre"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "lower lip, left"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "inner lip, top"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "inner lip, bottom"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "jaw, left"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "jaw, lower left"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "chin"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "jaw, lower right"),
        QT_TRANSLATE_NOOP("lipsync::studio::FrameView", "jaw, right"),
    };
    if (index < 0 || index >= LandmarkSet::kPointCount)
        return {};
    return QCoreApplication::translate("lipsync::studio::FrameView", names[index]);
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

QPointF FrameView::imageToWidget(const QPointF &image) const
{
    return offset() + image * scale();
}

QPointF FrameView::widgetToImage(const QPointF &widget) const
{
    return (widget - offset()) / scale();
}

double FrameView::pointRadius() const
{
    return std::clamp(2.0 + scale(), 3.0, 7.0);
}

int FrameView::pointAt(const QPointF &widget) const
{
    if (!m_landmarks || m_image.isNull())
        return -1;
    const double reach = pointRadius() + 4.0;
    int best = -1;
    double bestDistance = reach * reach;
    for (int i = 0; i < LandmarkSet::kPointCount; ++i) {
        const LandmarkPoint &pt = m_landmarks->points[std::size_t(i)];
        if (!pt.isDefined())
            continue;
        const QPointF d = imageToWidget(QPointF(pt.x, pt.y)) - widget;
        const double d2 = d.x() * d.x() + d.y() * d.y();
        if (d2 <= bestDistance) {
            bestDistance = d2;
            best = i;
        }
    }
    return best;
}

QPointF FrameView::clampToImage(const QPointF &image) const
{
    return QPointF(std::clamp(image.x(), 0.0, double(m_image.width() - 1)),
                   std::clamp(image.y(), 0.0, double(m_image.height() - 1)));
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

void FrameView::drawShape(QPainter &p, const LandmarkSet &set, bool onion) const
{
    const double r = pointRadius();
    QColor line = onion ? QColor(255, 128, 171, 150) : QColor(255, 255, 255, 150);
    p.setPen(QPen(line, onion ? 1.0 : 1.2, onion ? Qt::DashLine : Qt::SolidLine));
    for (const auto &[a, b] : landmarkConnections()) {
        const LandmarkPoint &pa = set.points[std::size_t(a)];
        const LandmarkPoint &pb = set.points[std::size_t(b)];
        if (pa.isDefined() && pb.isDefined())
            p.drawLine(imageToWidget(QPointF(pa.x, pa.y)), imageToWidget(QPointF(pb.x, pb.y)));
    }
    for (int i = 0; i < LandmarkSet::kPointCount; ++i) {
        const LandmarkPoint &pt = set.points[std::size_t(i)];
        if (!pt.isDefined())
            continue;
        const QPointF w = imageToWidget(QPointF(pt.x, pt.y));
        if (onion) {
            p.setPen(QPen(QColor(255, 128, 171, 200), 1.2));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(w, r * 0.8, r * 0.8);
            continue;
        }
        p.setPen(QPen(Qt::black, 1.0));
        p.setBrush(m_pointColour.value_or(stateColor(pt.state)));
        p.drawEllipse(w, r, r);
        if (i == m_selected) {
            p.setPen(QPen(Qt::white, 1.5));
            p.setBrush(Qt::NoBrush);
            p.drawEllipse(w, r + 3.0, r + 3.0);
        }
    }
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

    p.setRenderHint(QPainter::Antialiasing);
    if (m_onionVisible && m_onion)
        drawShape(p, *m_onion, true);
    if (m_landmarks)
        drawShape(p, *m_landmarks, false);

    if (m_landmarks && m_landmarks->definedCount() > 0 && !m_pointColour) {
        // Legend of the point states, bottom left.
        const QFontMetrics fm = p.fontMetrics();
        const std::pair<PointState, QString> states[] = {{PointState::Automatic, tr("automatic")},
                                                         {PointState::Placed, tr("placed")},
                                                         {PointState::Fixed, tr("fixed")}};
        double legendWidth = 0;
        for (const auto &entry : states)
            legendWidth += 8 + fm.horizontalAdvance(entry.second) + 16;
        double x = 12;
        const double y = height() - 12 - fm.height() / 2.0;
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0, 0, 0, 160));
        p.drawRoundedRect(QRectF(x - 8, y - fm.height() / 2.0 - 3, legendWidth, fm.height() + 6), 4, 4);
        for (const auto &[state, label] : states) {
            p.setPen(QPen(Qt::black, 1.0));
            p.setBrush(stateColor(state));
            p.drawEllipse(QPointF(x, y), 4.5, 4.5);
            p.setPen(QColor(235, 235, 235));
            p.drawText(QPointF(x + 8, y + fm.ascent() / 2.0 - 1), label);
            x += 8 + fm.horizontalAdvance(label) + 16;
        }
    }

    QStringList lines;
    if (!m_info.isEmpty())
        lines << m_info;
    if (m_editable) {
        const int next = nextUndefinedPoint();
        if (next >= 0 && (!m_landmarks || m_landmarks->definedCount() == 0))
            lines << tr("Click to place %1 (%2 of %3), or press %4 to detect all points")
                         .arg(pointName(next))
                         .arg(next + 1)
                         .arg(LandmarkSet::kPointCount)
                         .arg(QKeySequence(Qt::CTRL | Qt::Key_D).toString(QKeySequence::NativeText));
        else if (next >= 0)
            lines << tr("Click to place %1 (%2 of %3)").arg(pointName(next)).arg(next + 1).arg(LandmarkSet::kPointCount);
        else if (m_selected >= 0)
            lines << tr("Selected: %1").arg(pointName(m_selected));
    }
    if (!lines.isEmpty()) {
        const QString text = lines.join(QLatin1Char('\n'));
        QRectF box = p.fontMetrics().boundingRect(QRect(0, 0, width() - 20, height()), Qt::TextWordWrap, text);
        box.moveTopLeft(QPointF(8, 8));
        p.setPen(Qt::NoPen);
        p.setBrush(QColor(0, 0, 0, 160));
        p.drawRoundedRect(box.adjusted(-5, -3, 5, 3), 4, 4);
        p.setPen(QColor(240, 240, 240));
        p.drawText(box, Qt::TextWordWrap, text);
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
    if (event->button() == Qt::LeftButton && m_editable && !m_image.isNull() && !m_spaceHeld) {
        const int hit = pointAt(event->position());
        if (hit >= 0) {
            m_selected = hit;
            m_dragPoint = hit;
            m_dragMoved = false;
            m_dragStart = event->position();
            update();
            return;
        }
        const QPointF at = widgetToImage(event->position());
        const int next = nextUndefinedPoint();
        const bool inside = at.x() >= 0 && at.y() >= 0 && at.x() < m_image.width() && at.y() < m_image.height();
        if (next >= 0 && inside) {
            LandmarkSet set = m_landmarks.value_or(LandmarkSet{});
            set.points[std::size_t(next)] = {at.x(), at.y(), PointState::Placed};
            m_landmarks = set;
            m_selected = next;
            update();
            emit landmarksEdited(set, tr("Place %1").arg(pointName(next)));
            return;
        }
        m_selected = -1;
        update();
    }
    if (event->button() == Qt::LeftButton || event->button() == Qt::MiddleButton) {
        m_dragging = true;
        m_dragStart = event->position();
        m_panAtDragStart = m_pan;
        setCursor(Qt::ClosedHandCursor);
    }
}

void FrameView::mouseMoveEvent(QMouseEvent *event)
{
    if (m_dragPoint >= 0 && m_landmarks) {
        if (!m_dragMoved && (event->position() - m_dragStart).manhattanLength() < 2)
            return;
        m_dragMoved = true;
        const QPointF at = clampToImage(widgetToImage(event->position()));
        LandmarkPoint &pt = m_landmarks->points[std::size_t(m_dragPoint)];
        pt.x = at.x();
        pt.y = at.y();
        update();
        return;
    }
    if (!m_dragging)
        return;
    m_pan = m_panAtDragStart + (event->position() - m_dragStart);
    update();
}

void FrameView::mouseReleaseEvent(QMouseEvent *event)
{
    if (m_dragPoint >= 0 && event->button() == Qt::LeftButton) {
        const int index = m_dragPoint;
        m_dragPoint = -1;
        if (m_dragMoved && m_landmarks) {
            // The whole drag is one edit: a point the user corrects is fixed from now on.
            m_landmarks->points[std::size_t(index)].state = PointState::Fixed;
            update();
            emit landmarksEdited(*m_landmarks, tr("Move %1").arg(pointName(index)));
        }
        return;
    }
    m_dragging = false;
    if (m_spaceHeld)
        setCursor(Qt::OpenHandCursor);
    else
        unsetCursor();
}

void FrameView::mouseDoubleClickEvent(QMouseEvent *event)
{
    if (m_editable && event->button() == Qt::LeftButton && pointAt(event->position()) >= 0)
        return;
    if (m_editable && nextUndefinedPoint() >= 0) {
        mousePressEvent(event); // a quick second click places the next point too
        return;
    }
    fitToView();
}

void FrameView::keyPressEvent(QKeyEvent *event)
{
    if (m_editable && (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) && m_landmarks
        && m_selected >= 0 && m_landmarks->points[std::size_t(m_selected)].isDefined()) {
        const int index = m_selected;
        LandmarkSet set = *m_landmarks;
        set.points[std::size_t(index)] = {};
        m_landmarks = set;
        m_selected = -1;
        update();
        emit landmarksEdited(set, tr("Remove %1").arg(pointName(index)));
        return;
    }
    if (event->key() == Qt::Key_Space && event->modifiers() == Qt::NoModifier) {
        if (!event->isAutoRepeat()) {
            m_spaceHeld = true;
            if (!m_dragging)
                setCursor(Qt::OpenHandCursor);
        }
        return;
    }
    QWidget::keyPressEvent(event);
}

void FrameView::keyReleaseEvent(QKeyEvent *event)
{
    if (event->key() == Qt::Key_Space) {
        if (!event->isAutoRepeat()) {
            m_spaceHeld = false;
            if (!m_dragging)
                unsetCursor();
        }
        return;
    }
    QWidget::keyReleaseEvent(event);
}

void FrameView::focusOutEvent(QFocusEvent *event)
{
    // The release may go to another widget: do not stay in pan mode.
    m_spaceHeld = false;
    if (!m_dragging)
        unsetCursor();
    QWidget::focusOutEvent(event);
}

bool FrameView::event(QEvent *event)
{
    // Space pans while the pointer is over the focused view (the window's Space plays the video
    // otherwise): take it before the shortcut does.
    if (event->type() == QEvent::ShortcutOverride) {
        auto *key = static_cast<QKeyEvent *>(event);
        if (key->key() == Qt::Key_Space && key->modifiers() == Qt::NoModifier && underMouse()) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

} // namespace lipsync::studio
