#pragma once
// Edit ▸ Propose Transcript: speech recognition's words for the current sequence
// (align/SpeechRecognizer, CMU Sphinx's US-English models, as `lipsync transcribe`), marked as
// proposed (Sequence::transcriptProposed) until the user edits them or Edit ▸ Accept Proposed
// Transcript. The recogniser runs through the TaskRunner with progress and cancel, on the media
// path alone; the GUI thread then sets the words as one undo step
// (ProjectDocument::requestProposedTranscript). A cancel or a failure changes nothing; an existing
// transcript is replaced only after asking, and not at all if it changed while the recogniser ran.
#include "tasks/Task.h"

#include <QObject>
#include <QPointer>
#include <QString>

#include <vector>

class QAction;
class QWidget;

namespace lipsync::studio {

class StudioContext;

class TranscriptProposer : public QObject
{
    Q_OBJECT
public:
    // `window` parents the questions and error messages.
    TranscriptProposer(StudioContext *context, QWidget *window);

    // Enabled for the current sequence once its sound is loaded, when CMU Sphinx's model is
    // installed (SphinxAligner::available) and no proposal is running.
    QAction *proposeAction() const { return m_propose; }
    // Enabled when the current sequence's transcript is proposed.
    QAction *acceptAction() const { return m_accept; }
    bool isProposing() const;
    // Starts recognising the speech of sequence `row`; returns the task, or null when none
    // started (no such sequence, no model, a proposal still running, or the user kept the
    // transcript it has).
    Task *propose(int row);

public slots:
    void proposeCurrent();
    // One undo step ("Accept transcript of ID"); false if the transcript is not proposed.
    bool acceptCurrent();

signals:
    // A proposal started (tests wait for it).
    void proposalStarted(lipsync::Task *task);
    // Sequence `row` got the proposed transcript.
    void proposed(int row);

private:
    void apply(const QString &sequenceId, const QString &before, const QString &proposal,
               const std::vector<double> &confidence);
    // The current sequence of `context` (-1: none).
    static int currentRow(const StudioContext &context);

    StudioContext *m_context;
    QWidget *m_window;
    QAction *m_propose;
    QAction *m_accept;
    bool m_modelInstalled;
    QPointer<Task> m_task; // the latest proposal
};

} // namespace lipsync::studio
