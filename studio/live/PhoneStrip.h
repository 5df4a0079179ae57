#pragma once
// The recognised phones of the last seconds as a strip scrolling right to left: the newest sound
// at the right edge, one box per phone with its label, silence and breath drawn faintly, and a
// tick per second.
#include "annotation/Tier.h"

#include <QWidget>

namespace lipsync::studio {

class PhoneStrip : public QWidget
{
    Q_OBJECT
public:
    explicit PhoneStrip(QWidget *parent = nullptr);

    // The phones (times in seconds of the session), and the sound heard so far: the right edge.
    void setPhones(const Tier &phones, double now);
    void clear();
    // The phones in view, oldest first (the labels drawn).
    QStringList visibleLabels() const;
    // Seconds of sound the strip spans.
    void setSpan(double seconds);
    double span() const { return m_span; }

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    Tier m_phones{"phones", {}};
    double m_now = 0.0;
    double m_span = 4.0;
};

} // namespace lipsync::studio
