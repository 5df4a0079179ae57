#pragma once
// The expanded task list: a popup above the status bar with one row per task (newest first).
#include <QFrame>

class QVBoxLayout;

namespace lipsync {
class TaskRunner;
}

namespace lipsync::studio {

class TaskListModel;
class TaskRowWidget;

class TaskListPopup : public QFrame
{
    Q_OBJECT
public:
    TaskListPopup(TaskListModel *model, TaskRunner *runner, QWidget *parent = nullptr);

    // Shows the popup with its bottom-right corner at `anchor` (global coordinates).
    void showAbove(const QPoint &anchor);
    QList<TaskRowWidget *> rows() const;

private:
    void rebuild();

    TaskListModel *m_model;
    QVBoxLayout *m_rows;
};

} // namespace lipsync::studio
