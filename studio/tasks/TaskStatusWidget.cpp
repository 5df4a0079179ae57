#include "tasks/TaskStatusWidget.h"

#include "tasks/Task.h"
#include "tasks/TaskListModel.h"
#include "tasks/TaskListPopup.h"
#include "tasks/TaskRunner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QStyle>
#include <QToolButton>

namespace lipsync::studio {

TaskStatusWidget::TaskStatusWidget(TaskRunner *runner, QWidget *parent)
    : QWidget(parent), m_runner(runner), m_model(new TaskListModel(runner, this)),
      m_label(new QLabel(this)), m_progress(new QProgressBar(this)), m_cancel(new QToolButton(this)),
      m_listButton(new QToolButton(this))
{
    m_popup = new TaskListPopup(m_model, runner, this);
    auto *layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(4);
    m_label->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
    m_progress->setRange(0, 1000);
    m_progress->setFixedWidth(120);
    m_progress->setMaximumHeight(14);
    m_progress->setTextVisible(false);
    m_cancel->setObjectName(QStringLiteral("cancelButton"));
    m_cancel->setIcon(style()->standardIcon(QStyle::SP_DialogCancelButton));
    m_cancel->setToolTip(tr("Cancel this task"));
    m_cancel->setAutoRaise(true);
    m_listButton->setObjectName(QStringLiteral("taskListButton"));
    m_listButton->setArrowType(Qt::UpArrow);
    m_listButton->setToolTip(tr("Show all background tasks"));
    m_listButton->setAutoRaise(true);
    layout->addWidget(m_label);
    layout->addWidget(m_progress);
    layout->addWidget(m_cancel);
    layout->addWidget(m_listButton);

    connect(m_cancel, &QToolButton::clicked, this, [this] {
        if (m_shown)
            m_shown->cancel();
        refresh();
    });
    connect(m_listButton, &QToolButton::clicked, this, &TaskStatusWidget::showTaskList);
    connect(m_model, &QAbstractItemModel::rowsInserted, this, &TaskStatusWidget::refresh);
    connect(m_model, &QAbstractItemModel::dataChanged, this, &TaskStatusWidget::refresh);
    connect(m_model, &QAbstractItemModel::modelReset, this, &TaskStatusWidget::refresh);
    refresh();
}

void TaskStatusWidget::showTaskList()
{
    m_popup->showAbove(mapToGlobal(QPoint(width(), 0)));
}

void TaskStatusWidget::refresh()
{
    // Show the newest running task; the list button gives access to all of them.
    m_shown = nullptr;
    for (int row = 0; row < m_model->rowCount() && !m_shown; ++row) {
        Task *t = m_model->task(row);
        if (t && t->isRunning())
            m_shown = t;
    }
    const int running = m_model->runningCount();
    if (m_shown) {
        const QString more = running > 1 ? tr(" (+%n more)", "", running - 1) : QString();
        m_label->setText(m_shown->title() + more);
        m_progress->setValue(int(m_shown->progress() * 1000.0));
    } else {
        m_label->setText(m_model->rowCount() > 0 ? tr("All tasks done") : tr("No tasks"));
    }
    m_progress->setVisible(m_shown);
    m_cancel->setVisible(m_shown);
    m_cancel->setEnabled(m_shown && !m_shown->feedback().isCanceled());
}

} // namespace lipsync::studio
