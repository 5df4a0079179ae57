#pragma once
// The compact task indicator in the status bar: what runs now, its progress, a cancel button,
// and a button that opens the full task list.
#include "tasks/Task.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace lipsync {
class TaskRunner;
}

namespace lipsync::studio {

class TaskListModel;
class TaskListPopup;

class TaskStatusWidget : public QWidget
{
    Q_OBJECT
public:
    explicit TaskStatusWidget(TaskRunner *runner, QWidget *parent = nullptr);

    TaskListModel *model() const { return m_model; }
    // Cancels the task shown in the status bar (the newest running one).
    QToolButton *cancelButton() const { return m_cancel; }
    QToolButton *listButton() const { return m_listButton; }
    TaskListPopup *popup() const { return m_popup; }
    Task *shownTask() const { return m_shown; }

public slots:
    void showTaskList();

private:
    void refresh();

    TaskRunner *m_runner;
    TaskListModel *m_model;
    TaskListPopup *m_popup;
    QPointer<Task> m_shown;
    QLabel *m_label;
    QProgressBar *m_progress;
    QToolButton *m_cancel;
    QToolButton *m_listButton;
};

} // namespace lipsync::studio
