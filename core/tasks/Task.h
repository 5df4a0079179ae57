#pragma once
// One background job as the GUI sees it: title, progress, state, and cancel.
// Signals are emitted on the thread that owns the Task (the TaskRunner's, i.e. the GUI thread).
#include "tasks/Feedback.h"

#include <QObject>
#include <QString>

#include <functional>

namespace lipsync {

class Task : public QObject
{
    Q_OBJECT
public:
    enum class State { Running, Finished, Canceled, Failed };
    Q_ENUM(State)

    Task(int id, QString title, QObject *parent = nullptr);

    int id() const { return m_id; }
    QString title() const { return m_title; }
    State state() const { return m_state; }
    double progress() const { return m_progress; }
    QString status() const { return m_status; }
    QString errorMessage() const { return m_error; }
    bool isRunning() const { return m_state == State::Running; }

    Feedback &feedback() { return m_feedback; }

public slots:
    void cancel();

signals:
    void progressChanged(double fraction);
    void statusChanged(const QString &status);
    void iterationReported(int iteration, double objective);
    // Emitted once, after the result has been applied (Finished) or dropped (Canceled, Failed).
    void finished(lipsync::Task::State state);

private:
    friend class TaskRunner;
    void setProgressFromWorker(double fraction);
    void finish(State state, const QString &error = {});

    int m_id;
    QString m_title;
    State m_state = State::Running;
    double m_progress = 0.0;
    int m_shownPermille = -1;
    QString m_status;
    QString m_error;
    Feedback m_feedback;
};

} // namespace lipsync
