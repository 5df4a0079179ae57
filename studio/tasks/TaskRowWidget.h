#pragma once
// One task in the task list: title, state or status, a progress bar and a cancel button.
#include "tasks/Task.h"

#include <QPointer>
#include <QWidget>

class QLabel;
class QProgressBar;
class QToolButton;

namespace lipsync::studio {

class TaskRowWidget : public QWidget
{
    Q_OBJECT
public:
    explicit TaskRowWidget(Task *task, QWidget *parent = nullptr);

    Task *task() const { return m_task; }
    QToolButton *cancelButton() const { return m_cancel; }

private:
    void refresh();

    QPointer<Task> m_task;
    QLabel *m_title;
    QLabel *m_state;
    QProgressBar *m_progress;
    QToolButton *m_cancel;
};

} // namespace lipsync::studio
