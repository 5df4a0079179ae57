#include "timeline/TimelinePanel.h"

#include "timeline/WaveformView.h"

#include <QHBoxLayout>
#include <QScrollBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace lipsync::studio {

namespace {
// The scroll bar counts milliseconds.
constexpr double kUnitsPerSecond = 1000.0;
} // namespace

TimelinePanel::TimelinePanel(QWidget *parent)
    : QWidget(parent), m_waveform(new WaveformView(this)), m_scroll(new QScrollBar(Qt::Horizontal, this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(m_waveform, 1);

    auto *bar = new QHBoxLayout;
    bar->setContentsMargins(4, 0, 4, 2);
    auto makeButton = [this, bar](const QString &text, const QString &tip) {
        auto *b = new QToolButton(this);
        b->setText(text);
        b->setToolTip(tip);
        b->setAutoRaise(true);
        bar->addWidget(b);
        return b;
    };
    bar->addWidget(m_scroll, 1);
    QToolButton *zoomOut = makeButton(QStringLiteral("−"), tr("Zoom out (wheel down)"));
    QToolButton *zoomIn = makeButton(QStringLiteral("+"), tr("Zoom in (wheel up)"));
    QToolButton *fit = makeButton(tr("Fit"), tr("Show the whole sequence"));
    layout->addLayout(bar);

    connect(zoomIn, &QToolButton::clicked, this, [this] { m_waveform->zoomBy(2.0, m_waveform->width() / 2.0); });
    connect(zoomOut, &QToolButton::clicked, this, [this] { m_waveform->zoomBy(0.5, m_waveform->width() / 2.0); });
    connect(fit, &QToolButton::clicked, m_waveform, &WaveformView::zoomToFit);
    connect(m_waveform, &WaveformView::viewChanged, this, &TimelinePanel::syncScrollBar);
    connect(m_scroll, &QScrollBar::valueChanged, this, [this](int value) {
        if (!m_syncing)
            m_waveform->setViewStart(value / kUnitsPerSecond);
    });
    syncScrollBar();
}

void TimelinePanel::syncScrollBar()
{
    m_syncing = true;
    const int page = int(std::lround(m_waveform->visibleDuration() * kUnitsPerSecond));
    const int total = int(std::lround(m_waveform->duration() * kUnitsPerSecond));
    m_scroll->setRange(0, std::max(0, total - page));
    m_scroll->setPageStep(std::max(1, page));
    m_scroll->setSingleStep(std::max(1, page / 10));
    m_scroll->setValue(int(std::lround(m_waveform->viewStart() * kUnitsPerSecond)));
    m_scroll->setEnabled(total > page);
    m_syncing = false;
}

} // namespace lipsync::studio
