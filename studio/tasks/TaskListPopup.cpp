#include "tasks/TaskListPopup.h"

#include "tasks/TaskListModel.h"
#include "tasks/TaskRowWidget.h"
#include "tasks/TaskRunner.h"

#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QVBoxLayout>

namespace lipsync::studio {

TaskListPopup::TaskListPopup(TaskListModel *model, TaskRunner *runner, QWidget *parent)
    : QFrame(parent, Qt::Popup), m_model(model)
{
    setFrameShape(QFrame::StyledPanel);
    setObjectName(QStringLiteral("taskListPopup"));
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(6, 6, 6, 6);

    auto *header = new QHBoxLayout;
    auto *title = new QLabel(tr("Background tasks"), this);
    QFont bold = title->font();
    bold.setBold(true);
    title->setFont(bold);
    auto *clear = new QPushButton(tr("Clear finished"), this);
    header->addWidget(title);
    header->addStretch();
    header->addWidget(clear);
    layout->addLayout(header);

    auto *scroll = new QScrollArea(this);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    auto *content = new QWidget(scroll);
    m_rows = new QVBoxLayout(content);
    m_rows->setContentsMargins(0, 0, 0, 0);
    m_rows->setSpacing(0);
    scroll->setWidget(content);
    layout->addWidget(scroll);
    resize(380, 260);

    connect(clear, &QPushButton::clicked, runner, &TaskRunner::clearFinished);
    connect(model, &QAbstractItemModel::rowsInserted, this, &TaskListPopup::rebuild);
    connect(model, &QAbstractItemModel::modelReset, this, &TaskListPopup::rebuild);
    rebuild();
}

void TaskListPopup::showAbove(const QPoint &anchor)
{
    move(anchor - QPoint(width(), height()));
    show();
}

QList<TaskRowWidget *> TaskListPopup::rows() const
{
    QList<TaskRowWidget *> result;
    for (int i = 0; i < m_rows->count(); ++i)
        if (auto *row = qobject_cast<TaskRowWidget *>(m_rows->itemAt(i)->widget()))
            result.append(row);
    return result;
}

void TaskListPopup::rebuild()
{
    while (QLayoutItem *item = m_rows->takeAt(0)) {
        delete item->widget();
        delete item;
    }
    for (int row = 0; row < m_model->rowCount(); ++row)
        if (Task *task = m_model->task(row))
            m_rows->addWidget(new TaskRowWidget(task, this));
    if (m_model->rowCount() == 0)
        m_rows->addWidget(new QLabel(tr("No background tasks."), this));
    m_rows->addStretch();
}

} // namespace lipsync::studio
