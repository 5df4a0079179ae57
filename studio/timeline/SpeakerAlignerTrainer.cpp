#include "timeline/SpeakerAlignerTrainer.h"

#include "context/CommandRegistry.h"
#include "context/ErrorReporter.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"

#include "align/AcousticModel.h"
#include "align/AlignerTrainer.h"
#include "align/AlignerUtterance.h"
#include "align/BoundaryCorrection.h"
#include "align/ForcedAligner.h"
#include "align/Lexicon.h"
#include "align/ProjectAligner.h"
#include "align/PronunciationDictionary.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QAction>
#include <QDir>
#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <random>

namespace lipsync::studio {

namespace {

// What the worker hands back: how much speech it used and how the model does on held-out speech.
struct Trained
{
    int utterances = 0;
    double speechSeconds = 0;
    int heldOut = 0;          // sequences scored
    int boundaries = 0;       // their word boundaries with the project's words
    double heldOutWithin = 0; // share of those within 40 ms of the project's timings
};

constexpr double kTolerance = 0.040; // seconds: the boundary accuracy the benchmarks report

double spokenSeconds(const Tier &words)
{
    double seconds = 0;
    for (const Interval &w : words.intervals)
        if (!PhoneSet::isSilence(w.label) && !PhoneSet::isBreath(w.label))
            seconds += w.end - w.start;
    return seconds;
}

AcousticModel trainAndCalibrate(const std::vector<TrainingUtterance> &utterances, Feedback &feedback)
{
    AcousticModel model = AlignerTrainer::train(utterances, TrainerOptions{}, feedback);
    model.setBoundaryCorrection(AlignerTrainer::calibrate(model, utterances, {}));
    return model;
}

// A model trained on four fifths of `utterances` (a seeded shuffle) aligns the other fifth on the
// features already computed; their word boundaries are scored against the project's timings
// (TrainingUtterance::reference).
void scoreHeldOut(const Project &project, const std::vector<TrainingUtterance> &utterances, Feedback &feedback,
                  Trained &result)
{
    if (utterances.size() < 2)
        return;
    std::vector<size_t> order(utterances.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::mt19937 random(2007);
    std::shuffle(order.begin(), order.end(), random);
    const size_t held = std::max<size_t>(1, order.size() / 5);
    std::vector<TrainingUtterance> train;
    for (size_t k = held; k < order.size(); ++k)
        train.push_back(utterances[order[k]]);
    Feedback training(feedback, 0.0, 0.8);
    const AcousticModel model = trainAndCalibrate(train, training);
    const ForcedAligner aligner(model);
    int within = 0;
    for (size_t k = 0; k < held; ++k) {
        feedback.throwIfCanceled();
        const TrainingUtterance &u = utterances[order[k]];
        try {
            AlignmentResult aligned = aligner.align(
                u.features, Sequence::transcriptWords(project.sequence(u.id)->transcript), u.pronunciations);
            model.boundaryCorrection().apply(aligned);
            for (const BoundaryError &b : BoundaryCorrection::errors(aligned, u.reference))
                for (double e : b.errors) {
                    within += std::abs(e) <= kTolerance + 1e-9;
                    ++result.boundaries;
                }
            ++result.heldOut;
        } catch (const Error &) {
            // words that do not fit this model: not scored
        }
    }
    result.heldOutWithin = result.boundaries > 0 ? double(within) / result.boundaries : 0.0;
}

} // namespace

SpeakerAlignerTrainer::SpeakerAlignerTrainer(StudioContext *context, QWidget *window)
    : QObject(window), m_context(context), m_window(window)
{
    m_action = context->commands()->add(
        {QStringLiteral("aligner/train-own"), tr("Train the Speaker's Own Aligner…"), {}, QStyle::SP_CustomBase,
         [this](const StudioContext &c) {
             return c.document()->isOpen() && !c.document()->isReadOnly() && !isTraining();
         },
         [this](StudioContext &) { start(); }},
        this);
    m_action->setToolTip(tr("Train an aligner model on this project's transcribed speech (three minutes of words "
                            "or more), and align the project with it from then on"));
}

bool SpeakerAlignerTrainer::isTraining() const
{
    return m_task && m_task->isRunning();
}

double SpeakerAlignerTrainer::speechSeconds(const Project &project)
{
    double seconds = 0;
    for (const Sequence &s : project.sequences)
        if (!Sequence::transcriptWords(s.transcript).empty())
            seconds += spokenSeconds(s.words);
    return seconds;
}

QString SpeakerAlignerTrainer::offer() const
{
    const ProjectDocument *document = m_context->document();
    if (!document->isOpen() || document->project().model("aligner"))
        return {};
    const double seconds = speechSeconds(document->project());
    if (seconds < m_minimumSeconds)
        return {};
    return tr(" Its %1 min of words can train the speaker's own aligner: Model ▸ Train the Speaker's Own "
              "Aligner…")
        .arg(seconds / 60.0, 0, 'f', 1);
}

Task *SpeakerAlignerTrainer::start()
{
    ProjectDocument *document = m_context->document();
    const QString title = tr("Train the Speaker's Own Aligner");
    if (!document->isOpen() || isTraining())
        return nullptr;
    ModelStore *store = m_context->modelStore();
    const QString file = store->reserveFile(QStringLiteral("aligner"));
    const QString path = store->writablePath(file);
    if (path.isEmpty()) {
        store->releaseFile(file);
        ErrorReporter::report(m_window, tr("The aligner could not be trained."), QString(),
                              tr("The model is written into the project's folder, and the bundled demo is "
                                 "read-only: save the project in a folder of your own first."));
        return nullptr;
    }
    const Project project = document->project(); // the worker's copy
    const double minimum = m_minimumSeconds;
    auto result = std::make_shared<Trained>();
    QPointer<SpeakerAlignerTrainer> self(this);
    Task *task = m_context->taskRunner()->start(title, [project, path, result, minimum](Feedback &feedback) -> TaskRunner::Commit {
        feedback.setStatus("reading the transcribed sequences");
        const Lexicon lexicon(&PronunciationDictionary::cmu(), Lexicon::parseOverrides(project.pronunciations));
        std::vector<TrainingUtterance> utterances;
        {
            Feedback part(feedback, 0.0, 0.2);
            utterances = projectUtterances(project, featureModel(TrainerOptions{}), lexicon, part);
        }
        // The project's word timings are what the boundary correction learns from.
        for (TrainingUtterance &u : utterances) {
            u.reference = project.sequence(u.id)->words;
            result->speechSeconds += spokenSeconds(u.reference);
        }
        result->utterances = int(utterances.size());
        if (result->speechSeconds < minimum)
            throw Error("the project has " + std::to_string(int(std::lround(result->speechSeconds)))
                            + " s of aligned, transcribed words; training the speaker's own aligner needs at least "
                            + std::to_string(int(minimum)) + " s (until then CMU Sphinx adapted to each recording "
                            + "aligns better)",
                        project.manifestPath());
        feedback.setStatus("training on four fifths, scoring the rest");
        {
            Feedback part(feedback, 0.2, 0.55);
            scoreHeldOut(project, utterances, part, *result);
        }
        feedback.setStatus("training the speaker's aligner");
        Feedback part(feedback, 0.55, 1.0);
        const AcousticModel model = trainAndCalibrate(utterances, part);
        QDir().mkpath(QFileInfo(path).absolutePath());
        model.save(path.toStdString());
        return {};
    });
    m_task = task;
    connect(task, &Task::finished, this, [self, task, file, path, result, title](Task::State state) {
        if (!self)
            return;
        ModelStore *store = self->m_context->modelStore();
        store->releaseFile(file);
        if (state == Task::State::Failed)
            ErrorReporter::report(self->m_window, tr("The aligner could not be trained."), QString(),
                                  task->errorMessage());
        if (state == Task::State::Finished) {
            ProjectDocument *document = self->m_context->document();
            const QString name = tr("Trained on %1").arg(QString::fromStdString(document->project().name));
            document->requestAddModel({"aligner", name.toStdString(), file.toStdString()}, title);
            self->m_context->showStatus(
                tr("The speaker's own aligner is trained on %n sequences", nullptr, result->utterances)
                    + tr(" (%1 min of words). On %2 sequences it was not trained on, %3 % of its word boundaries are "
                         "within 40 ms of the project's timings. The project is aligned with it from now on.")
                          .arg(result->speechSeconds / 60.0, 0, 'f', 1)
                          .arg(result->heldOut)
                          .arg(100.0 * result->heldOutWithin, 0, 'f', 1),
                20000);
            emit self->trained(file);
        } else {
            QFile::remove(path); // canceled or failed after the model was written: not the project's
        }
        self->m_context->commands()->revalidate();
    });
    m_context->commands()->revalidate();
    return task;
}

} // namespace lipsync::studio
