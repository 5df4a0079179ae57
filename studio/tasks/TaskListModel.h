#pragma once
// The runner's tasks as a list model (newest first) for the status-bar task list. Rows follow
// the runner: a task appears when started and stays, with its final state, until cleared.
#include "tasks/Task.h"

#include <QAbstractListModel>
#include <QList>
#include <QPointer>

namespace lipsync {
class TaskRunner;
}

namespace lipsync::studio {

class TaskListModel : public QAbstractListModel
{
    Q_OBJECT
public:
    enum Role {
        TaskRole = Qt::UserRole + 1, // lipsync::Task* (as QObject*)
        ProgressRole,                // double in [0, 1]
        StateRole,                   // int(lipsync::Task::State)
        StatusRole,                  // QString
    };

    explicit TaskListModel(TaskRunner *runner, QObject *parent = nullptr);

    int rowCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QHash<int, QByteArray> roleNames() const override;

    Task *task(int row) const;
    int rowOf(const Task *task) const;
    int runningCount() const;

    // A translated word for a task state ("Running", "Canceled"...).
    static QString stateText(int state);

private:
    void addTask(Task *task);
    void watch(Task *task);
    void taskChanged(Task *task);
    void resync();

    QPointer<TaskRunner> m_runner;
    QList<QPointer<Task>> m_tasks;
};

} // namespace lipsync::studio
