#include "compare/ParticipantSession.h"

#include "compare/ParticipantView.h"
#include "context/ErrorReporter.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "tasks/Feedback.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QScreen>

namespace lipsync::studio {

ParticipantSession::ParticipantSession(StudioContext *context, QWidget *window, int session,
                                       std::shared_ptr<StudyClipRenderer> renderer, QObject *parent)
    : QObject(parent), m_context(context), m_window(window), m_session(session), m_renderer(std::move(renderer)),
      m_view(new ParticipantView)
{
    m_view->setAttribute(Qt::WA_DeleteOnClose);
    connect(m_view, &ParticipantView::answered, this, &ParticipantSession::onAnswered);
    connect(m_view, &ParticipantView::leaveRequested, this, &ParticipantSession::leave);
}

ParticipantSession::~ParticipantSession()
{
    for (Prepared *p : {&m_current, &m_next})
        if (p->task)
            p->task->cancel();
    if (m_view)
        m_view->close();
}

ParticipantView *ParticipantSession::view() const
{
    return m_view;
}

const StudySession &ParticipantSession::studySession() const
{
    return m_context->document()->project().study->sessions().at(std::size_t(m_session));
}

void ParticipantSession::start(bool fullScreen)
{
    // On the main window's screen; the geometry is set as well since without a window manager
    // (kiosk set-ups, Xvfb) the full-screen state alone does not resize the window.
    QScreen *screen = m_window->screen();
    if (fullScreen) {
        m_view->setGeometry(screen->geometry());
        m_view->showFullScreen();
    } else {
        m_view->resize(screen->availableGeometry().size() * 3 / 4);
        m_view->show();
    }
    m_view->activateWindow();
    m_view->setFocus();
    showTrial(studySession().nextTrial());
}

void ParticipantSession::prepare(int trial)
{
    Prepared &slot = trial == m_trial ? m_current : m_next;
    slot = Prepared{trial, nullptr, nullptr};
    const StudySession &s = studySession();
    const ForcedChoiceStudy &study = *m_context->document()->project().study;
    const StudyTrial &t = s.trials.at(std::size_t(trial));
    const std::string utterance = t.utterance;
    const std::string left = study.methods().at(std::size_t(t.left));
    const std::string right = study.methods().at(std::size_t(t.right));
    std::shared_ptr<StudyClipRenderer> renderer = m_renderer;
    // Titles stay neutral: the task list is visible to the experimenter, not the participant.
    slot.task = m_context->taskRunner()->start(tr("Preparing study trial %1").arg(trial + 1), [=, this](Feedback &feedback) {
        auto clips = std::make_shared<std::pair<StudyClip, StudyClip>>();
        Feedback first(feedback, 0.0, 0.5);
        clips->first = renderer->render(utterance, left, first);
        Feedback second(feedback, 0.5, 1.0);
        clips->second = renderer->render(utterance, right, second);
        return TaskRunner::Commit([this, trial, clips] {
            Prepared &target = m_current.trial == trial ? m_current : m_next;
            if (target.trial != trial)
                return;
            target.clips = clips;
            if (trial == m_trial && m_view)
                showTrial(trial);
        });
    });
    connect(slot.task, &Task::finished, this, [this, trial, task = slot.task](Task::State state) {
        if (state == Task::State::Failed && trial == m_trial && m_view)
            m_view->showMessage(tr("This trial cannot be shown: %1").arg(task ? task->errorMessage() : QString()));
    });
}

void ParticipantSession::showTrial(int trial)
{
    const int count = int(studySession().trials.size());
    if (trial < 0) {
        m_trial = -1;
        m_view->showFinished();
        return;
    }
    if (trial != m_trial) {
        m_trial = trial;
        if (m_next.trial == trial)
            std::swap(m_current, m_next);
        if (m_current.trial != trial)
            prepare(trial);
    }
    if (!m_current.clips) {
        m_view->showPreparing(trial, count);
        return;
    }
    m_view->showTrial(trial, count, m_current.clips->first, m_current.clips->second);
    // The next open trial is prepared while this one plays.
    int next = -1;
    for (int i = trial + 1; i < count && next < 0; ++i)
        if (studySession().trials[std::size_t(i)].choice == StudyChoice::Unanswered)
            next = i;
    if (next >= 0 && m_next.trial != next)
        prepare(next);
}

void ParticipantSession::onAnswered(StudyChoice choice, double seconds)
{
    try {
        m_context->document()->recordStudyAnswer(m_session, m_trial, choice, seconds);
    } catch (const Error &e) {
        ErrorReporter::report(m_view, tr("Record the answer"), e);
        m_view->showMessage(tr("The answer could not be saved. Please call the experimenter."));
        return;
    }
    m_current = Prepared{};
    showTrial(studySession().nextTrial());
}

void ParticipantSession::leave()
{
    for (Prepared *p : {&m_current, &m_next})
        if (p->task)
            p->task->cancel();
    if (m_view)
        m_view->close();
    emit finished();
}

} // namespace lipsync::studio
