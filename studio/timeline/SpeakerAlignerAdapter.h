#pragma once
// Timeline ▸ Model ▸ Make the Speaker's Own Aligner…: the shipped aligner model adapted to the
// project's speaker from the project's own transcribed sequences (SpeakerAdaptation: MLLR per
// regression class + MAP of the means, as `lipsync aligner adapt`), written into the project's
// models folder and added to the project as its aligner (one undo step). From then on every
// alignment of the project uses it (align/ProjectAligner: the speaker's own model wins).
// Runs in the background with progress and cancel; a canceled or failed adaptation leaves the
// project as it was.
#include <QObject>
#include <QPointer>

class QAction;
class QWidget;

namespace lipsync {
class Task;
}

namespace lipsync::studio {

class StudioContext;

class SpeakerAlignerAdapter : public QObject
{
    Q_OBJECT
public:
    // Transcribed speech below this is refused: MLLR needs tens of seconds [choice].
    static constexpr double kMinimumSeconds = 20.0;

    SpeakerAlignerAdapter(StudioContext *context, QWidget *window);

    QAction *action() const { return m_action; }
    // Starts the adaptation; null (the reason reported) when the project cannot take it.
    Task *start();
    // " Its N s of transcribed speech can make …" when the open project has enough transcribed
    // speech and no aligner of its own (the timeline's hint on opening), else empty.
    QString offer() const;

signals:
    // The project now names this aligner model (its path relative to the project).
    void adapted(const QString &file);

private:
    void updateAction();

    StudioContext *m_context;
    QWidget *m_window;
    QAction *m_action;
    QPointer<Task> m_task;
};

} // namespace lipsync::studio
