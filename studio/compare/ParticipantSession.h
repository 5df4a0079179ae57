#pragma once
// One participant's run through the blind study: shows the ParticipantView full screen, prepares
// each trial's two videos off the GUI thread (TaskRunner; the next trial is prepared while the
// current one plays), and records every answer in the project document, which writes it to the
// project's study file at once. Participants are kept apart: each has an own session (own
// random order, own answers), and a session left early resumes at its first open trial.
#include "compare/StudyClipRenderer.h"
#include "tasks/Task.h"

#include <QObject>
#include <QPointer>

#include <memory>
#include <optional>

namespace lipsync::studio {

class ParticipantView;
class StudioContext;

class ParticipantSession : public QObject
{
    Q_OBJECT
public:
    // Session `session` of the context's study; the view goes full screen on `window`'s screen.
    ParticipantSession(StudioContext *context, QWidget *window, int session,
                       std::shared_ptr<StudyClipRenderer> renderer, QObject *parent = nullptr);
    ~ParticipantSession() override;

    // Shows the view (full screen unless `fullScreen` is false) at the first open trial.
    void start(bool fullScreen = true);
    ParticipantView *view() const;
    int session() const { return m_session; }
    int currentTrial() const { return m_trial; }

signals:
    void finished();

private:
    struct Prepared
    {
        int trial = -1;
        std::shared_ptr<std::pair<StudyClip, StudyClip>> clips;
        QPointer<Task> task;
    };
    const StudySession &studySession() const;
    void showTrial(int trial);
    void prepare(int trial);
    void onAnswered(StudyChoice choice, double seconds);
    void leave();

    StudioContext *m_context;
    QWidget *m_window;
    int m_session;
    std::shared_ptr<StudyClipRenderer> m_renderer;
    QPointer<ParticipantView> m_view;
    int m_trial = -1;
    Prepared m_current;
    Prepared m_next;
};

} // namespace lipsync::studio
