#include "tasks/TaskRowWidget.h"

#include "tasks/Task.h"
#include "tasks/TaskListModel.h"

#include <QGridLayout>
#include <QLabel>
#include <QProgressBar>
#include <QStyle>
#include <QToolButton>

namespace lipsync::studio {

TaskRowWidget::TaskRowWidget(Task *task, QWidget *parent)
    : QWidget(parent), m_task(task), m_title(new QLabel(this)), m_state(new QLabel(this)),
      m_progress(new QProgressBar(this)), m_cancel(new QToolButton(this))
{
    auto *layout = new QGridLayout(this);
    layout->setContentsMargins(6, 4, 6, 4);
    layout->setHorizontalSpacing(8);
    layout->setVerticalSpacing(2);
    m_title->setText(task->title());
    QFont bold = m_title->font();
    bold.setBold(true);
    m_title->setFont(bold);
    m_state->setForegroundRole(QPalette::PlaceholderText);
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_progress->setFixedHeight(10);
    m_cancel->setObjectName(QStringLiteral("cancelButton"));
    m_cancel->setIcon(style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancel->setToolTip(tr("Cancel this task"));
    m_cancel->setAutoRaise(true);
    QSizePolicy keepSpace = m_cancel->sizePolicy();
    keepSpace.setRetainSizeWhenHidden(true);
    m_cancel->setSizePolicy(keepSpace);
    layout->addWidget(m_title, 0, 0);
    layout->addWidget(m_state, 0, 1, Qt::AlignRight);
    layout->addWidget(m_progress, 1, 0, 1, 2);
    layout->addWidget(m_cancel, 0, 2, 2, 1, Qt::AlignVCenter);
    layout->setColumnStretch(0, 1);

    connect(m_cancel, &QToolButton::clicked, task, &Task::cancel);
    connect(m_cancel, &QToolButton::clicked, this, &TaskRowWidget::refresh);
    connect(task, &Task::progressChanged, this, &TaskRowWidget::refresh);
    connect(task, &Task::statusChanged, this, &TaskRowWidget::refresh);
    connect(task, &Task::finished, this, &TaskRowWidget::refresh);
    refresh();
}

void TaskRowWidget::refresh()
{
    if (!m_task)
        return;
    m_progress->setValue(int(m_task->progress() * 1000.0));
    QString state;
    if (m_task->isRunning())
        state = m_task->feedback().isCanceled() ? tr("Canceling…") : m_task->status();
    else
        state = TaskListModel::stateText(int(m_task->state()));
    if (m_task->isRunning() && state.isEmpty())
        state = tr("%1 %").arg(int(m_task->progress() * 100.0));
    m_state->setText(state);
    setToolTip(m_task->errorMessage());
    m_cancel->setEnabled(m_task->isRunning() && !m_task->feedback().isCanceled());
    // A finished task has nothing to cancel; keep the space so the rows stay aligned.
    m_cancel->setVisible(m_task->isRunning());
}

} // namespace lipsync::studio
