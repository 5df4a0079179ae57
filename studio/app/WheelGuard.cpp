#include "app/WheelGuard.h"

#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QEvent>
#include <QWidget>

namespace lipsync::studio {

namespace {
bool takesWheelValues(const QObject *o)
{
    return qobject_cast<const QAbstractSpinBox *>(o) || qobject_cast<const QComboBox *>(o)
           || (qobject_cast<const QAbstractSlider *>(o) && !o->inherits("QScrollBar"));
}
} // namespace

WheelGuard::WheelGuard(QObject *owner) : QObject(owner) {}

void WheelGuard::install(QObject *owner)
{
    qApp->installEventFilter(new WheelGuard(owner));
}

bool WheelGuard::eventFilter(QObject *watched, QEvent *event)
{
    if (event->type() == QEvent::Polish && takesWheelValues(watched)) {
        // Not focused by the wheel either (Qt gives wheel focus before filters see the event).
        auto *w = static_cast<QWidget *>(watched);
        if (w->focusPolicy() == Qt::WheelFocus)
            w->setFocusPolicy(Qt::StrongFocus);
    } else if (event->type() == QEvent::Wheel && takesWheelValues(watched)
               && !static_cast<QWidget *>(watched)->hasFocus()) {
        // Not taken: Qt passes an ignored wheel event on to the parent, so the panel scrolls.
        event->ignore();
        return true;
    }
    return QObject::eventFilter(watched, event);
}

} // namespace lipsync::studio
