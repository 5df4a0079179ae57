#include "timeline/WaveformView.h"

#include "util/PhoneSet.h"

#include <QKeyEvent>
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
constexpr int kWordsHeight = 24;
constexpr int kPhonesHeight = 24;
constexpr int kFrameLabelsHeight = 18;
constexpr double kGrabPixels = 4.0;
const QColor kBackground(0x1e, 0x1f, 0x22);
const QColor kLane(0x2a, 0x2c, 0x30);
const QColor kCursor(0xff, 0x52, 0x52);
const QColor kSilence(0x33, 0x35, 0x3a);
const QColor kBoundary(0x9e, 0xa3, 0xab);

// Phones coloured by class, so the strip reads at a glance: vowels, stops, fricatives and
// affricates, nasals, liquids and glides; silence grey, breath dark green.
QColor phoneColor(const std::string &label)
{
    const int index = PhoneSet::index(label);
    if (index < 0)
        return QColor(0x80, 0x80, 0x80);
    if (index == PhoneSet::kSilence)
        return kSilence;
    if (index == PhoneSet::kBreath)
        return QColor(0x2e, 0x5e, 0x4e);
    const std::string l = PhoneSet::label(index);
    static const std::array<const char *, 15> vowels{"AA", "AE", "AH", "AO", "AW", "AY", "EH", "ER",
                                                      "EY", "IH", "IY", "OW", "OY", "UH", "UW"};
    static const std::array<const char *, 6> stops{"B", "D", "G", "K", "P", "T"};
    static const std::array<const char *, 3> nasals{"M", "N", "NG"};
    static const std::array<const char *, 4> glides{"L", "R", "W", "Y"};
    auto in = [&l](const auto &set) { return std::find(set.begin(), set.end(), l) != set.end(); };
    if (in(vowels))
        return QColor(0x8e, 0x44, 0xad);
    if (in(stops))
        return QColor(0xc0, 0x5a, 0x2b);
    if (in(nasals))
        return QColor(0x2e, 0x86, 0xab);
    if (in(glides))
        return QColor(0x3f, 0x8f, 0x5a);
    return QColor(0xa0, 0x7d, 0x1c); // fricatives, affricates, HH
}
// Dark blue through red to pale yellow (perceptually ordered like "inferno"), v in [0, 1].
QRgb spectrogramColor(float v)
{
    static constexpr std::array<std::array<int, 3>, 5> stops{{{0, 0, 4}, {87, 16, 110}, {188, 55, 84}, {249, 142, 9}, {252, 255, 164}}};
    const float x = v * float(stops.size() - 1);
    const int i = std::min(int(x), int(stops.size()) - 2);
    const float u = x - float(i);
    auto mix = [&](int c) { return int(std::lround(stops[size_t(i)][size_t(c)] * (1 - u) + stops[size_t(i) + 1][size_t(c)] * u)); };
    return qRgb(mix(0), mix(1), mix(2));
}
} // namespace

namespace {

// The audio lanes' least height: the waveform alone, or the waveform and the spectrogram, each
// tall enough to read.
constexpr int kLegibleAudioLane = 64;

int minimumViewHeight(bool spectrogram)
{
    return kRulerHeight + kThumbHeight / 2 + kWordsHeight + kPhonesHeight + kFrameLabelsHeight
           + (spectrogram ? 2 * kLegibleAudioLane : 40);
}

} // namespace

WaveformView::WaveformView(QWidget *parent) : QWidget(parent)
{
    setMinimumHeight(minimumViewHeight(false));
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::ClickFocus);
    setMouseTracking(true);
}

QColor WaveformView::waveformColor()
{
    return QColor(0x4f, 0xc3, 0xf7);
}

QColor WaveformView::editedColor()
{
    return QColor(0xff, 0xa7, 0x26);
}

void WaveformView::setPeaks(std::shared_ptr<const WaveformPeaks> peaks)
{
    m_peaks = std::move(peaks);
    update();
}

void WaveformView::setSpectrogram(std::shared_ptr<const Spectrogram> spectrogram)
{
    m_spectrogram = std::move(spectrogram);
    m_spectrogramImage = QImage();
    if (m_spectrogram && !m_spectrogram->isEmpty()) {
        // Rendered once per sequence; painting then only scales the visible columns.
        const Eigen::MatrixXf &db = m_spectrogram->powerDb();
        const float top = m_spectrogram->maxDb();
        constexpr float kRangeDb = 70.0f;
        m_spectrogramImage = QImage(int(db.rows()), int(db.cols()), QImage::Format_RGB32);
        for (int b = 0; b < db.cols(); ++b) {
            auto *line = reinterpret_cast<QRgb *>(m_spectrogramImage.scanLine(int(db.cols()) - 1 - b));
            for (int f = 0; f < db.rows(); ++f)
                line[f] = spectrogramColor(std::clamp((db(f, b) - top + kRangeDb) / kRangeDb, 0.0f, 1.0f));
        }
    }
    update();
}

