#include "preview/PreviewPanel.h"

#include "annotate/FrameView.h"
#include "app/StudioActions.h"

#include <QLabel>
#include <QToolButton>
#include <QVBoxLayout>

namespace lipsync::studio {

PreviewPanel::PreviewPanel(const StudioActions &actions, QWidget *parent)
    : QWidget(parent), m_view(new FrameView(this)), m_caption(new QLabel(this))
{
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    auto *header = new QHBoxLayout;
    header->setContentsMargins(8, 4, 8, 0);
    header->setSpacing(16);
    auto *title = new QLabel(tr("Recorded video"), this);
    QFont bold = title->font();
    bold.setBold(true);
    title->setFont(bold);
    auto *play = new QToolButton(this);
    play->setDefaultAction(actions.playPause);
    play->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    header->addWidget(title);
    header->addWidget(m_caption, 1);
    header->addWidget(play);
    layout->addLayout(header);
    layout->addWidget(m_view, 1);
}

void PreviewPanel::setFrame(const QImage &image, const QString &caption)
{
    m_view->setImage(image);
    m_caption->setText(caption);
}

void PreviewPanel::setPlaceholderText(const QString &text)
{
    m_view->setPlaceholderText(text);
}

} // namespace lipsync::studio
