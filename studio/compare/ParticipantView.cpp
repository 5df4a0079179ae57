#include "compare/ParticipantView.h"

#include "compare/StudyClipRenderer.h"

#include <QApplication>
#include <QAudioOutput>
#include <QKeyEvent>
#include <QLabel>
#include <QMediaPlayer>
#include <QMessageBox>
#include <QPainter>
#include <QPushButton>
#include <QTimer>
#include <QUrl>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace lipsync::studio {

ParticipantView::ParticipantView(QWidget *parent)
    : QWidget(parent), m_progress(new QLabel(this)), m_prompt(new QLabel(this)), m_timer(new QTimer(this))
{
    setObjectName(QStringLiteral("participantView"));
    setWindowTitle(tr("Which one is real?"));
    setFocusPolicy(Qt::StrongFocus);
    setAutoFillBackground(true);
    QPalette dark = palette();
    dark.setColor(QPalette::Window, Qt::black);
    dark.setColor(QPalette::WindowText, QColor(230, 230, 230));
    setPalette(dark);
    QFont big = font();
    big.setPointSizeF(big.pointSizeF() > 0 ? big.pointSizeF() * 1.6 : 16.0);
    m_progress->setFont(big);
    m_prompt->setFont(big);
    m_progress->setAlignment(Qt::AlignCenter);
    m_prompt->setAlignment(Qt::AlignCenter);
    m_prompt->setWordWrap(true);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_progress);
    layout->addStretch(1);
    layout->addWidget(m_prompt);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, &ParticipantView::tick);
}

ParticipantView::~ParticipantView() = default;

void ParticipantView::showPreparing(int index, int count)
{
    stop();
    m_left.clear();
    m_right.clear();
    m_accepting = false;
    m_message = tr("Preparing the next videos…");
    m_progress->setText(tr("Trial %1 of %2").arg(index + 1).arg(count));
    m_prompt->clear();
    update();
}

void ParticipantView::showTrial(int index, int count, const StudyClip &left, const StudyClip &right)
{
    stop();
    m_left = left.frames;
    m_right = right.frames;
    m_frameRate = left.frameRate > 0 ? left.frameRate : 25.0;
    m_mediaPath = left.mediaPath;
    m_message.clear();
    m_progress->setText(tr("Trial %1 of %2").arg(index + 1).arg(count));
    m_prompt->setText(tr("Which video is real?   ← left     ↓ can't decide     → right     R replay"));
    m_accepting = true;
    m_answerClock.start();
    replay();
}

void ParticipantView::showFinished()
{
    stop();
    m_left.clear();
    m_right.clear();
    m_accepting = false;
    m_progress->clear();
    m_message = tr("Thank you! All answers are saved.");
    m_prompt->setText(tr("Press Esc to leave."));
    update();
}

void ParticipantView::showMessage(const QString &text)
{
    stop();
    m_accepting = false;
    m_message = text;
    m_prompt->setText(tr("Press Esc to leave."));
    update();
}

QString ParticipantView::progressText() const
{
    return m_progress->text();
}

QString ParticipantView::promptText() const
{
    return m_prompt->text();
}

bool ParticipantView::isPlaying() const
{
    return m_timer->isActive();
}

void ParticipantView::replay()
{
    if (m_left.empty())
        return;
    stop();
    m_frame = 0;
    if (m_audioEnabled && !m_mediaPath.isEmpty()) {
        if (!m_player) {
            m_player = new QMediaPlayer(this);
            m_output = new QAudioOutput(this);
            m_player->setAudioOutput(m_output);
        }
        if (m_player->source() != QUrl::fromLocalFile(m_mediaPath))
            m_player->setSource(QUrl::fromLocalFile(m_mediaPath));
        m_player->setPosition(0);
        m_player->play();
    }
    m_clock.start();
    m_timer->start(int(std::max(5.0, 500.0 / m_frameRate)));
    update();
}

void ParticipantView::stop()
{
    m_timer->stop();
    if (m_player)
        m_player->pause();
}

void ParticipantView::tick()
{
    // The frame follows the wall clock the sound also runs on, so a late timer skips frames
    // rather than letting the picture fall behind the speech.
    const int count = int(std::min(m_left.size(), m_right.size()));
    const int frame = int(std::floor(m_clock.elapsed() / 1000.0 * m_frameRate));
    if (frame >= count) {
        m_frame = std::max(0, count - 1);
        stop();
    } else {
        m_frame = frame;
    }
    update();
}

void ParticipantView::answer(StudyChoice choice)
{
    if (!m_accepting)
        return;
    m_accepting = false;
    stop();
    emit answered(choice, m_answerClock.elapsed() / 1000.0);
}

void ParticipantView::askToLeave()
{
    stop();
    if (m_confirmLeave && m_accepting) {
        // In the application's colours, not the view's black (a child inherits its palette):
        // legible on the dark screen. Enter continues; only an explicit choice leaves.
        QMessageBox box(QMessageBox::Question, tr("Leave the study"),
                        tr("Leave the study now? The answers given so far are saved; this participant can "
                           "continue later."),
                        QMessageBox::NoButton, this);
        box.setObjectName(QStringLiteral("leaveStudyBox"));
        box.setPalette(QApplication::palette());
        QPushButton *leave = box.addButton(tr("Leave"), QMessageBox::AcceptRole);
        QPushButton *stay = box.addButton(tr("Continue the study"), QMessageBox::RejectRole);
        box.setDefaultButton(stay);
        box.setEscapeButton(stay);
        box.exec();
        if (box.clickedButton() != leave)
            return;
    }
    emit leaveRequested();
}

void ParticipantView::keyPressEvent(QKeyEvent *event)
{
    switch (event->key()) {
    case Qt::Key_Left: answer(StudyChoice::Left); break;
    case Qt::Key_Right: answer(StudyChoice::Right); break;
    case Qt::Key_Down: answer(StudyChoice::Undecided); break;
    case Qt::Key_R:
    case Qt::Key_Space: replay(); break;
    case Qt::Key_Escape: askToLeave(); break;
    default: QWidget::keyPressEvent(event); return;
    }
    event->accept();
}

void ParticipantView::paintEvent(QPaintEvent *event)
{
    QWidget::paintEvent(event);
    QPainter painter(this);
    painter.setRenderHint(QPainter::SmoothPixmapTransform);
    const QRect area = rect().adjusted(24, 80, -24, -90);
    if (m_left.empty() || m_right.empty()) {
        painter.setPen(palette().color(QPalette::WindowText));
        painter.setFont(m_progress->font());
        painter.drawText(area, Qt::AlignCenter | Qt::TextWordWrap, m_message);
        return;
    }
    // Two equal panels with a gap; each video scaled to fit, centred, aspect kept.
    const int gap = 32;
    const int panelWidth = (area.width() - gap) / 2;
    const int index = std::clamp(m_frame, 0, int(std::min(m_left.size(), m_right.size())) - 1);
    const QImage *images[2] = {&m_left[size_t(index)], &m_right[size_t(index)]};
    for (int side = 0; side < 2; ++side) {
        const QRect panel(area.left() + side * (panelWidth + gap), area.top(), panelWidth, area.height());
        const QSize size = images[side]->size().scaled(panel.size(), Qt::KeepAspectRatio);
        const QRect target(panel.left() + (panel.width() - size.width()) / 2,
                           panel.top() + (panel.height() - size.height()) / 2, size.width(), size.height());
        painter.drawImage(target, *images[side]);
    }
}

} // namespace lipsync::studio
