#pragma once
// Spin boxes, combo boxes and sliders take the mouse wheel only once they have focus (a click or
// Tab): over an unfocused one the wheel scrolls what holds it, so scrolling a panel never changes
// a setting under the cursor by accident. An event filter on the application, owned by a window.
#include <QObject>

namespace lipsync::studio {

class WheelGuard : public QObject
{
    Q_OBJECT
public:
    // Filters the whole application's events for as long as `owner` lives.
    static void install(QObject *owner);

protected:
    bool eventFilter(QObject *watched, QEvent *event) override;

private:
    explicit WheelGuard(QObject *owner);
};

} // namespace lipsync::studio
