#pragma once
// The faces workflow of the main window: the landmark editor on the Annotate tab (the FrameView's
// edits become undoable document edits), and the Faces menu — automatic landmarks (Ctrl+D), copy
// the previous frame's points (C), onion skin (O), next unlabelled frame (N), next worst-fitted
// frame (W), Pick Frames to Label (diverse frames of all clips with automatic points, core's
// FramePicking) and their review, most doubtful first (Shift+W), Build AAM, Track Sequence /
// Track All, and the modes-of-variation view. Detection,
// building and tracking run as TaskRunner tasks: the worker never touches the document, the commit
// pushes one undo command.
#include "aam/AamModel.h"
#include "aam/FramePicking.h"

#include <QCoreApplication>
#include <QHash>
#include <QObject>
#include <QPointer>

#include <map>
#include <memory>
#include <vector>

class QAction;
class QMenu;

namespace lipsync {
class Task;
}

namespace lipsync::studio {

class FrameView;
class ModesView;
class StudioContext;

class FacesController : public QObject
{
    Q_OBJECT
public:
    // The Faces menu's actions on the context's document and current frame, drawn in `view`;
    // `window` owns the actions (their shortcuts) and parents the dialogs.
    FacesController(StudioContext *context, FrameView *view, QWidget *window);
    ~FacesController() override;

    QMenu *menu() const { return m_menu; }
    QAction *detectAction() const { return m_detect; }
    QAction *copyPreviousAction() const { return m_copyPrevious; }
    QAction *onionSkinAction() const { return m_onionSkin; }
    QAction *nextUnlabelledAction() const { return m_nextUnlabelled; }
    QAction *nextWorstAction() const { return m_nextWorst; }
    QAction *pickFramesAction() const { return m_pickFrames; }
    QAction *nextPickedAction() const { return m_nextPicked; }
    QAction *buildAamAction() const { return m_buildAam; }
    QAction *trackSequenceAction() const { return m_trackSequence; }
    QAction *trackAllAction() const { return m_trackAll; }
    QAction *modesAction() const { return m_modes; }

    // The AAM in use (the ModelStore's for the project's latest reference), or null.
    std::shared_ptr<const AamModel> model() const;
    // The AAM in use, loaded if need be; a file that does not load is reported (file and reason)
    // and false returned.
    bool ensureModel();

    // The actions, callable directly (tests). Each returns the task started, or null.
    Task *detectLandmarks();
    // `count` diverse frames of the project's clips (every `step`-th frame a candidate) get
    // automatic points, one undo step; the review queue then holds them, the most doubtful first.
    Task *pickFramesToLabel(int count, int step = FramePickingOptions{}.step);
    Task *buildAam();
    Task *trackSequences(const QList<int> &rows);
    bool copyPreviousFrame();
    void nextUnlabelledFrame();
    void nextWorstFrame();
    // The next frame of the review queue (another sequence is loaded first); false when empty.
    bool nextPickedFrame();
    // A picked frame to review: where it is and how doubtful its automatic points are.
    struct ReviewItem
    {
        std::string sequenceId;
        int frame = 0;
        double disagreement = -1.0; // NME a held-out AAM moves the points by (-1: not measured)
    };
    // The picks, the most doubtful first.
    const std::vector<ReviewItem> &reviewQueue() const { return m_review; }
    // "Picked frame k of n …" for the frame Shift+W went to last (empty before the first).
    QString reviewStatus() const;
    void showModes();

private:
    void onDocumentReset();
    void onSequenceChanged(int row);
    // The project's models changed (Build AAM, its undo and redo): the AAM in use follows the
    // project's active reference everywhere (tracking, detection, Modes of Variation).
    void onModelsChanged();
    void refreshFrame();
    // The Faces menu's actions as commands, each with when it can act (CommandRegistry::adopt).
    void adoptCommands();
    void updateActions();
    void reportFailure(Task *task, const QString &what);

    StudioContext *m_context;
    FrameView *m_view;
    QWidget *m_parent;
    QMenu *m_menu = nullptr;
    QAction *m_detect = nullptr;
    QAction *m_copyPrevious = nullptr;
    QAction *m_onionSkin = nullptr;
    QAction *m_nextUnlabelled = nullptr;
    QAction *m_nextWorst = nullptr;
    QAction *m_pickFrames = nullptr;
    QAction *m_nextPicked = nullptr;
    QAction *m_buildAam = nullptr;
    QAction *m_trackSequence = nullptr;
    QAction *m_trackAll = nullptr;
    QAction *m_modes = nullptr;
    QPointer<ModesView> m_modesView;

    std::string m_aamFile; // the reference file of the AAM in use, as last seen
    int m_worstRank = -1; // where W is in the current sequence's worst-fit queue
    std::vector<ReviewItem> m_review; // picked frames, most doubtful first
    int m_reviewIndex = -1;                            // where Shift+W is in it
    int m_pendingFrame = -1; // the frame to show once the sequence Shift+W switched to has loaded
};

} // namespace lipsync::studio
