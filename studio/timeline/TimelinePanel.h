#pragma once
// The Timeline dock: the waveform view with its tiers, the speech workflow's buttons (align the
// sequence or all of them, re-align the selection, play), a scroll bar and zoom buttons.
//
// It is also the timing controller of the view: it turns the view's gestures (boundary drags,
// relabel requests) and its own edit actions (split S, merge M, relabel Enter, insert silence I
// or breath B) into tier edits (TierEdits) requested from the ProjectDocument, so every edit is
// one step on the main window's undo stack — a whole boundary drag included. Alignments use the
// project's pronunciations, edited in the Pronunciations dialog it opens, which also lists the
// words espeak-ng had to guess. It follows the
// current sequence of the main window and redraws the tiers whenever the document changes them.
#include "document/TierEdits.h"
#include "tasks/Task.h"

#include <QPointer>
#include <QWidget>

#include <map>
#include <memory>
#include <string>
#include <vector>

class QAction;
class QHBoxLayout;
class QLabel;
class QMenu;
class QScrollBar;
class QToolButton;

namespace lipsync {
struct SpeechToFaceResult;
}

namespace lipsync::studio {

class StudioContext;
class ProjectDocument;
class PlaybackController;
class PronunciationsDialog;
class SpeakerAlignerTrainer;
class IntervalLabelEditor;
class WaveformView;
struct AlignJob;
struct AlignOutcome;

class TimelinePanel : public QWidget
{
    Q_OBJECT
public:
    explicit TimelinePanel(QWidget *parent = nullptr);
    WaveformView *waveform() const { return m_waveform; }
    // The main window's player, which plays the selection, a word or everything (null until attached).
    PlaybackController *player() const { return m_player; }

    // Follows the context's document, current sequence, player and task runner. Until then the
    // panel only shows what it is given (setWords etc. on the view).
    void attach(StudioContext *context);
    int row() const { return m_row; }

    // Shows the alignment of speech generated in the Preview — its sound, words, phones and frame
    // labels, read-only under a banner that says so — until the sequence is shown again; null
    // returns to the current sequence.
    void showGeneratedSpeech(std::shared_ptr<const SpeechToFaceResult> speech);
    bool isShowingGeneratedSpeech() const { return m_speech != nullptr; }

    QAction *alignAction() const { return m_align; }
    QAction *alignAllAction() const { return m_alignAll; }
    QAction *realignAction() const { return m_realign; }
    QAction *adaptToSpeakerAction() const { return m_adaptAction; }
    // The aligner model choice (exclusive, remembered in the settings): the built-in model or
    // CMU Sphinx's generic US-English model.
    QAction *builtInAlignerAction() const { return m_builtInAlignerAction; }
    QAction *sphinxAlignerAction() const { return m_sphinxAlignerAction; }
    // Model ▸ Make the Speaker's Own Aligner… (null before attach()).
    SpeakerAlignerTrainer *speakerAligner() const { return m_speakerAligner; }
    QAction *splitAction() const { return m_split; }
    QAction *mergeAction() const { return m_merge; }
    QAction *relabelAction() const { return m_relabel; }
    QAction *insertSilenceAction() const { return m_insertSilence; }
    QAction *insertBreathAction() const { return m_insertBreath; }
    QAction *playSelectionAction() const { return m_playSelection; }
    QAction *playWordAction() const { return m_playWord; }
    QAction *playAllAction() const { return m_playAll; }
    QAction *pronunciationsAction() const { return m_pronunciationsAction; }
    // Checkable: the spectrogram lane under the waveform (for the View menu; remembered in
    // QSettings as timeline/spectrogram).
    QAction *spectrogramAction() const { return m_spectrogramAction; }
    // The Pronunciations dialog once opened (null before).
    PronunciationsDialog *pronunciationsDialog() const;
    // Words espeak-ng pronounced in the alignments so far, with its guesses.
    const std::map<std::string, std::string> &guessedPronunciations() const { return m_guessed; }

    // The open relabel editor (a QLineEdit for words, an editable QComboBox of the 41 phones for
    // phones), or null.
    QWidget *relabelEditor() const;

public slots:
    void alignSequence();
    void alignAll();
    void realignSelection();
    void splitAtCursor();
    void mergeWithNext();
    void relabelSelected();
    void insertSilence();
    void insertBreath();
    void playSelection();
    void playWord();
    void playAll();
    void togglePlay();
    void showPronunciations();

signals:
    // An alignment task started (the tests wait for it).
    void alignmentStarted(lipsync::Task *task);

private:
    void createActions();
    QHBoxLayout *createButtonBar();
    void connectActions();
    void syncScrollBar();
    bool preparePlayer();
    void showSequence(int row);
    void refresh();
    // Registers the timeline's own actions (their keys work in the timeline) as commands: what
    // each does, and when it can (CommandRegistry::adopt).
    void adoptCommands();
    void updateActions();
    // The Speech menu's aligner and adaptation, for every alignment of the studio (ModelStore).
    void applyProjectAligner();
    void publishAlignerChoice();
    TierPair currentTiers() const;
    bool edit(const TierPair &next, const QString &text, int mergeKey = -1);
    // The jobs that align `rows` again keeping user edits (alignmentFor); empty if the user declined.
    std::vector<AlignJob> alignmentJobs(const std::vector<int> &rows);
    void startAlignment(const QString &title, std::vector<AlignJob> jobs);
    void applyAlignment(const QString &title, std::vector<AlignOutcome> outcomes);
    void openLabelEditor(TierKind kind, int index);
    void relabel(TierKind kind, int index, const std::string &label); // the editor's, one undo step
    void insertInterval(const std::string &label);
    void onDragStarted(TierKind kind, int boundary, int drag);
    void onDragged(TierKind kind, int boundary, double time, int drag);

    QLabel *m_banner;
    WaveformView *m_waveform;
    QScrollBar *m_scroll;
    IntervalLabelEditor *m_labelEditor;
    PlaybackController *m_player = nullptr;
    bool m_syncing = false;

    StudioContext *m_context = nullptr;
    ProjectDocument *m_document = nullptr;
    int m_row = -1;
    std::shared_ptr<const SpeechToFaceResult> m_speech; // shown instead of the sequence, or null
    QString m_mediaPath; // of the sequence shown (the player may be playing other media)

    TierPair m_dragBase;
    int m_dragKey = -1;
    int m_dragMergeKey = 0;
    // A project of the user's own opened, aligned with GRID's speaker's model: say so once its
    // first sequence is shown.
    bool m_alignerHintPending = false;

    QAction *m_align;
    QAction *m_alignAll;
    QAction *m_realign;
    QAction *m_adaptAction;
    QAction *m_builtInAlignerAction;
    QAction *m_sphinxAlignerAction;
    QMenu *m_alignerMenu = nullptr;
    SpeakerAlignerTrainer *m_speakerAligner = nullptr;
    QAction *m_split;
    QAction *m_merge;
    QAction *m_relabel;
    QAction *m_insertSilence;
    QAction *m_insertBreath;
    QAction *m_playSelection;
    QAction *m_playWord;
    QAction *m_playAll;
    QAction *m_pronunciationsAction;
    QAction *m_spectrogramAction;
    QPointer<PronunciationsDialog> m_pronunciations;
    std::map<std::string, std::string> m_guessed;
    QPointer<Task> m_alignTask;
};

} // namespace lipsync::studio
