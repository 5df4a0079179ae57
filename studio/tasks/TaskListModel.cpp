#include "tasks/TaskListModel.h"

#include "tasks/TaskRunner.h"

namespace lipsync::studio {

TaskListModel::TaskListModel(TaskRunner *runner, QObject *parent)
    : QAbstractListModel(parent), m_runner(runner)
{
    connect(runner, &TaskRunner::taskStarted, this, &TaskListModel::addTask);
    connect(runner, &TaskRunner::taskFinished, this, &TaskListModel::taskChanged);
    connect(runner, &TaskRunner::tasksCleared, this, &TaskListModel::resync);
    resync();
    for (const auto &t : std::as_const(m_tasks))
        watch(t);
}

int TaskListModel::rowCount(const QModelIndex &parent) const
{
    return parent.isValid() ? 0 : int(m_tasks.size());
}

QVariant TaskListModel::data(const QModelIndex &index, int role) const
{
    Task *t = index.isValid() ? task(index.row()) : nullptr;
    if (!t)
        return {};
    switch (role) {
    case Qt::DisplayRole: return t->title();
    case Qt::ToolTipRole:
        return t->errorMessage().isEmpty() ? t->status() : t->errorMessage();
    case TaskRole: return QVariant::fromValue<QObject *>(t);
    case ProgressRole: return t->progress();
    case StateRole: return int(t->state());
    case StatusRole: return t->status();
    default: return {};
    }
}

QHash<int, QByteArray> TaskListModel::roleNames() const
{
    auto names = QAbstractListModel::roleNames();
    names[TaskRole] = "task";
    names[ProgressRole] = "progress";
    names[StateRole] = "state";
    names[StatusRole] = "status";
    return names;
}

Task *TaskListModel::task(int row) const
{
    return row >= 0 && row < m_tasks.size() ? m_tasks[row].data() : nullptr;
}

int TaskListModel::rowOf(const Task *task) const
{
    for (int i = 0; i < m_tasks.size(); ++i)
        if (m_tasks[i] == task)
            return i;
    return -1;
}

int TaskListModel::runningCount() const
{
    int n = 0;
    for (const auto &t : m_tasks)
        n += t && t->isRunning() ? 1 : 0;
    return n;
}

QString TaskListModel::stateText(int state)
{
    switch (Task::State(state)) {
    case Task::State::Running: return tr("Running");
    case Task::State::Finished: return tr("Finished");
    case Task::State::Canceled: return tr("Canceled");
    case Task::State::Failed: return tr("Failed");
    }
    return {};
}

void TaskListModel::addTask(Task *task)
{
    beginInsertRows({}, 0, 0);
    m_tasks.prepend(task);
    endInsertRows();
    watch(task);
}

void TaskListModel::watch(Task *task)
{
    connect(task, &Task::progressChanged, this, [this, task] { taskChanged(task); });
    connect(task, &Task::statusChanged, this, [this, task] { taskChanged(task); });
}

void TaskListModel::taskChanged(Task *task)
{
    const int row = rowOf(task);
    if (row >= 0)
        emit dataChanged(index(row), index(row));
}

void TaskListModel::resync()
{
    beginResetModel();
    m_tasks.clear();
    if (m_runner) {
        const QList<Task *> tasks = m_runner->tasks();
        for (auto it = tasks.rbegin(); it != tasks.rend(); ++it)
            m_tasks.append(*it);
    }
    endResetModel();
}

} // namespace lipsync::studio
