#pragma once
// The studio's shared state, owned outside any widget (as Aegisub's agi::Context): the project
// document with its undo stack, the task runner, the model store, the one media player, and the
// sequence and frame being worked on. Panels are given the context, not the main window, so a
// panel can be built and driven without one; the main window is one view of the context.
#include "aam/AamSynthesizer.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <Eigen/Core>

#include <map>
#include <memory>
#include <string>
#include <vector>

class QUndoStack;

namespace lipsync {
class AamModel;
class DynamicModel;
class PostureTransfer;
class Task;
class TaskRunner;
struct SpeechToFaceResult;
}

namespace lipsync::studio {

class CommandRegistry;
class ModelStore;
class PlaybackController;
class ProjectDocument;
struct SequenceMedia;

class StudioContext : public QObject
{
    Q_OBJECT
public:
    explicit StudioContext(QObject *parent = nullptr);
    ~StudioContext() override;

    QUndoStack *undoStack() const { return m_undo; }
    ProjectDocument *document() const { return m_document; }
    TaskRunner *taskRunner() const { return m_runner; }
    // The AAMs and dynamic models the project's references point at (built, trained or loaded).
    ModelStore *modelStore() const { return m_models; }
    PlaybackController *playback() const { return m_playback; }
    // The studio's commands (menus, toolbars, shortcuts), each validating itself on this context.
    CommandRegistry *commands() const { return m_commands; }

    // The sequence worked on (-1: none), its media (null until loaded) and the frame shown.
    int currentSequence() const { return m_row; }
    int currentFrame() const { return m_frame; }
    std::shared_ptr<const SequenceMedia> media() const { return m_media; }

    // Makes sequence `row` the current one: its media are decoded in the background
    // (SequenceLoader), then the current frame becomes 0 and sequenceLoaded is emitted. A newer
    // request supersedes a pending one; a canceled or failed load leaves the current sequence as
    // it was (sequenceLoadEnded(false)). Out-of-range rows and the row already shown are ignored.
    void selectSequence(int row);
    // The row whose media are being decoded (-1: none); else the current one.
    int requestedSequence() const { return m_pendingRow >= 0 ? m_pendingRow : m_row; }
    // Sequence `row` with its loaded media becomes the current one (frame -1 until
    // setCurrentFrame), without decoding; announceSequenceLoaded() tells the views.
    void setCurrentSequence(int row, std::shared_ptr<const SequenceMedia> media);
    void announceSequenceLoaded();
    // No sequence (a new document): any pending load canceled, the player paused.
    void clearCurrentSequence();
    // Moves to `frame` of the current sequence (clamped to its frames) and announces it; nothing
    // without media or when it is the frame shown.
    void setCurrentFrame(int frame);
    // Shows the moment `seconds` of what the timeline shows: the new speech's frame at that time
    // (speechSeekRequested, for the Preview that plays it), else the current sequence's.
    void seek(double seconds);
    // Plays the current sequence from the current frame, or pauses the player.
    void togglePlayback();
    // The stretch of time selected in the timeline (Loop selection plays it); false if none.
    bool selection(double *start, double *end) const;
    void setSelection(double start, double end); // end <= start: none

    // Faces generated for new speech that the Preview shows instead of the current sequence
    // (null: none): the timeline shows its alignment and Export writes it.
    std::shared_ptr<const SpeechToFaceResult> shownSpeech() const { return m_speech; }
    QString shownSpeechTitle() const { return m_speechTitle; }
    void setShownSpeech(std::shared_ptr<const SpeechToFaceResult> speech, const QString &title);
    // How generated faces are drawn into the frames, in the preview and in exported videos
    // (View > Generated Face): the lower face with exemplar detail unless changed.
    const CompositeOptions &compositeOptions() const { return m_composite; }
    void setCompositeOptions(const CompositeOptions &options);
    // Whether generated lips close on /p b m/ (render/BilabialClosure) in the preview, exported
    // videos, study clips and the live view (View > Generated Face): on unless changed.
    bool closesLips() const { return m_closesLips; }
    void setClosesLips(bool close);
    // A passing message for the user (the window's status bar), shown for `milliseconds`.
    void showStatus(const QString &message, int milliseconds = 0);

    // Every trained dynamic model's trajectory for sequence `row`'s phone labels (ModelKinds
    // order), as the preview draws and videos export them: the lips closed on /p b m/ with `aam`
    // when closesLips(). A model whose dimension is not the AAM's (without one: the sequence's
    // features') is left out; none without phones. The one generation the plot and the preview
    // share.
    struct GeneratedTrajectory
    {
        QString kind;
        Eigen::MatrixXd features;
        // How the model's face keeps the posture of the frames it is drawn into (with an AAM).
        std::shared_ptr<const PostureTransfer> posture = nullptr;
    };
    std::vector<GeneratedTrajectory> generatedTrajectories(int row, const AamModel *aam) const;

signals:
    // selectSequence(row) started decoding `row` (the sequence list shows it selected).
    void sequenceRequested(int row);
    // The newest load started by selectSequence ended: its media reached the views (after
    // sequenceLoaded), or not (canceled or failed; a failure is also reported by
    // sequenceLoadFailed). A load superseded by a newer request ends without a word.
    void sequenceLoadEnded(bool loaded);
    void sequenceLoadFailed(const QString &mediaPath, const QString &problem);
    // The current sequence's media reached the views (sequenceId); empty when no sequence is
    // current any more (the one shown was removed).
    void sequenceLoaded(const QString &sequenceId);
    // The frame shown changed (also when a sequence's media arrives).
    void currentFrameChanged(int frame);
    void statusMessage(const QString &message, int milliseconds);
    void shownSpeechChanged();
    // seek() on the new speech: its frame at `seconds` (the Preview shows it).
    void speechSeekRequested(double seconds);
    void compositeOptionsChanged();
    void lipClosureChanged();

private:
    QUndoStack *m_undo;
    TaskRunner *m_runner;
    ProjectDocument *m_document;
    ModelStore *m_models;
    PlaybackController *m_playback;
    CommandRegistry *m_commands;
    void applyLoadedMedia(int row, std::shared_ptr<const SequenceMedia> media);
    void onLoadFinished(Task *task, const QString &mediaPath);

    std::shared_ptr<const SequenceMedia> m_media;
    int m_row = -1;
    int m_pendingRow = -1;
    QPointer<Task> m_loadTask;
    int m_frame = 0;
    double m_selectionStart = 0.0, m_selectionEnd = 0.0;
    std::shared_ptr<const SpeechToFaceResult> m_speech;
    QString m_speechTitle;
    CompositeOptions m_composite;
    bool m_closesLips = true;

    // Each model kind's posture transfer for the AAM it was made with: built once per trained
    // model and AAM (about a millisecond of generation per model), not at every listing.
    struct CachedPosture
    {
        std::weak_ptr<const DynamicModel> model;
        std::string aam; // AamModel::identifier
        std::shared_ptr<const PostureTransfer> posture;
    };
    mutable std::map<QString, CachedPosture> m_postures;
    std::shared_ptr<const PostureTransfer> postureFor(const QString &kind, const std::shared_ptr<const DynamicModel> &model,
                                                      const AamModel &aam) const;
};

} // namespace lipsync::studio
