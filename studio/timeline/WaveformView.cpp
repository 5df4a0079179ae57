#include "timeline/WaveformView.h"

#include <QLocale>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <algorithm>
#include <array>
#include <cmath>

namespace lipsync::studio {

namespace {
constexpr int kRulerHeight = 20;
constexpr int kThumbHeight = 44;
constexpr int kWordsHeight = 26;
const QColor kBackground(0x1e, 0x1f, 0x22);
const QColor kLane(0x2a, 0x2c, 0x30);
const QColor kCursor(0xff, 0x52, 0x52);

bool isSilence(const std::string &label)
{
    return label == "sil" || label == "sp" || label.empty();
}
} // namespace

WaveformView::WaveformView(QWidget *parent) : QWidget(parent)
{
    setMinimumHeight(kRulerHeight + kThumbHeight + kWordsHeight + 60);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::ClickFocus);
}

QColor WaveformView::waveformColor()
{
    return QColor(0x4f, 0xc3, 0xf7);
}

void WaveformView::setPeaks(std::shared_ptr<const WaveformPeaks> peaks)
{
    m_peaks = std::move(peaks);
    update();
}

void WaveformView::setWords(const Tier &words)
{
    m_words = words;
    update();
}

void WaveformView::setThumbnails(const QVector<QImage> &thumbnails, double frameRate)
{
    m_thumbnails = thumbnails;
    m_frameRate = frameRate > 0 ? frameRate : 25.0;
    update();
}

void WaveformView::setDuration(double seconds)
{
    m_duration = std::max(0.0, seconds);
    m_fitted = true;
    zoomToFit();
}

void WaveformView::setPlaceholderText(const QString &text)
{
    m_placeholder = text;
    update();
}

void WaveformView::clear()
{
    m_peaks.reset();
    m_words = {};
    m_thumbnails.clear();
    update();
}

void WaveformView::setCursorTime(double seconds)
{
    m_cursor = seconds;
    // Keep the cursor in view while stepping or playing through a zoomed-in timeline.
    if (!m_fitted && (seconds < m_start || seconds > m_start + visibleDuration()))
        setViewStart(seconds - visibleDuration() * 0.1);
    update();
}

double WaveformView::fitSecondsPerPixel() const
{
    return m_duration > 0 && width() > 0 ? m_duration / width() : 0.01;
}

void WaveformView::clampView()
{
    const double maxStart = std::max(0.0, m_duration - visibleDuration());
    m_start = std::clamp(m_start, 0.0, maxStart);
}

void WaveformView::setViewStart(double seconds)
{
    m_start = seconds;
    clampView();
    update();
    emit viewChanged();
}

void WaveformView::zoomBy(double factor, double anchorX)
{
    const double anchorTime = timeAt(anchorX);
    // From one audio sample per 4 pixels (16 kHz) out to the whole sequence.
    const double finest = 1.0 / 64000.0;
    const double coarsest = fitSecondsPerPixel();
    m_secondsPerPixel = std::clamp(m_secondsPerPixel / factor, finest, std::max(finest, coarsest));
    m_fitted = m_secondsPerPixel >= coarsest;
    m_start = anchorTime - anchorX * m_secondsPerPixel;
    clampView();
    update();
    emit viewChanged();
}

void WaveformView::zoomToFit()
{
    m_secondsPerPixel = fitSecondsPerPixel();
    m_start = 0.0;
    m_fitted = true;
    update();
    emit viewChanged();
}

void WaveformView::resizeEvent(QResizeEvent *)
{
    if (m_fitted)
        zoomToFit();
    else
        setViewStart(m_start);
}

void WaveformView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.fillRect(rect(), kBackground);
    const int w = width();
    const QRect ruler(0, 0, w, kRulerHeight);
    const QRect thumbs(0, ruler.bottom() + 1, w, kThumbHeight);
    const QRect words(0, height() - kWordsHeight, w, kWordsHeight);
    const QRect wave(0, thumbs.bottom() + 1, w, words.top() - thumbs.bottom() - 1);

    drawRuler(p, ruler);
    drawThumbnails(p, thumbs);
    drawWaveform(p, wave);
    drawWords(p, words);

    if (!m_peaks && !m_placeholder.isEmpty()) {
        p.setPen(QColor(190, 190, 190));
        p.drawText(wave, Qt::AlignCenter, m_placeholder);
    }
    if (m_duration > 0) {
        const double x = xAt(m_cursor);
        p.setPen(QPen(kCursor, 1.5));
        p.drawLine(QPointF(x, kRulerHeight), QPointF(x, height()));
    }
}

