#include "timeline/SpeakerAlignerAdapter.h"

#include "context/ErrorReporter.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include "align/AcousticModel.h"
#include "align/Lexicon.h"
#include "align/ProjectAligner.h"
#include "align/PronunciationDictionary.h"
#include "align/ShippedAlignerModel.h"
#include "align/SpeakerAdaptation.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <memory>

namespace lipsync::studio {

namespace {

// What the worker hands back: how much speech it used and how the fit improved.
struct Adapted
{
    int utterances = 0;
    int skipped = 0;
    double seconds = 0;
    double before = 0, after = 0; // log-likelihood per frame, first and last pass
};

} // namespace

SpeakerAlignerAdapter::SpeakerAlignerAdapter(StudioContext *context, QWidget *window)
    : QObject(window), m_context(context), m_window(window),
      m_action(new QAction(tr("Make the Speaker's Own Aligner…"), this))
{
    m_action->setObjectName(QStringLiteral("speakerAlignerAction"));
    m_action->setToolTip(tr("Adapt the built-in aligner model to this project's speaker from its transcribed "
                            "sequences, and align the project with it from then on"));
    connect(m_action, &QAction::triggered, this, &SpeakerAlignerAdapter::start);
    connect(m_context->document(), &ProjectDocument::documentReset, this, &SpeakerAlignerAdapter::updateAction);
    connect(m_context->document(), &ProjectDocument::locationChanged, this, &SpeakerAlignerAdapter::updateAction);
    updateAction();
}

void SpeakerAlignerAdapter::updateAction()
{
    const ProjectDocument *document = m_context->document();
    m_action->setEnabled(document->isOpen() && !document->isReadOnly() && !(m_task && m_task->isRunning()));
}

QString SpeakerAlignerAdapter::offer() const
{
    const ProjectDocument *document = m_context->document();
    if (!document->isOpen() || document->project().model("aligner"))
        return {};
    double seconds = 0;
    for (const Sequence &s : document->project().sequences)
        if (!Sequence::transcriptWords(s.transcript).empty())
            seconds += s.clock().duration();
    if (seconds < kMinimumSeconds)
        return {};
    return tr(" Its %1 s of transcribed speech can make the speaker's own aligner: Model ▸ Make the Speaker's Own "
              "Aligner…")
        .arg(seconds, 0, 'f', 0);
}

Task *SpeakerAlignerAdapter::start()
{
    ProjectDocument *document = m_context->document();
    const QString title = tr("Make the Speaker's Own Aligner");
    if (!document->isOpen() || (m_task && m_task->isRunning()))
        return nullptr;
    ModelStore *store = m_context->modelStore();
    const QString file = store->reserveFile(QStringLiteral("aligner"));
    const QString path = store->writablePath(file);
    if (path.isEmpty()) {
        store->releaseFile(file);
        ErrorReporter::report(m_window, tr("The aligner could not be adapted."), QString(),
                              tr("The model is written into the project's folder, and the bundled demo is "
                                 "read-only: save the project in a folder of your own first."));
        return nullptr;
    }
    const Project project = document->project(); // the worker's copy
    auto result = std::make_shared<Adapted>();
    QPointer<SpeakerAlignerAdapter> self(this);
    Task *task = m_context->taskRunner()->start(title, [project, path, result](Feedback &feedback) -> TaskRunner::Commit {
        feedback.setStatus("reading the transcribed sequences");
        const AcousticModel base = AcousticModel::load(shippedAlignerModelPath());
        const Lexicon lexicon(&PronunciationDictionary::cmu(), Lexicon::parseOverrides(project.pronunciations));
        std::vector<std::string> skipped;
        std::vector<TrainingUtterance> utterances;
        {
            Feedback part(feedback, 0.0, 0.3);
            utterances = projectUtterances(project, base, lexicon, part, &skipped);
        }
        for (const TrainingUtterance &u : utterances)
            result->seconds += double(u.features.rows()) * base.featureOptions().shiftSeconds;
        result->utterances = int(utterances.size());
        result->skipped = int(skipped.size());
        if (result->seconds < kMinimumSeconds)
            throw Error("the project has " + std::to_string(int(result->seconds)) + " s of transcribed speech the "
                        + "aligner can use; adapting it to the speaker needs at least "
                        + std::to_string(int(kMinimumSeconds)) + " s",
                        project.manifestPath());
        feedback.setStatus("adapting the aligner model to the speaker");
        Feedback part(feedback, 0.3, 1.0);
        AdaptationReport report;
        const AcousticModel adapted = SpeakerAdaptation::adapt(base, utterances, {}, part, &report);
        if (!report.logLikelihoodPerFrame.empty()) {
            result->before = report.logLikelihoodPerFrame.front();
            result->after = report.logLikelihoodPerFrame.back();
        }
        QDir().mkpath(QFileInfo(path).absolutePath());
        adapted.save(path.toStdString());
        return {};
    });
    m_task = task;
    connect(task, &Task::finished, this, [self, task, file, path, result, title](Task::State state) {
        if (!self)
            return;
        ModelStore *store = self->m_context->modelStore();
        store->releaseFile(file);
        if (state == Task::State::Failed)
            ErrorReporter::report(self->m_window, tr("The aligner could not be adapted."), QString(),
                                  task->errorMessage());
        if (state == Task::State::Finished) {
            ProjectDocument *document = self->m_context->document();
            const QString name = tr("Adapted to %1").arg(QString::fromStdString(document->project().name));
            document->requestAddModel({"aligner", name.toStdString(), file.toStdString()}, title);
            self->m_context->showStatus(
                tr("The aligner is adapted to the speaker from %n sequences", nullptr, result->utterances)
                    + tr(" (%1 s of speech; log-likelihood per frame %2 → %3): the project is aligned with it "
                         "from now on.")
                          .arg(result->seconds, 0, 'f', 0)
                          .arg(result->before, 0, 'f', 2)
                          .arg(result->after, 0, 'f', 2),
                15000);
            emit self->adapted(file);
        } else {
            QFile::remove(path); // canceled or failed after the model was written: not the project's
        }
        self->updateAction();
    });
    updateAction();
    return task;
}

} // namespace lipsync::studio
