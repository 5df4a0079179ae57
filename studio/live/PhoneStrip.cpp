#include "live/PhoneStrip.h"

#include "util/PhoneSet.h"

#include <QPainter>

#include <cmath>

namespace lipsync::studio {

PhoneStrip::PhoneStrip(QWidget *parent) : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void PhoneStrip::setPhones(const Tier &phones, double now)
{
    m_phones = phones;
    m_now = now;
    update();
}

void PhoneStrip::clear()
{
    m_phones.intervals.clear();
    m_now = 0.0;
    update();
}

void PhoneStrip::setSpan(double seconds)
{
    m_span = std::max(0.5, seconds);
    update();
}

QStringList PhoneStrip::visibleLabels() const
{
    QStringList labels;
    for (const Interval &p : m_phones.intervals)
        if (p.end > m_now - m_span && p.start < m_now)
            labels << QString::fromStdString(p.label);
    return labels;
}

QSize PhoneStrip::sizeHint() const
{
    return {480, fontMetrics().height() * 2 + 12};
}

QSize PhoneStrip::minimumSizeHint() const
{
    return {160, sizeHint().height()};
}

void PhoneStrip::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    const QPalette &pal = palette();
    p.fillRect(rect(), pal.color(QPalette::Base));
    const double left = m_now - m_span;
    const double scale = width() / m_span; // pixels per second
    auto x = [&](double t) { return (t - left) * scale; };
    const int boxTop = 4;
    const int boxHeight = height() - fontMetrics().height() / 2 - 10;

    // A tick per second of the session.
    p.setPen(pal.color(QPalette::Mid));
    for (double s = std::ceil(std::max(0.0, left)); s <= m_now; s += 1.0)
        p.drawLine(QPointF(x(s), height() - 5), QPointF(x(s), height()));

    const QColor speech = pal.color(QPalette::Highlight);
    QColor faint = pal.color(QPalette::Mid);
    faint.setAlpha(70);
    for (const Interval &phone : m_phones.intervals) {
        if (phone.end <= left || phone.start >= m_now)
            continue;
        const QRectF box(QPointF(x(phone.start), boxTop), QPointF(x(std::min(phone.end, m_now)), boxTop + boxHeight));
        const bool quiet = PhoneSet::isSilence(phone.label) || PhoneSet::isBreath(phone.label);
        QColor fill = quiet ? faint : speech.lighter(160);
        if (!quiet)
            fill.setAlpha(180);
        p.fillRect(box.adjusted(0.5, 0, -0.5, 0), fill);
        p.setPen(quiet ? pal.color(QPalette::PlaceholderText) : pal.color(QPalette::Text));
        const QString label = QString::fromStdString(phone.label);
        if (p.fontMetrics().horizontalAdvance(label) + 2 <= box.width())
            p.drawText(box, Qt::AlignCenter, label);
    }
    p.setPen(pal.color(QPalette::Mid));
    p.drawRect(rect().adjusted(0, 0, -1, -1));
}

} // namespace lipsync::studio