void WaveformView::drawRuler(QPainter &p, const QRect &r) const
{
    p.fillRect(r, kLane);
    if (m_duration <= 0)
        return;
    // The smallest "round" step leaving at least 70 pixels between labels.
    static constexpr std::array<double, 13> steps{0.005, 0.01, 0.02, 0.05, 0.1, 0.2, 0.25, 0.5, 1, 2, 5, 10, 30};
    double step = steps.back();
    for (double s : steps) {
        if (s / m_secondsPerPixel >= 70.0) {
            step = s;
            break;
        }
    }
    p.setPen(QColor(170, 170, 170));
    QFont f = p.font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    p.setFont(f);
    const int decimals = step >= 1 ? 0 : step >= 0.1 ? 1 : step >= 0.01 ? 2 : 3;
    for (double t = std::ceil(m_start / step) * step; t <= m_start + visibleDuration(); t += step) {
        const double x = xAt(t);
        p.drawLine(QPointF(x, r.bottom() - 5), QPointF(x, r.bottom()));
        p.drawText(QPointF(x + 3, r.bottom() - 6), QLocale().toString(t, 'f', decimals) + QStringLiteral(" s"));
    }
}

void WaveformView::drawThumbnails(QPainter &p, const QRect &r) const
{
    p.fillRect(r, kBackground);
    if (m_thumbnails.isEmpty())
        return;
    const QImage &first = m_thumbnails.front();
    const int h = r.height() - 4;
    const int tw = std::max(8, first.height() > 0 ? first.width() * h / first.height() : h);
    p.setRenderHint(QPainter::SmoothPixmapTransform);
    // One thumbnail per slot, showing the frame at the slot's centre time.
    for (int x = 0; x < r.width(); x += tw + 1) {
        const int frame = int(timeAt(x + tw / 2.0) * m_frameRate);
        if (frame < 0 || frame >= m_thumbnails.size())
            continue;
        p.drawImage(QRect(x, r.top() + 2, tw, h), m_thumbnails[frame]);
    }
}

void WaveformView::drawWaveform(QPainter &p, const QRect &r) const
{
    const double mid = r.center().y();
    const double half = r.height() / 2.0 - 2.0;
    p.setPen(QColor(0x3a, 0x3d, 0x42));
    p.drawLine(QPointF(0, mid), QPointF(r.width(), mid));
    if (!m_peaks || m_peaks->isEmpty())
        return;
    // Scale to the loudest sample so quiet recordings stay readable.
    const Peak all = m_peaks->peak(0, m_peaks->sampleCount());
    const double gain = 0.95 / std::max(0.05, double(std::max(std::abs(all.min), std::abs(all.max))));
    p.setPen(waveformColor());
    for (int x = 0; x < r.width(); ++x) {
        const double t0 = timeAt(x);
        if (t0 >= m_peaks->duration())
            break;
        const Peak pk = m_peaks->peakInTime(t0, t0 + m_secondsPerPixel);
        const double top = mid - std::clamp(pk.max * gain, -1.0, 1.0) * half;
        const double bottom = mid - std::clamp(pk.min * gain, -1.0, 1.0) * half;
        p.drawLine(QPointF(x + 0.5, top), QPointF(x + 0.5, std::max(bottom, top + 1.0)));
    }
}

void WaveformView::drawWords(QPainter &p, const QRect &r) const
{
    p.fillRect(r, kLane);
    int spoken = 0;
    for (const Interval &iv : m_words.intervals) {
        const double x0 = xAt(iv.start);
        const double x1 = xAt(iv.end);
        if (x1 < 0 || x0 > r.width())
            continue;
        const QRectF box(x0, r.top() + 2, std::max(1.0, x1 - x0), r.height() - 4);
        if (isSilence(iv.label)) {
            p.fillRect(box, QColor(0x33, 0x35, 0x3a));
            continue;
        }
        p.fillRect(box, (spoken++ % 2) ? QColor(0x5c, 0x6b, 0xc0) : QColor(0x7e, 0x57, 0xc2));
        p.setPen(Qt::white);
        p.drawText(box.adjusted(2, 0, -2, 0), Qt::AlignCenter,
                   p.fontMetrics().elidedText(QString::fromStdString(iv.label), Qt::ElideRight,
                                              int(box.width()) - 4));
    }
}

void WaveformView::wheelEvent(QWheelEvent *event)
{
    const double steps = event->angleDelta().y() / 120.0;
    if (event->modifiers() & Qt::ShiftModifier || event->angleDelta().x() != 0) {
        const double delta = event->angleDelta().x() != 0 ? -event->angleDelta().x() / 120.0 : -steps;
        setViewStart(m_start + delta * visibleDuration() * 0.1);
    } else {
        zoomBy(std::pow(1.25, steps), event->position().x());
    }
    event->accept();
}

void WaveformView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() == Qt::LeftButton && m_duration > 0)
        emit timeClicked(std::clamp(timeAt(event->position().x()), 0.0, m_duration));
}

void WaveformView::mouseMoveEvent(QMouseEvent *event)
{
    if (event->buttons() & Qt::LeftButton && m_duration > 0)
        emit timeClicked(std::clamp(timeAt(event->position().x()), 0.0, m_duration));
}

} // namespace lipsync::studio
