#include "tasks/Task.h"

#include <QMetaObject>

namespace lipsync {

Task::Task(int id, QString title, QObject *parent)
    : QObject(parent), m_id(id), m_title(std::move(title))
{
    // Worker-thread reports are posted to this object's thread. Progress is posted only when the
    // shown value (per mille) changes, as Aegisub's progress dialog does, so a tight loop cannot
    // flood the event queue.
    m_feedback.onProgress = [this](double fraction) { setProgressFromWorker(fraction); };
    m_feedback.onStatus = [this](const std::string &status) {
        QMetaObject::invokeMethod(this, [this, s = QString::fromStdString(status)] {
            m_status = s;
            emit statusChanged(s);
        }, Qt::QueuedConnection);
    };
    m_feedback.onIteration = [this](int iteration, double objective) {
        QMetaObject::invokeMethod(this, [this, iteration, objective] {
            emit iterationReported(iteration, objective);
        }, Qt::QueuedConnection);
    };
}

void Task::setProgressFromWorker(double fraction)
{
    const int permille = int(fraction * 1000.0);
    if (permille == m_shownPermille)
        return;
    m_shownPermille = permille;
    QMetaObject::invokeMethod(this, [this, fraction] {
        m_progress = fraction;
        emit progressChanged(fraction);
    }, Qt::QueuedConnection);
}

void Task::cancel()
{
    m_feedback.cancel();
}

void Task::finish(State state, const QString &error)
{
    m_state = state;
    m_error = error;
    if (state == State::Finished) {
        m_progress = 1.0;
        emit progressChanged(1.0);
    }
    emit finished(state);
}

} // namespace lipsync
