#pragma once
// Timeline ▸ Model ▸ Train the Speaker's Own Aligner…: an aligner model trained on the project's
// own transcribed speech (flat start, as `lipsync aligner train`), its word-boundary correction
// learned from the project's word timings (`lipsync aligner calibrate`), written into the project's
// models folder and made the project's aligner (one undo step). From then on every alignment of
// the project uses it (align/ProjectAligner: the speaker's own model wins).
//
// It needs kMinimumSpeechSeconds of words. On GRID s1 (bench BM_GridAlignerLearningCurve, 5 folds)
// an own aligner trained on 2.0 minutes of words places 79.0 % of the held-out word boundaries
// within 40 ms, on 3.0 minutes 87.8 %, on 3.9 minutes 92.4 %; CMU Sphinx adapted to each clip, the
// default for a new speaker, places 85.7 %. Adapting the shipped GRID model to another speaker is
// no substitute: on mfa-tests it reaches 47.7 % within 25 ms against CMU Sphinx adapted's 80.7 %.
//
// Before the final model, one trained on four fifths of the sequences is scored on the rest
// against the project's timings: the figure the studio shows. Runs in the background with progress
// and cancel; a canceled or failed training leaves the project as it was.
#include <QObject>
#include <QPointer>

class QAction;
class QWidget;

namespace lipsync {
class Task;
class Project;
}

namespace lipsync::studio {

class StudioContext;

class SpeakerAlignerTrainer : public QObject
{
    Q_OBJECT
public:
    // Three minutes of words: where an own aligner passes the generic one on GRID s1 (above).
    static constexpr double kMinimumSpeechSeconds = 180.0;

    SpeakerAlignerTrainer(StudioContext *context, QWidget *window);

    QAction *action() const { return m_action; }
    // Starts the training; null (the reason reported) when the project cannot take it.
    Task *start();
    // " Its N min of words can train …" when the open project has enough aligned, transcribed
    // speech and no aligner of its own (the timeline's hint on opening), else empty.
    QString offer() const;
    // The seconds of words (the word tiers' spoken intervals) of `project`'s transcribed sequences.
    static double speechSeconds(const Project &project);
    // Below this many seconds of words a training is refused (tests train on the demo's 15 s).
    void setMinimumSpeechSeconds(double seconds) { m_minimumSeconds = seconds; }

signals:
    // The project now names this aligner model (its path relative to the project).
    void trained(const QString &file);

private:
    bool isTraining() const;

    StudioContext *m_context;
    QWidget *m_window;
    QAction *m_action;
    QPointer<Task> m_task;
    double m_minimumSeconds = kMinimumSpeechSeconds;
};

} // namespace lipsync::studio