void WaveformView::setSpectrogramVisible(bool visible)
{
    m_showSpectrogram = visible;
    // The timeline dock grows to keep both lanes legible (thumbnails give way first).
    setMinimumHeight(minimumViewHeight(visible));
    update();
}

void WaveformView::setWords(const Tier &words)
{
    m_words = words;
    if (m_activeTier == TierKind::Words && m_selectedIndex >= int(m_words.intervals.size()))
        m_selectedIndex = -1;
    update();
}

void WaveformView::setPhones(const Tier &phones)
{
    m_phones = phones;
    if (m_activeTier == TierKind::Phones && m_selectedIndex >= int(m_phones.intervals.size()))
        m_selectedIndex = -1;
    update();
}

void WaveformView::setFrameLabels(const std::vector<std::string> &labels, const FrameClock &frames)
{
    m_frameLabels = labels;
    m_labelFrames = frames;
    update();
}

void WaveformView::setThumbnails(const QVector<QImage> &thumbnails, const FrameClock &frames)
{
    m_thumbnails = thumbnails;
    m_thumbnailFrames = frames;
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

void WaveformView::setEditable(bool editable)
{
    m_editable = editable;
    update();
}

void WaveformView::clear()
{
    m_peaks.reset();
    setSpectrogram(nullptr);
    m_words = {};
    m_phones = {};
    m_frameLabels.clear();
    m_thumbnails.clear();
    m_selectedIndex = -1;
    m_rangeStart = m_rangeEnd = 0.0;
    m_gesture = Gesture::None;
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

void WaveformView::requestTime(double seconds)
{
    emit timeClicked(seconds);
}

void WaveformView::selectInterval(TierKind kind, int index)
{
    m_activeTier = kind;
    m_selectedIndex = index >= 0 && index < int(tier(kind).intervals.size()) ? index : -1;
    m_rangeStart = m_rangeEnd = 0.0;
    update();
    emit selectionChanged();
}

void WaveformView::setRange(double start, double end)
{
    m_rangeStart = std::clamp(std::min(start, end), 0.0, m_duration);
    m_rangeEnd = std::clamp(std::max(start, end), 0.0, m_duration);
    m_selectedIndex = -1;
    update();
    emit selectionChanged();
}

void WaveformView::clearSelection()
{
    m_selectedIndex = -1;
    m_rangeStart = m_rangeEnd = 0.0;
    update();
    emit selectionChanged();
}

bool WaveformView::selection(double *start, double *end) const
{
    if (hasRange()) {
        *start = m_rangeStart;
        *end = m_rangeEnd;
        return true;
    }
    if (m_selectedIndex >= 0) {
        const Interval &iv = tier(m_activeTier).intervals[size_t(m_selectedIndex)];
        *start = iv.start;
        *end = iv.end;
        return true;
    }
    return false;
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

QRect WaveformView::laneRect(Lane lane) const
{
    const int w = width();
    const int frames = height() - kFrameLabelsHeight;
    const int phones = frames - kPhonesHeight;
    const int words = phones - kWordsHeight;
    // Thumbnails give way first when the dock is low, more so with the spectrogram.
    const int thumbs = std::clamp((words - kRulerHeight - (m_showSpectrogram ? 2 * kLegibleAudioLane : 0)) / 4, 0,
                                  kThumbHeight);
    const int audio = std::max(0, words - kRulerHeight - thumbs);
    // The spectrogram, when shown, takes the lower half of the audio lanes.
    const int spectrogram = m_showSpectrogram ? audio / 2 : 0;
    switch (lane) {
    case Lane::Ruler: return QRect(0, 0, w, kRulerHeight);
    case Lane::Thumbnails: return QRect(0, kRulerHeight, w, thumbs);
    case Lane::Waveform: return QRect(0, kRulerHeight + thumbs, w, audio - spectrogram);
    case Lane::Spectrogram: return QRect(0, words - spectrogram, w, spectrogram);
    case Lane::Words: return QRect(0, words, w, kWordsHeight);
    case Lane::Phones: return QRect(0, phones, w, kPhonesHeight);
    case Lane::FrameLabels: return QRect(0, frames, w, kFrameLabelsHeight);
    }
    return {};
}

void WaveformView::paintEvent(QPaintEvent *)
{
    QPainter p(this);
    p.fillRect(rect(), kBackground);
    const QRect wave = laneRect(Lane::Waveform);
    drawRuler(p, laneRect(Lane::Ruler));
    drawThumbnails(p, laneRect(Lane::Thumbnails));
    drawWaveform(p, wave);
    if (m_showSpectrogram)
        drawSpectrogram(p, laneRect(Lane::Spectrogram));
    drawTier(p, laneRect(Lane::Words), TierKind::Words);
    drawTier(p, laneRect(Lane::Phones), TierKind::Phones);
    drawFrameLabels(p, laneRect(Lane::FrameLabels));

    if (!m_peaks && !m_placeholder.isEmpty()) {
        p.setPen(QColor(190, 190, 190));
        p.drawText(wave, Qt::AlignCenter, m_placeholder);
    }
    if (hasRange()) {
        const double x0 = xAt(m_rangeStart);
        const double x1 = xAt(m_rangeEnd);
        const QRectF band(x0, kRulerHeight, x1 - x0, laneRect(Lane::FrameLabels).bottom() - kRulerHeight);
        p.fillRect(band, QColor(255, 255, 255, 40));
        p.setPen(QColor(255, 255, 255, 140));
        p.drawLine(QPointF(x0, kRulerHeight), QPointF(x0, height()));
        p.drawLine(QPointF(x1, kRulerHeight), QPointF(x1, height()));
    }
    if (m_duration > 0) {
        const double x = xAt(m_cursor);
        p.setPen(QPen(kCursor, 1.5));
        p.drawLine(QPointF(x, kRulerHeight), QPointF(x, height()));
    }
    if (hasFocus()) {
        p.setPen(QColor(0x4f, 0xc3, 0xf7, 120));
        p.drawRect(rect().adjusted(0, 0, -1, -1));
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
    // One thumbnail per slot, showing the frame on screen at the slot's centre time.
    for (int x = 0; x < r.width(); x += tw + 1) {
        const double t = timeAt(x + tw / 2.0);
        if (m_thumbnailFrames.empty() || t < m_thumbnailFrames.startTime() || t >= m_thumbnailFrames.endTime())
            continue;
        const int frame = m_thumbnailFrames.frameAt(t);
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

void WaveformView::drawSpectrogram(QPainter &p, const QRect &r) const
{
    p.fillRect(r, kBackground);
    if (m_spectrogramImage.isNull() || r.isEmpty())
        return;
    // Image column f is frame f, centred at frameCentre(f): x in image units for time t.
    const Spectrogram &s = *m_spectrogram;
    auto column = [&s](double t) { return (t - s.windowSeconds() / 2.0) / s.shiftSeconds() + 0.5; };
    const double c0 = std::max(0.0, column(timeAt(0)));
    const double c1 = std::min(double(m_spectrogramImage.width()), column(timeAt(r.width())));
    if (c1 <= c0)
        return;
    auto xOf = [&](double c) { return xAt((c - 0.5) * s.shiftSeconds() + s.windowSeconds() / 2.0); };
    const QRectF target(xOf(c0), r.top(), xOf(c1) - xOf(c0), r.height());
    p.drawImage(target, m_spectrogramImage, QRectF(c0, 0, c1 - c0, m_spectrogramImage.height()));
    drawLaneName(p, r, tr("spectrogram"));
}

void WaveformView::drawLaneName(QPainter &p, const QRect &r, const QString &name) const
{
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.75);
    p.setFont(f);
    const QRect box(r.left(), r.top(), p.fontMetrics().horizontalAdvance(name) + 6, p.fontMetrics().height());
    p.fillRect(box, QColor(0, 0, 0, 140));
    p.setPen(QColor(200, 200, 200));
    p.drawText(box, Qt::AlignCenter, name);
    p.setFont(font());
}

void WaveformView::drawTier(QPainter &p, const QRect &r, TierKind kind) const
{
    p.fillRect(r, kLane);
    p.setFont(font());
    const Tier &t = tier(kind);
    const bool phones = kind == TierKind::Phones;
    if (t.intervals.empty()) {
        p.setPen(QColor(150, 150, 150));
        p.drawText(r, Qt::AlignCenter,
                   phones ? tr("No phones yet: align the sequence (Align)") : tr("No words"));
        drawLaneName(p, r, phones ? tr("phones") : tr("words"));
        return;
    }
    int spoken = 0;
    for (int i = 0; i < int(t.intervals.size()); ++i) {
        const Interval &iv = t.intervals[size_t(i)];
        const double x0 = xAt(iv.start);
        const double x1 = xAt(iv.end);
        const bool silent = PhoneSet::isSilence(iv.label);
        if (!silent)
            ++spoken;
        if (x1 < 0 || x0 > r.width())
            continue;
        const QRectF box(x0, r.top() + 2, std::max(1.0, x1 - x0), r.height() - 4);
        QColor fill = silent ? kSilence
                      : phones ? phoneColor(iv.label)
                               : ((spoken % 2) ? QColor(0x7e, 0x57, 0xc2) : QColor(0x5c, 0x6b, 0xc0));
        p.fillRect(box, fill);
        if (iv.userEdited)
            p.fillRect(QRectF(box.left(), box.top(), box.width(), 3), editedColor());
        if (!silent || phones) {
            p.setPen(silent ? QColor(160, 160, 160) : Qt::white);
            const QString text = QString::fromStdString(iv.label);
            if (p.fontMetrics().horizontalAdvance(text) <= box.width() - 2 || !phones)
                p.drawText(box.adjusted(1, 0, -1, 0), Qt::AlignCenter,
                           p.fontMetrics().elidedText(text, Qt::ElideRight, int(box.width()) - 2));
        }
        if (i == m_selectedIndex && kind == m_activeTier && !hasRange()) {
            p.setPen(QPen(Qt::white, 2));
            p.drawRect(box.adjusted(1, 1, -1, -1));
        }
    }
    // Boundaries on top: orange where the user moved or relabelled a neighbour.
    for (int b = 1; b < int(t.intervals.size()); ++b) {
        const double x = xAt(t.intervals[size_t(b)].start);
        if (x < 0 || x > r.width())
            continue;
        const bool edited = t.intervals[size_t(b)].userEdited || t.intervals[size_t(b - 1)].userEdited;
        p.setPen(QPen(edited ? editedColor() : kBoundary, edited ? 2.0 : 1.0));
        p.drawLine(QPointF(x, r.top()), QPointF(x, r.bottom()));
    }
    drawLaneName(p, r, phones ? tr("phones") : tr("words"));
}

void WaveformView::drawFrameLabels(QPainter &p, const QRect &r) const
{
    p.fillRect(r, kBackground);
    if (m_frameLabels.empty()) {
        drawLaneName(p, r, tr("frame labels"));
        return;
    }
    QFont f = p.font();
    f.setPointSizeF(f.pointSizeF() * 0.75);
    p.setFont(f);
    const int labelled = std::min(int(m_frameLabels.size()), m_labelFrames.count());
    for (int i = 0; i < labelled; ++i) {
        const double x0 = xAt(m_labelFrames.time(i));
        const double x1 = xAt(m_labelFrames.endTime(i));
        if (x1 < 0 || x0 > r.width())
            continue;
        const QRectF cell(x0, r.top() + 1, std::max(1.0, x1 - x0 - 1), r.height() - 2);
        QColor fill = phoneColor(m_frameLabels[size_t(i)]);
        p.fillRect(cell, i % 2 ? fill.darker(115) : fill);
        const QString text = QString::fromStdString(m_frameLabels[size_t(i)]);
        if (p.fontMetrics().horizontalAdvance(text) <= cell.width()) {
            p.setPen(QColor(235, 235, 235));
            p.drawText(cell, Qt::AlignCenter, text);
        }
    }
    p.setFont(font());
    drawLaneName(p, r, tr("frames"));
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

bool WaveformView::tierAt(const QPointF &pos, TierKind *kind) const
{
    if (laneRect(Lane::Words).contains(pos.toPoint())) {
        *kind = TierKind::Words;
        return true;
    }
    if (laneRect(Lane::Phones).contains(pos.toPoint())) {
        *kind = TierKind::Phones;
        return true;
    }
    return false;
}

int WaveformView::boundaryAtX(TierKind kind, double x) const
{
    return tieredit::boundaryNear(tier(kind), timeAt(x), kGrabPixels * m_secondsPerPixel);
}

void WaveformView::mousePressEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton || m_duration <= 0)
        return;
    const QPointF pos = event->position();
    const double t = std::clamp(timeAt(pos.x()), 0.0, m_duration);
    m_pressX = pos.x();
    m_pressTime = t;
    TierKind kind;
    if (tierAt(pos, &kind)) {
        const int boundary = m_editable ? boundaryAtX(kind, pos.x()) : -1;
        if (boundary > 0) {
            m_gesture = Gesture::Boundary;
            m_dragTier = kind;
            m_dragBoundary = boundary;
            m_boundaryStart = tieredit::boundaryTime(tier(kind), boundary);
            emit boundaryDragStarted(kind, boundary, ++m_dragCount);
            return;
        }
        m_gesture = Gesture::None;
        selectInterval(kind, tier(kind).indexAt(t));
        emit timeClicked(t);
        setCursorTime(t); // the exact time (the main window puts it at the frame's centre)
        return;
    }
    m_gesture = laneRect(Lane::Ruler).contains(pos.toPoint()) ? Gesture::Scrub : Gesture::Range;
    if (m_gesture == Gesture::Range && (hasRange() || m_selectedIndex >= 0))
        clearSelection();
    emit timeClicked(t);
    setCursorTime(t);
}

void WaveformView::mouseMoveEvent(QMouseEvent *event)
{
    const QPointF pos = event->position();
    if (!(event->buttons() & Qt::LeftButton) || m_gesture == Gesture::None) {
        // Hover: a resize cursor where a press would grab a boundary.
        TierKind kind;
        const bool grab = m_editable && tierAt(pos, &kind) && boundaryAtX(kind, pos.x()) > 0;
        setCursor(grab ? Qt::SizeHorCursor : Qt::ArrowCursor);
        return;
    }
    if (m_duration <= 0)
        return;
    const double t = std::clamp(timeAt(pos.x()), 0.0, m_duration);
    switch (m_gesture) {
    case Gesture::Boundary:
        emit boundaryDragged(m_dragTier, m_dragBoundary,
                             m_boundaryStart + (pos.x() - m_pressX) * m_secondsPerPixel, m_dragCount);
        break;
    case Gesture::Scrub:
        emit timeClicked(t);
        setCursorTime(t);
        break;
    case Gesture::Range:
        if (std::abs(pos.x() - m_pressX) >= 3.0)
            setRange(m_pressTime, t);
        break;
    case Gesture::None:
        break;
    }
}

void WaveformView::mouseReleaseEvent(QMouseEvent *event)
{
    if (event->button() != Qt::LeftButton)
        return;
    if (m_gesture == Gesture::Boundary) {
        emit boundaryDragged(m_dragTier, m_dragBoundary,
                             m_boundaryStart + (event->position().x() - m_pressX) * m_secondsPerPixel, m_dragCount);
        emit boundaryDragFinished(m_dragTier, m_dragBoundary, m_dragCount);
    }
    m_gesture = Gesture::None;
}

void WaveformView::mouseDoubleClickEvent(QMouseEvent *event)
{
    TierKind kind;
    if (event->button() != Qt::LeftButton || !m_editable || !tierAt(event->position(), &kind))
        return;
    const int index = tier(kind).indexAt(timeAt(event->position().x()));
    if (index < 0)
        return;
    selectInterval(kind, index);
    emit relabelRequested(kind, index);
}

bool WaveformView::event(QEvent *event)
{
    // Space plays the timeline's selection while the timeline has focus (the window's Space
    // plays the video otherwise); Tab walks the intervals instead of the focus chain.
    if (event->type() == QEvent::ShortcutOverride) {
        auto *key = static_cast<QKeyEvent *>(event);
        if ((key->key() == Qt::Key_Space || key->key() == Qt::Key_Escape) && key->modifiers() == Qt::NoModifier) {
            event->accept();
            return true;
        }
    }
    return QWidget::event(event);
}

bool WaveformView::focusNextPrevChild(bool)
{
    return false;
}

void WaveformView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Space:
        emit playRequested();
        return;
    case Qt::Key_Escape:
        clearSelection();
        return;
    case Qt::Key_Tab:
    case Qt::Key_Backtab: {
        const Tier &t = tier(m_activeTier);
        if (t.intervals.empty())
            return;
        const bool back = event->key() == Qt::Key_Backtab || (event->modifiers() & Qt::ShiftModifier);
        int index = m_selectedIndex;
        if (index < 0)
            index = std::max(0, t.indexAt(m_cursor)) + (back ? 0 : -1);
        index = std::clamp(index + (back ? -1 : 1), 0, int(t.intervals.size()) - 1);
        selectInterval(m_activeTier, index);
        const Interval &iv = t.intervals[size_t(index)];
        emit timeClicked(iv.start);
        setCursorTime(iv.start);
        return;
    }
    default:
        QWidget::keyPressEvent(event);
    }
}

} // namespace lipsync::studio
