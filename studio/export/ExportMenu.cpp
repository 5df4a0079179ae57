#include "export/ExportMenu.h"

#include "context/CommandRegistry.h"
#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "export/MouthShapesDialog.h"
#include "document/ProjectDocument.h"

#include "aam/AamModel.h"
#include "aam/PtsFile.h"
#include "animation/AnimationControls.h"
#include "animation/MouthCues.h"
#include "animation/MouthTrack.h"
#include "dynamics/ModelFile.h"
#include "io/FeatureCsv.h"
#include "io/TextGrid.h"
#include "render/FaceRenderer.h"
#include "render/SpeechToFace.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QInputDialog>
#include <QFileInfo>
#include <QMenu>
#include <QPointer>
#include <QRegularExpression>

#include <algorithm>
#include <array>
#include <cstdio>
#include <utility>

namespace lipsync::studio {

namespace {

// The project's trained dynamic model of `kind`, or by default the first of the studio's order
// (ModelKinds::ids(), the default model first).
const ModelReference *dynamicModel(const Project &project, const QString &kind = {})
{
    if (!kind.isEmpty())
        return project.model(kind.toStdString());
    for (const QString &k : ModelKinds::ids())
        if (const ModelReference *m = project.model(k.toStdString()))
            return m;
    return nullptr;
}

bool isGenerated(ExportMenu::Kind kind)
{
    return kind == ExportMenu::Kind::Video || kind == ExportMenu::Kind::SideBySide || kind == ExportMenu::Kind::Images;
}

bool isAnimation(ExportMenu::Kind kind)
{
    return kind == ExportMenu::Kind::MouthCues || kind == ExportMenu::Kind::Controls;
}

// The exports that write the new speech the Preview shows, when it shows some.
bool followsShownSpeech(ExportMenu::Kind kind)
{
    return isGenerated(kind) || isAnimation(kind);
}

bool usesDynamicModel(ExportMenu::Kind kind)
{
    return isGenerated(kind) || kind == ExportMenu::Kind::Model;
}

// The side-by-side panels' labels are drawn in ASCII: the model's name, else its id.
std::string panelLabel(const std::string &kind)
{
    const QString name = ModelKinds::name(kind);
    for (QChar c : name)
        if (c.unicode() >= 0x80)
            return kind;
    return name.toStdString();
}

// Renders a generated result into its recording's frames (or a neutral frame) and writes the
// video or the frames: the work of the three generated exports.
TaskRunner::Work renderWork(std::shared_ptr<const SpeechToFaceResult> result, RenderOptions options,
                            std::string target, bool images)
{
    return [result = std::move(result), options, target, images](Feedback &feedback) -> TaskRunner::Commit {
        std::unique_ptr<FaceRenderer> renderer;
        {
            Feedback step(feedback, 0.0, 0.25);
            renderer = makeRenderer(*result, result->mediaPath, step);
        }
        Feedback step(feedback, 0.25, 1.0);
        if (images)
            exportRenderedImages(*result, *renderer, target, step, options);
        else
            exportRenderedVideo(*result, *renderer, target, step, options);
        return {};
    };
}

} // namespace

ExportMenu::ExportMenu(StudioContext *context, QMenu *parentMenu, QWidget *dialogParent)
    : QObject(dialogParent), m_context(context), m_dialogParent(dialogParent),
      m_menu(parentMenu->addMenu(tr("E&xport")))
{
    const std::array<QString, 10> titles = {
        tr("Generated &Video%1 (MP4)…").arg(QString()), tr("Real and Generated &Side by Side%1 (MP4)…").arg(QString()),
        tr("Generated &Frames%1 (PNG)…").arg(QString()), tr("F&eatures (CSV)…"),
        tr("&Alignment (TextGrid)…"),           tr("&Landmarks (.pts)…"),
        tr("Active Appearance &Model…"),        tr("&Trained Dynamic Model…"),
        tr("Mouth &Cues%1 (Rhubarb, Moho)…").arg(QString()), tr("Animation C&ontrols%1 (JSON, CSV)…").arg(QString())};
    static const std::array<const char *, 10> names = {
        "export/video",     "export/side-by-side", "export/frames", "export/features",   "export/alignment",
        "export/landmarks", "export/aam",          "export/model",  "export/mouth-cues", "export/controls"};
    CommandRegistry *commands = context->commands();
    for (size_t i = 0; i < titles.size(); ++i) {
        if (i == 3 || i == 6 || i == 8)
            m_menu->addSeparator();
        const Kind kind = Kind(i);
        QAction *action = commands->add({QLatin1String(names[i]), titles[i], {}, QStyle::SP_CustomBase,
                                         [this, kind](const StudioContext &) { return canExport(kind); },
                                         [this, kind](StudioContext &) { trigger(kind); }},
                                        this);
        m_menu->addAction(action);
        m_actions.append(action);
    }
    m_mouthShapesAction = commands->add(
        {QStringLiteral("export/mouth-shapes"), tr("Mouth S&hapes…"), {}, QStyle::SP_CustomBase,
         [](const StudioContext &c) { return c.document()->project().aam() != nullptr; },
         [this](StudioContext &) { showMouthShapes(); }},
        this);
    m_menu->addAction(m_mouthShapesAction);
    m_mouthShapesAction->setToolTip(tr("The nine mouth shapes of the cues, learned from this person's frames: see "
                                       "them and set your own"));
    // What the entries would write depends on more than the registry follows (models trained,
    // landmarks placed): validated again as the menu opens, as Aegisub's menus do.
    connect(m_menu, &QMenu::aboutToShow, this, &ExportMenu::updateActions);
    m_modelPrompt = [this](const QStringList &kinds, const QStringList &names) {
        bool ok = false;
        const QString name = QInputDialog::getItem(m_dialogParent, tr("Export"), tr("Which trained model?"), names, 0,
                                                   false, &ok);
        return ok ? kinds.value(names.indexOf(name)) : QString();
    };
    m_prompt = [this](const PathRequest &request) {
        if (request.filter.isEmpty())
            return QFileDialog::getExistingDirectory(m_dialogParent, request.title, request.suggestedPath);
        QString selected;
        const QString path = QFileDialog::getSaveFileName(m_dialogParent, request.title, request.suggestedPath,
                                                          request.filter, &selected);
        return withFilterSuffix(path, selected);
    };
}

QString ExportMenu::withFilterSuffix(const QString &path, const QString &filter)
{
    if (path.isEmpty() || !QFileInfo(path).suffix().isEmpty())
        return path;
    static const QRegularExpression pattern(QStringLiteral("\\(\\*(\\.[^) ]+)"));
    const QRegularExpressionMatch match = pattern.match(filter);
    return match.hasMatch() ? path + match.captured(1) : path;
}

QAction *ExportMenu::action(Kind kind) const
{
    return m_actions.value(int(kind));
}

void ExportMenu::updateActions()
{
    // While the Preview shows faces for new speech, the generated exports write those.
    const QString of = m_context->shownSpeech() ? tr(" of %1").arg(m_context->shownSpeechTitle()) : QString();
    action(Kind::Video)->setText(tr("Generated &Video%1 (MP4)…").arg(of));
    action(Kind::SideBySide)->setText(tr("Real and Generated &Side by Side%1 (MP4)…").arg(of));
    action(Kind::Images)->setText(tr("Generated &Frames%1 (PNG)…").arg(of));
    action(Kind::MouthCues)->setText(tr("Mouth &Cues%1 (Rhubarb, Moho)…").arg(of));
    action(Kind::Controls)->setText(tr("Animation C&ontrols%1 (JSON, CSV)…").arg(of));
    m_context->commands()->revalidate();
}

bool ExportMenu::canExport(Kind kind) const
{
    const ProjectDocument *document = m_context->document();
    const int row = m_context->currentSequence();
    const Sequence *s = row >= 0 && row < document->sequenceCount() ? &document->sequence(row) : nullptr;
    const Project &project = document->project();
    const auto speech = m_context->shownSpeech();
    const bool canGenerate = speech || (s && dynamicModel(project) && project.aam());
    switch (kind) {
    case Kind::Video:
    case Kind::Images:
        return canGenerate;
    case Kind::SideBySide:
        return speech ? speech->hasVideo : canGenerate;
    case Kind::Features:
        return s && s->features.rows() > 0;
    case Kind::Alignment:
        return s && !s->phones.isEmpty();
    case Kind::Landmarks:
        return s && !s->landmarks.empty();
    case Kind::Aam:
        return project.aam() != nullptr;
    case Kind::Model:
        return dynamicModel(project) != nullptr;
    case Kind::MouthCues:
    case Kind::Controls:
        return project.aam() && (speech || (s && s->features.rows() > 0 && !s->phones.isEmpty()));
    }
    return false;
}

Task *ExportMenu::trigger(Kind kind)
{
    const ProjectDocument *document = m_context->document();
    const int row = m_context->currentSequence();
    const auto speech = followsShownSpeech(kind) ? m_context->shownSpeech() : nullptr;
    const QString stem = speech ? QFileInfo(QString::fromStdString(speech->mediaPath)).completeBaseName()
                         : row >= 0 && row < document->sequenceCount()
                             ? QString::fromStdString(document->sequence(row).id)
                             : QStringLiteral("export");
    const QString folder = document->exportFolder();
    // Several trained models: the user picks one (never a silent default). New speech was
    // generated by one already.
    QString modelKind = speech ? QString::fromStdString(speech->modelKind) : QString();
    if (usesDynamicModel(kind) && !speech) {
        QStringList kinds, names;
        for (const QString &k : ModelKinds::ids())
            if (document->project().model(k.toStdString())) {
                kinds << k;
                names << ModelKinds::name(k);
            }
        if (kinds.size() > 1) {
            modelKind = m_modelPrompt ? m_modelPrompt(kinds, names) : QString();
            if (modelKind.isEmpty())
                return nullptr;
        } else {
            modelKind = kinds.value(0);
        }
    }
    const QString modelSuffix = modelKind.isEmpty() ? QString() : QLatin1Char('-') + modelKind;
    PathRequest request{kind, action(kind)->text().remove(QLatin1Char('&')).remove(QStringLiteral("…")),
                        QString(), QString()};
    // Suggested name (after the sequence id, or alone for project-wide files) and file filter
    // (none: a folder), in Kind order.
    const std::array<std::pair<QString, QString>, 10> targets = {{
        {stem + "-generated" + modelSuffix + ".mp4", tr("MP4 video (*.mp4)")},
        {stem + "-side-by-side" + modelSuffix + ".mp4", tr("MP4 video (*.mp4)")},
        {stem + "-frames" + modelSuffix, QString()},
        {stem + ".csv", tr("Feature tables (*.csv)")},
        {stem + ".TextGrid", tr("Praat TextGrid (*.TextGrid)")},
        {stem + "-landmarks", QString()},
        {QStringLiteral("model.aam"), tr("Active appearance models (*.aam)")},
        {(modelKind.isEmpty() ? QStringLiteral("dynamics") : modelKind) + QStringLiteral(".model"),
         tr("Dynamic models (*.model)")},
        {stem + "-cues.tsv", tr("Rhubarb TSV (*.tsv);;Rhubarb JSON (*.json);;Rhubarb XML (*.xml);;Moho switch data (*.dat)")},
        {stem + "-controls.json", tr("Controls JSON (*.json);;Controls CSV (*.csv)")},
    }};
    request.suggestedPath = folder + "/" + targets[size_t(kind)].first;
    request.filter = targets[size_t(kind)].second;
    const QString path = m_prompt ? m_prompt(request) : QString();
    if (path.isEmpty())
        return nullptr;
    return exportTo(kind, path, modelKind);
}

Task *ExportMenu::exportTo(Kind kind, const QString &path, const QString &modelKind)
{
    const ProjectDocument *document = m_context->document();
    const int row = m_context->currentSequence();
    const bool projectWide = kind == Kind::Aam || kind == Kind::Model;
    const QString what = tr("Cannot export");
    if (!projectWide && (row < 0 || row >= document->sequenceCount())) {
        ErrorReporter::report(m_dialogParent, what, path, tr("no sequence is selected"));
        return nullptr;
    }
    // Everything the worker needs is copied here, on the GUI thread: it never reads the document.
    const Sequence sequence = projectWide ? Sequence() : document->sequence(row);
    Job job;
    switch (kind) {
    case Kind::Video:
    case Kind::SideBySide:
    case Kind::Images: job = videoJob(kind, path, sequence, modelKind); break;
    case Kind::Features:
    case Kind::Alignment:
    case Kind::Landmarks: job = sequenceDataJob(kind, path, sequence); break;
    case Kind::Aam:
    case Kind::Model: job = modelJob(kind, path, modelKind); break;
    case Kind::MouthCues:
    case Kind::Controls: job = animationJob(kind, path, sequence); break;
    }
    if (!job.work)
        return nullptr; // refused, and said why
    Task *task = m_context->taskRunner()->start(job.title, std::move(job.work));
    connect(task, &Task::finished, this, [this, task, path, what](Task::State state) {
        if (state == Task::State::Finished) {
            m_context->showStatus(tr("Exported to %1").arg(QDir::toNativeSeparators(path)), 15000);
            emit exported(path);
        }
        else if (state == Task::State::Failed)
            ErrorReporter::report(m_dialogParent, what, path, task->errorMessage());
    });
    return task;
}

// The generated video, side by side, or frames: of the new speech the Preview shows, else of the
// sequence generated from its own alignment.
ExportMenu::Job ExportMenu::videoJob(Kind kind, const QString &path, const Sequence &sequence, const QString &modelKind)
{
    const Project &project = m_context->document()->project();
    ModelStore *store = m_context->modelStore();
    const ModelReference *model = dynamicModel(project, modelKind);
    const ModelReference *aam = project.aam();
    const std::string target = path.toStdString();
    const QString id = QString::fromStdString(sequence.id);
    const QString what = tr("Cannot export");
    QString title;
    RenderOptions options;
    options.sideBySide = kind == Kind::SideBySide;
    options.composite = m_context->compositeOptions();
    if (const auto speech = m_context->shownSpeech()) {
        const QString name = m_context->shownSpeechTitle();
        if (options.sideBySide && !speech->hasVideo) {
            ErrorReporter::report(m_dialogParent, what, path,
                                  tr("%1 has no video to put beside the generated face").arg(name));
            return {};
        }
        options.leftLabel = "real";
        options.rightLabel = panelLabel(speech->modelKind);
        title = kind == Kind::Images ? tr("Export the generated frames of %1").arg(name)
                                     : tr("Export the generated video of %1").arg(name);
        return {title, renderWork(speech, options, target, kind == Kind::Images)};
    }
    QString problem;
    const auto aamModel = store->aam(&problem);
    const auto dynamic = model ? store->dynamicModel(QString::fromStdString(model->kind), &problem) : nullptr;
    if (!dynamic || !aamModel) {
        ErrorReporter::report(m_dialogParent, what, path,
                              problem.isEmpty() ? tr("the project has no trained dynamic model and AAM (train one "
                                                     "in the Models panel)")
                                                : problem);
        return {};
    }
    SpeechToFaceRequest request;
    request.mediaPath = project.mediaPath(sequence);
    request.modelPath = project.resolve(model->file);
    request.aamPath = project.resolve(aam->file);
    request.model = dynamic;
    request.aam = aamModel;
    request.frameRate = sequence.frameRate;
    request.closeBilabials = m_context->closesLips();
    options.leftLabel = "real";
    options.rightLabel = panelLabel(model->kind);
    title = kind == Kind::Images ? tr("Export the generated frames of %1").arg(id)
                                 : tr("Export the generated video of %1").arg(id);
    // Generated from the sequence's own alignment, then rendered as for new speech.
    return {title, [request, sequence, options, target, kind](Feedback &feedback) -> TaskRunner::Commit {
        std::shared_ptr<const SpeechToFaceResult> generated;
        {
            Feedback step(feedback, 0.0, 0.1);
            generated = std::make_shared<const SpeechToFaceResult>(
                generateFromPhones(request, sequence.phones, sequence.words, step));
        }
        Feedback step(feedback, 0.1, 1.0);
        return renderWork(generated, options, target, kind == Kind::Images)(step);
    }};
}

// The sequence's features (CSV), alignment (TextGrid) or landmarks (.pts files).
ExportMenu::Job ExportMenu::sequenceDataJob(Kind kind, const QString &path, const Sequence &sequence)
{
    const std::string target = path.toStdString();
    const QString id = QString::fromStdString(sequence.id);
    const QString what = tr("Cannot export");
    QString title;
    TaskRunner::Work work;
    switch (kind) {
    case Kind::Features:
        if (sequence.features.rows() == 0) {
            ErrorReporter::report(m_dialogParent, what, path, tr("%1 has no face features (track it first)").arg(id));
            return {};
        }
        title = tr("Export the features of %1").arg(id);
        work = [sequence, target](Feedback &) -> TaskRunner::Commit {
            writeFeatureCsv(target, sequence.features, {}, sequence.frameRate);
            return {};
        };
        break;
    case Kind::Alignment:
        if (sequence.phones.isEmpty()) {
            ErrorReporter::report(m_dialogParent, what, path, tr("%1 has no phone alignment (align it first)").arg(id));
            return {};
        }
        title = tr("Export the alignment of %1").arg(id);
        work = [sequence, target](Feedback &) -> TaskRunner::Commit {
            std::vector<Tier> tiers;
            if (!sequence.words.isEmpty())
                tiers.push_back(sequence.words);
            tiers.push_back(sequence.phones);
            // The tiers' own extent: no padding interval is added to them.
            writeTextGrid(target, makeTextGrid(tiers, std::max(sequence.phones.endTime(), sequence.words.endTime())));
            return {};
        };
        break;
    case Kind::Landmarks:
        if (sequence.landmarks.empty()) {
            ErrorReporter::report(m_dialogParent, what, path, tr("%1 has no landmarks").arg(id));
            return {};
        }
        title = tr("Export the landmarks of %1").arg(id);
        // One <id>_<frame>.pts per annotated frame (frame numbers from 1, as in the studio).
        work = [sequence, target](Feedback &feedback) -> TaskRunner::Commit {
            if (!QDir().mkpath(QString::fromStdString(target)))
                throw Error("cannot create the folder", target);
            int done = 0;
            for (const auto &[frame, set] : sequence.landmarks) {
                feedback.throwIfCanceled();
                char name[32];
                std::snprintf(name, sizeof name, "_%05d.pts", frame + 1);
                writeLandmarkSet(target + "/" + sequence.id + name, set);
                feedback.setProgress(double(++done) / double(sequence.landmarks.size()));
            }
            return {};
        };
        break;
    default:
        break;
    }
    return {title, std::move(work)};
}

// The project's AAM or a dynamic model, from memory: one made in this session may not be in any
// folder yet.
ExportMenu::Job ExportMenu::modelJob(Kind kind, const QString &path, const QString &modelKind)
{
    const Project &project = m_context->document()->project();
    ModelStore *store = m_context->modelStore();
    const ModelReference *model = dynamicModel(project, modelKind);
    const ModelReference *aam = project.aam();
    const std::string target = path.toStdString();
    const QString what = tr("Cannot export");
    TaskRunner::Work work;
    const ModelReference *reference = kind == Kind::Aam ? aam : model;
    if (!reference) {
        ErrorReporter::report(m_dialogParent, what, path,
                              kind == Kind::Aam ? tr("the project has no AAM")
                                                : tr("the project has no trained dynamic model"));
        return {};
    }
    QString problem;
    const QString title = tr("Export %1").arg(QString::fromStdString(reference->name));
    if (kind == Kind::Aam) {
        const auto model = store->aam(&problem);
        if (model)
            work = [model, target](Feedback &) -> TaskRunner::Commit {
                model->save(target);
                return {};
            };
    } else {
        const QString kindId = QString::fromStdString(reference->kind);
        const auto model = store->dynamicModel(kindId, &problem);
        const std::string aamId = store->recordedAamIdentifier(kindId);
        if (model)
            work = [model, aamId, target](Feedback &) -> TaskRunner::Commit {
                saveModel(*model, target, aamId);
                return {};
            };
    }
    if (!work) {
        ErrorReporter::report(m_dialogParent, what, QString::fromStdString(project.resolve(reference->file)), problem);
        return {};
    }
    return {title, std::move(work)};
}

// The mouth of the new speech the Preview shows, else of the sequence as tracked, as Rhubarb's
// mouth cues or as animation controls; the mapping is learned from the project's frames in the
// worker.
ExportMenu::Job ExportMenu::animationJob(Kind kind, const QString &path, const Sequence &sequence)
{
    const QString what = tr("Cannot export");
    QString problem;
    const auto aam = m_context->modelStore()->aam(&problem);
    if (!aam) {
        ErrorReporter::report(m_dialogParent, what, path,
                              problem.isEmpty() ? tr("the project has no AAM (build one in the Models panel)") : problem);
        return {};
    }
    const auto speech = m_context->shownSpeech();
    const QString id = speech ? m_context->shownSpeechTitle() : QString::fromStdString(sequence.id);
    if (!speech && (sequence.features.rows() == 0 || sequence.phones.isEmpty())) {
        ErrorReporter::report(m_dialogParent, what, path,
                              tr("%1 needs face features and a phone alignment (track and align it first)").arg(id));
        return {};
    }
    const bool cues = kind == Kind::MouthCues;
    // Moho's frames at the clip's own rate, within the 24 to 100 fps Rhubarb allows.
    DatOptions dat;
    dat.frameRate = std::clamp(speech ? speech->frameRate : sequence.frameRate, 24.0, 100.0);
    Project project = m_context->document()->project(); // the worker's copy: frames to learn from
    const std::string target = path.toStdString();
    const QString title = cues ? tr("Export the mouth cues of %1").arg(id) : tr("Export the animation controls of %1").arg(id);
    return {title, [project = std::move(project), aam, speech, sequence, target, cues, dat](Feedback &feedback)
                       -> TaskRunner::Commit {
                feedback.setStatus("learning this person's mouth shapes");
                const MouthMeasurer measurer(*aam);
                // A sequence's track is one the mapping learns from: measured once.
                const auto [mapping, track] = speech ? std::pair(projectMouthMapping(measurer, project),
                                                                 mouthTrackOfGenerated(measurer, *speech))
                                                     : projectMouthMappingAndTrack(measurer, project, sequence);
                feedback.throwIfCanceled();
                feedback.setProgress(0.8);
                if (cues)
                    writeMouthCues(mouthCues(track, mapping), target, dat);
                else
                    writeAnimationControls(animationControls(track, mapping), target);
                return {};
            }};
}

MouthShapesDialog *ExportMenu::mouthShapesDialog() const
{
    return m_shapesDialog;
}

void ExportMenu::showMouthShapes()
{
    if (!m_shapesDialog) {
        m_shapesDialog = new MouthShapesDialog(m_context, m_dialogParent);
        m_shapesDialog->setObjectName(QStringLiteral("mouthShapesDialog"));
    }
    m_shapesDialog->show();
    m_shapesDialog->raise();
    m_shapesDialog->relearn();
}

} // namespace lipsync::studio
