#include "app/TransportBar.h"

#include "context/StudioActions.h"

#include <QHBoxLayout>
#include <QLocale>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QSpinBox>
#include <QToolButton>

namespace lipsync::studio {

TransportBar::TransportBar(const StudioActions &actions, QWidget *parent)
    : QWidget(parent), m_slider(new QSlider(Qt::Horizontal, this)), m_spin(new QSpinBox(this)),
      m_time(new QLabel(this))
{
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(6, 2, 6, 2);
    for (QAction *a : {actions.firstFrame, actions.previousFrame, actions.playPause, actions.nextFrame,
                       actions.lastFrame}) {
        auto *b = new QToolButton(this);
        b->setDefaultAction(a);
        b->setAutoRaise(true);
        layout->addWidget(b);
    }
    layout->addWidget(m_slider, 1);
    auto *label = new QLabel(tr("Frame"), this);
    label->setBuddy(m_spin);
    layout->addWidget(label);
    m_spin->setAccelerated(true);
    m_spin->setKeyboardTracking(false);
    layout->addWidget(m_spin);
    m_time->setMinimumWidth(m_time->fontMetrics().horizontalAdvance(QStringLiteral("00.00 s / 00.00 s")) + 8);
    m_time->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    layout->addWidget(m_time);

    connect(m_slider, &QSlider::valueChanged, this, &TransportBar::frameRequested);
    // Frames are numbered from 1 wherever the studio shows them (the annotator's and the
    // preview's captions too); the slider and the signals use indices from 0.
    connect(m_spin, &QSpinBox::valueChanged, this, [this](int shown) { emit frameRequested(shown - 1); });
    setClock({});
}

void TransportBar::setClock(const FrameClock &clock)
{
    const QSignalBlocker b1(m_slider);
    const QSignalBlocker b2(m_spin);
    m_clock = clock;
    const int count = clock.count();
    m_slider->setRange(0, std::max(0, count - 1));
    m_spin->setRange(1, std::max(1, count));
    m_slider->setPageStep(std::max(1, int(clock.rate()))); // about a second
    setEnabled(count > 0);
    updateTime();
}

void TransportBar::setFrame(int frame)
{
    const QSignalBlocker b1(m_slider);
    const QSignalBlocker b2(m_spin);
    m_slider->setValue(frame);
    m_spin->setValue(frame + 1);
    updateTime();
}

int TransportBar::frame() const
{
    return m_spin->value() - 1;
}

void TransportBar::updateTime()
{
    m_time->setText(tr("%1 s / %2 s")
                        .arg(QLocale().toString(m_clock.empty() ? 0.0 : m_clock.time(frame()), 'f', 2),
                             QLocale().toString(m_clock.endTime(), 'f', 2)));
}

} // namespace lipsync::studio
