#include "app/LongRecordingImporter.h"

#include "app/ImportLongRecordingDialog.h"
#include "context/ErrorReporter.h"
#include "context/WritableProject.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include "align/Lexicon.h"
#include "align/ProjectAligner.h"
#include "align/PronunciationDictionary.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "project/ProjectManifest.h"
#include "render/LongRecordingImport.h"
#include "tasks/TaskRunner.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <memory>
#include <utility>

namespace lipsync::studio {

namespace {

// What the worker hands to the GUI thread: the new sequences, their media relative to `folder`
// (the project's when the import started), until the document takes them.
struct ImportedSequences
{
    std::vector<Sequence> sequences;
    std::string folder;
    int words = 0;
    bool shippedForLong = false; // CMU Sphinx was chosen, the recording too long for it
};

} // namespace

LongRecordingImporter::LongRecordingImporter(StudioContext *context, std::function<bool()> saveProject,
                                             QWidget *window)
    : QObject(window), m_context(context), m_saveProject(std::move(saveProject)), m_window(window),
      m_action(new QAction(tr("Import &Long Recording…"), this))
{
    setObjectName(QStringLiteral("longRecordingImporter"));
    m_action->setObjectName(QStringLiteral("importLongRecordingAction"));
    m_action->setToolTip(tr("Align a long recording of one speaker to its transcript and add its utterances to the "
                            "project as sequences"));
    connect(m_action, &QAction::triggered, this, &LongRecordingImporter::importWithDialog);
    ProjectDocument *document = m_context->document();
    // Another project: the import was for the one before.
    connect(document, &ProjectDocument::documentReset, this, [this] {
        if (isImporting())
            m_task->cancel();
        updateAction();
    });
    updateAction();
}

bool LongRecordingImporter::isImporting() const
{
    return m_task && m_task->isRunning();
}

void LongRecordingImporter::updateAction()
{
    m_action->setEnabled(m_context->document()->isOpen() && !isImporting());
}

void LongRecordingImporter::importWithDialog()
{
    ProjectDocument *document = m_context->document();
    if (!document->isOpen() || isImporting())
        return;
    if (!ensureWritableProject(m_window, *document, m_saveProject, tr("Import Long Recording"),
                               tr("The recording's clips are written into the project's folder, and the "
                                  "bundled demo is read-only. Save the project in a folder of your own first?")))
        return;
    ImportLongRecordingDialog dialog(m_window);
    dialog.setObjectName(QStringLiteral("importLongRecordingDialog"));
    emit dialogOpened(&dialog);
    if (dialog.exec() != QDialog::Accepted)
        return;
    start(dialog.recordingPath(), dialog.transcriptPath(), dialog.splitOptions());
}

Task *LongRecordingImporter::start(const QString &recordingPath, const QString &transcriptPath,
                                   const UtteranceSplitOptions &split)
{
    ProjectDocument *document = m_context->document();
    if (!document->isOpen() || isImporting())
        return nullptr;
    if (document->isReadOnly()) {
        ErrorReporter::report(m_window, tr("The long recording could not be imported."), recordingPath,
                              tr("The bundled demo is read-only: save the project in a folder of your own first."));
        return nullptr;
    }
    // The worker's copy of the project: its folder (where the clips go) and its sequence ids
    // (which the new ones must not take), all importLongRecording reads.
    const Project &project = document->project();
    Project target;
    target.setFolder(project.folder());
    for (const Sequence &s : project.sequences) {
        Sequence taken;
        taken.id = s.id;
        target.sequences.push_back(std::move(taken));
    }
    const std::map<std::string, std::string> pronunciations = project.pronunciations;
    // The aligner the timeline aligns with (ModelStore: the Speech menu's choice), from the cache
    // its alignments load theirs into.
    const AlignerChoice choice = m_context->modelStore()->alignerChoice();
    const std::shared_ptr<AlignerCache> aligners = m_context->modelStore()->aligners();
    LongRecordingImportOptions options;
    options.split = split;
    auto imported = std::make_shared<ImportedSequences>();
    const QString name = QFileInfo(recordingPath).fileName();
    QPointer<LongRecordingImporter> self(this);
    Task *task = m_context->taskRunner()->start(
        tr("Import %1").arg(name),
        [target = std::move(target), recordingPath, transcriptPath, pronunciations, choice, aligners, options,
         imported, name, self](Feedback &feedback) -> TaskRunner::Commit {
            feedback.setStatus("reading the transcript");
            const Transcript transcript = readTranscript(transcriptPath.toStdString());
            feedback.setStatus("loading the aligner model");
            // A recording longer than CMU Sphinx aligns is cut with the shipped model, window by
            // window (the utterances can be aligned again afterwards).
            AlignerChoice chosen = choice;
            chosen.transcriptFit = true; // marks the utterances when the words do not fit the sound
            imported->shippedForLong =
                fallBackForLongRecording(chosen, MediaInfo::probe(recordingPath.toStdString()).audioDuration);
            const std::shared_ptr<const Aligner> aligner = aligners->get(chosen);
            const Lexicon lexicon(&PronunciationDictionary::cmu(), Lexicon::parseOverrides(pronunciations));
            feedback.setStatus(name.toStdString());
            LongRecordingImportResult result =
                importLongRecording(target, recordingPath.toStdString(), transcript.words,
                                    transcriptPath.toStdString(), *aligner, lexicon, options, feedback);
            imported->sequences = std::move(result.sequences);
            imported->folder = target.folder();
            imported->words = result.words;
            return [self, imported, name] {
                if (!self)
                    return;
                ProjectDocument *document = self->m_context->document();
                std::vector<Sequence> sequences = std::exchange(imported->sequences, {});
                const int count = int(sequences.size());
                // The project may have been saved elsewhere meanwhile: its clips stay where they are.
                for (Sequence &s : sequences)
                    s.mediaFile = rebaseRelativePath(s.mediaFile, imported->folder, document->project().folder());
                const int first = document->sequenceCount();
                // Refused (editRefused says why): an id was taken meanwhile, by a Redo of an earlier
                // import of this recording, whose sequences now use these clips: they stay.
                if (!document->requestAddSequences(std::move(sequences), tr("Import %1").arg(name)))
                    return;
                if (imported->shippedForLong)
                    self->m_context->showStatus(
                        tr("Imported from %1: %2 sequences, %3 words, cut with the built-in model (the recording is "
                           "longer than Generic US English aligns): Align All aligns them again with it.")
                            .arg(name)
                            .arg(count)
                            .arg(imported->words),
                        20000);
                else
                    self->m_context->showStatus(
                        tr("Imported from %1: %2 sequences, %3 words.").arg(name).arg(count).arg(imported->words), 8000);
                emit self->imported(first, count);
            };
        });
    m_task = task;
    connect(task, &Task::finished, this, [this, task, imported](Task::State state) {
        if (state == Task::State::Failed)
            ErrorReporter::report(m_window, tr("The long recording could not be imported."), QString(),
                                  task->errorMessage());
        // Canceled after its clips were written: they go again, the project folder as it was.
        if (state != Task::State::Finished) {
            const QDir folder(QString::fromStdString(imported->folder));
            for (const Sequence &s : imported->sequences)
                QFile::remove(folder.absoluteFilePath(QString::fromStdString(s.mediaFile)));
        }
        updateAction();
    });
    updateAction();
    emit importStarted(task);
    return task;
}

} // namespace lipsync::studio
