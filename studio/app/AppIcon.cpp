#include "app/AppIcon.h"

#include <QPainter>
#include <QPainterPath>
#include <QPixmap>

namespace lipsync::studio {

namespace {

QPixmap paintIcon(int size)
{
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter p(&pixmap);
    p.setRenderHint(QPainter::Antialiasing);
    p.scale(size / 64.0, size / 64.0); // drawn on a 64 x 64 grid
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0x26, 0x32, 0x38));
    p.drawRoundedRect(QRectF(2, 2, 60, 60), 12, 12);

    QPainterPath wave;
    const QPointF points[] = {{8, 46}, {14, 46}, {17, 40}, {21, 52}, {25, 36}, {29, 56},
                              {33, 42}, {37, 50}, {41, 46}, {44, 48}, {56, 48}};
    wave.moveTo(points[0]);
    for (const QPointF &pt : points)
        wave.lineTo(pt);
    p.setBrush(Qt::NoBrush);
    p.setPen(QPen(QColor(0x4f, 0xc3, 0xf7), 2.5, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.drawPath(wave);

    QPainterPath upper;
    upper.moveTo(12, 24);
    upper.cubicTo(18, 14, 26, 13, 32, 18);
    upper.cubicTo(38, 13, 46, 14, 52, 24);
    upper.cubicTo(44, 24, 38, 25, 32, 25);
    upper.cubicTo(26, 25, 20, 24, 12, 24);
    QPainterPath lower;
    lower.moveTo(12, 24);
    lower.cubicTo(20, 36, 44, 36, 52, 24);
    lower.cubicTo(44, 27, 20, 27, 12, 24);
    p.setPen(Qt::NoPen);
    p.setBrush(QColor(0xe5, 0x73, 0x73));
    p.drawPath(upper);
    p.setBrush(QColor(0xc6, 0x28, 0x28));
    p.drawPath(lower);
    return pixmap;
}

} // namespace

QIcon appIcon()
{
    QIcon icon;
    for (int size : {16, 24, 32, 48, 64, 128, 256})
        icon.addPixmap(paintIcon(size));
    return icon;
}

} // namespace lipsync::studio
