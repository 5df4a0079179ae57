#include "app/TranscriptProposer.h"

#include "app/SequenceListModel.h"
#include "context/CommandRegistry.h"
#include "context/ErrorReporter.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include "align/SpeechRecognizer.h"
#include "align/SphinxAligner.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"
#include "tasks/Task.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>

namespace lipsync::studio {

TranscriptProposer::TranscriptProposer(StudioContext *context, QWidget *window)
    : QObject(window), m_context(context), m_window(window), m_modelInstalled(SphinxAligner::available())
{
    setObjectName(QStringLiteral("transcriptProposer"));
    CommandRegistry *commands = context->commands();
    m_propose = commands->add({QStringLiteral("edit/propose-transcript"), tr("&Propose Transcript"), {},
                               QStyle::SP_CustomBase,
                               [this](const StudioContext &c) {
                                   // The current sequence's sound is loaded: there is speech to recognise.
                                   return m_modelInstalled && currentRow(c) >= 0 && c.media() && c.media()->peaks
                                          && !isProposing();
                               },
                               [this](StudioContext &) { proposeCurrent(); }},
                              this);
    m_propose->setToolTip(m_modelInstalled
                              ? tr("Propose a transcript of this sequence by speech recognition (CMU Sphinx's US-English "
                                   "models), marked as not checked until you edit or accept it")
                              : tr("Needs CMU Sphinx's US-English model (Debian package pocketsphinx-en-us)"));
    m_accept = commands->add({QStringLiteral("edit/accept-transcript"), tr("&Accept Proposed Transcript"), {},
                              QStyle::SP_CustomBase,
                              [](const StudioContext &c) {
                                  const int row = currentRow(c);
                                  return row >= 0 && c.document()->sequence(row).transcriptProposed;
                              },
                              [this](StudioContext &) { acceptCurrent(); }},
                             this);
    m_accept->setToolTip(tr("Take the proposed transcript of this sequence as checked, as it is"));

    // Another project: the proposal was for the one before.
    connect(m_context->document(), &ProjectDocument::documentReset, this, [this] {
        if (isProposing())
            m_task->cancel();
    });
}

int TranscriptProposer::currentRow(const StudioContext &context)
{
    const ProjectDocument *document = context.document();
    const int row = context.currentSequence();
    return document->isOpen() && row >= 0 && row < document->sequenceCount() ? row : -1;
}

bool TranscriptProposer::isProposing() const
{
    return m_task && m_task->isRunning();
}

void TranscriptProposer::proposeCurrent()
{
    propose(m_context->currentSequence());
}

bool TranscriptProposer::acceptCurrent()
{
    return m_context->document()->requestAcceptTranscript(m_context->currentSequence());
}

Task *TranscriptProposer::propose(int row)
{
    ProjectDocument *document = m_context->document();
    if (!document->isOpen() || row < 0 || row >= document->sequenceCount() || !m_modelInstalled || isProposing())
        return nullptr;
    const Sequence &sequence = document->sequence(row);
    const QString id = QString::fromStdString(sequence.id);
    const QString before = QString::fromStdString(sequence.transcript);
    // Words the user has are not thrown away unasked (as Align asks before replacing edited
    // boundaries); Undo would bring them back.
    if (!before.trimmed().isEmpty() && !ErrorReporter::isBatchMode()
        && QMessageBox::question(m_window, tr("Propose Transcript"),
                                 tr("%1 has a transcript. Proposing one replaces it with the words speech recognition "
                                    "hears. Propose anyway?")
                                     .arg(id))
               != QMessageBox::Yes)
        return nullptr;
    const QString mediaPath = document->mediaPath(row);
    QPointer<TranscriptProposer> self(this);
    Task *task = m_context->taskRunner()->start(
        tr("Propose transcript of %1").arg(id),
        [mediaPath, id, before, self](Feedback &feedback) -> TaskRunner::Commit {
            feedback.setStatus("loading the speech recogniser");
            const SpeechRecognizer recognizer;
            feedback.throwIfCanceled();
            feedback.setStatus(QFileInfo(mediaPath).fileName().toStdString());
            const SpeechRecognizer::Result result = recognizer.recognize(mediaPath.toStdString(), feedback);
            Transcript heard;
            heard.words = result.words;
            if (heard.words.empty())
                throw Error("no speech recognised", mediaPath.toStdString());
            const QString proposal = QString::fromStdString(heard.text());
            return [self, id, before, proposal, confidence = result.confidence] {
                if (self)
                    self->apply(id, before, proposal, confidence);
            };
        });
    m_task = task;
    connect(task, &Task::finished, this, [this, task](Task::State state) {
        if (state == Task::State::Failed)
            ErrorReporter::report(m_window, tr("No transcript could be proposed."), QString(), task->errorMessage());
        m_context->commands()->revalidate();
    });
    m_context->commands()->revalidate();
    emit proposalStarted(task);
    return task;
}

void TranscriptProposer::apply(const QString &sequenceId, const QString &before, const QString &proposal,
                               const std::vector<double> &confidence)
{
    ProjectDocument *document = m_context->document();
    int row = -1;
    for (int r = 0; r < document->sequenceCount() && row < 0; ++r)
        if (QString::fromStdString(document->sequence(r).id) == sequenceId)
            row = r;
    if (row < 0)
        return; // the sequence went (an undone import)
    // Words typed while the recogniser ran are the user's latest: they stay.
    if (QString::fromStdString(document->sequence(row).transcript) != before) {
        m_context->showStatus(
            tr("The transcript of %1 changed while its speech was recognised: the proposal was not applied.")
                .arg(sequenceId),
            8000);
        return;
    }
    // Recognised words the sequence already has (checked or not) stay as they are.
    if (proposal.simplified() == before.simplified() || !document->requestProposedTranscript(row, proposal, confidence)) {
        m_context->showStatus(tr("Speech recognition proposes the transcript %1 has: nothing changed.").arg(sequenceId),
                              8000);
        return;
    }
    // The words to check first: the recogniser's least sure, as the sequence now keeps them.
    const QString doubtful = SequenceListModel::doubtfulWords(document->sequence(row));
    if (doubtful.isEmpty())
        m_context->showStatus(tr("Transcript of %1 proposed: check it, then edit or accept it.").arg(sequenceId), 8000);
    else
        m_context->showStatus(tr("Transcript of %1 proposed: check it, the most doubtful words first: %2.")
                                  .arg(sequenceId, doubtful),
                              30000);
    emit proposed(row);
}

} // namespace lipsync::studio
