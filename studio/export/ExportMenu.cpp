#include "export/ExportMenu.h"

#include "app/ErrorReporter.h"
#include "app/MainWindow.h"
#include "app/ModelKinds.h"
#include "app/ProjectDocument.h"

#include "aam/PtsFile.h"
#include "io/AtomicFile.h"
#include "io/FeatureCsv.h"
#include "io/TextGrid.h"
#include "render/FaceRenderer.h"
#include "render/SpeechToFace.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QAction>
#include <QDir>
#include <QFileDialog>
#include <QInputDialog>
#include <QStatusBar>
#include <QFileInfo>
#include <QMenu>

#include <array>
#include <cstdio>
#include <utility>

namespace lipsync::studio {

namespace {

// The project's trained dynamic model of `kind`, or by default the first of the studio's order
// (the paper's DPDS first).
const ModelReference *dynamicModel(const Project &project, const QString &kind = {})
{
    if (!kind.isEmpty())
        return project.model(kind.toStdString());
    for (const QString &k : ModelKinds::ids())
        if (const ModelReference *m = project.model(k.toStdString()))
            return m;
    return nullptr;
}

bool usesDynamicModel(ExportMenu::Kind kind)
{
    return kind == ExportMenu::Kind::Video || kind == ExportMenu::Kind::SideBySide
           || kind == ExportMenu::Kind::Images || kind == ExportMenu::Kind::Model;
}

void copyFileAtomically(const std::string &from, const std::string &to)
{
    writeFileAtomically(to, readWholeFile(from));
}

} // namespace

ExportMenu::ExportMenu(MainWindow *window, QMenu *parentMenu)
    : QObject(window), m_window(window), m_menu(parentMenu->addMenu(tr("E&xport")))
{
    const std::array<QString, 8> titles = {
        tr("Generated &Video (MP4)…"),          tr("Real and Generated &Side by Side (MP4)…"),
        tr("Generated &Frames (PNG)…"),         tr("F&eatures (CSV)…"),
        tr("&Alignment (TextGrid)…"),           tr("&Landmarks (.pts)…"),
        tr("Active Appearance &Model…"),        tr("&Trained Dynamic Model…")};
    for (size_t i = 0; i < titles.size(); ++i) {
        if (i == 3 || i == 6)
            m_menu->addSeparator();
        QAction *action = m_menu->addAction(titles[i]);
        const Kind kind = Kind(i);
        connect(action, &QAction::triggered, this, [this, kind] { trigger(kind); });
        m_actions.append(action);
    }
    connect(m_menu, &QMenu::aboutToShow, this, &ExportMenu::updateActions);
    m_modelPrompt = [this](const QStringList &kinds, const QStringList &names) {
        bool ok = false;
        const QString name = QInputDialog::getItem(m_window, tr("Export"), tr("Which trained model?"), names, 0,
                                                   false, &ok);
        return ok ? kinds.value(names.indexOf(name)) : QString();
    };
    m_prompt = [this](const PathRequest &request) {
        if (request.filter.isEmpty())
            return QFileDialog::getExistingDirectory(m_window, request.title, request.suggestedPath);
        return QFileDialog::getSaveFileName(m_window, request.title, request.suggestedPath, request.filter);
    };
}

QAction *ExportMenu::action(Kind kind) const
{
    return m_actions.value(int(kind));
}

void ExportMenu::updateActions()
{
    const ProjectDocument *document = m_window->document();
    const int row = m_window->currentSequence();
    const bool hasSequence = row >= 0 && row < document->sequenceCount();
    const Project &project = document->project();
    const bool canGenerate = hasSequence && dynamicModel(project) && project.model("aam");
    action(Kind::Video)->setEnabled(canGenerate);
    action(Kind::SideBySide)->setEnabled(canGenerate);
    action(Kind::Images)->setEnabled(canGenerate);
    action(Kind::Features)->setEnabled(hasSequence && document->sequence(row).features.rows() > 0);
    action(Kind::Alignment)->setEnabled(hasSequence && !document->sequence(row).phones.isEmpty());
    action(Kind::Landmarks)->setEnabled(hasSequence && !document->sequence(row).landmarks.empty());
    action(Kind::Aam)->setEnabled(project.model("aam") != nullptr);
    action(Kind::Model)->setEnabled(dynamicModel(project) != nullptr);
}

Task *ExportMenu::trigger(Kind kind)
{
    const ProjectDocument *document = m_window->document();
    const int row = m_window->currentSequence();
    const QString stem = row >= 0 && row < document->sequenceCount()
                             ? QString::fromStdString(document->sequence(row).id)
                             : QStringLiteral("export");
    const QString folder = QDir::homePath();
    // Several trained models: the user picks one (never a silent default).
    QString modelKind;
    if (usesDynamicModel(kind)) {
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
    const std::array<std::pair<QString, QString>, 8> targets = {{
        {stem + "-generated" + modelSuffix + ".mp4", tr("MP4 video (*.mp4)")},
        {stem + "-side-by-side" + modelSuffix + ".mp4", tr("MP4 video (*.mp4)")},
        {stem + "-frames" + modelSuffix, QString()},
        {stem + ".csv", tr("Feature tables (*.csv)")},
        {stem + ".TextGrid", tr("Praat TextGrid (*.TextGrid)")},
        {stem + "-landmarks", QString()},
        {QStringLiteral("model.aam"), tr("Active appearance models (*.aam)")},
        {(modelKind.isEmpty() ? QStringLiteral("dynamics") : modelKind) + QStringLiteral(".model"),
         tr("Dynamic models (*.model)")},
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
    const ProjectDocument *document = m_window->document();
    const Project &project = document->project();
    const int row = m_window->currentSequence();
    const bool projectWide = kind == Kind::Aam || kind == Kind::Model;
    const QString what = tr("Cannot export");
    if (!projectWide && (row < 0 || row >= document->sequenceCount())) {
        ErrorReporter::report(m_window, what, path, tr("no sequence is selected"));
        return nullptr;
    }
    // Everything the worker needs is copied here, on the GUI thread: it never reads the document.
    const Sequence sequence = projectWide ? Sequence() : document->sequence(row);
    const ModelReference *model = dynamicModel(project, modelKind);
    const ModelReference *aam = project.model("aam");
    const std::string target = path.toStdString();
    const QString id = QString::fromStdString(sequence.id);
    TaskRunner::Work work;
    QString title;
    switch (kind) {
    case Kind::Video:
    case Kind::SideBySide:
    case Kind::Images: {
        if (!model || !aam) {
            ErrorReporter::report(m_window, what, path,
                                  tr("the project has no trained dynamic model and AAM (train one in the "
                                     "Models panel)"));
            return nullptr;
        }
        SpeechToFaceRequest request;
        request.mediaPath = project.mediaPath(sequence);
        request.modelPath = project.resolve(model->file);
        request.aamPath = project.resolve(aam->file);
        request.frameRate = sequence.frameRate;
        RenderOptions options;
        options.sideBySide = kind == Kind::SideBySide;
        if (options.sideBySide) {
            options.leftLabel = "real";
            // The panel labels are drawn in ASCII: the model's name, else its id.
            const QString name = ModelKinds::name(model->kind);
            bool ascii = true;
            for (QChar c : name)
                ascii = ascii && c.unicode() < 0x80;
            options.rightLabel = ascii ? name.toStdString() : model->kind;
        }
        title = kind == Kind::Images ? tr("Export the generated frames of %1").arg(id)
                                     : tr("Export the generated video of %1").arg(id);
        work = [request, options, sequence, target, kind](Feedback &feedback) -> TaskRunner::Commit {
            SpeechToFaceResult generated;
            {
                Feedback step(feedback, 0.0, 0.1);
                generated = generateFromPhones(request, sequence.phones, sequence.words, step);
            }
            std::unique_ptr<FaceRenderer> renderer;
            {
                Feedback step(feedback, 0.1, 0.3);
                renderer = makeRenderer(generated, request.mediaPath, step);
            }
            Feedback step(feedback, 0.3, 1.0);
            if (kind == Kind::Images)
                exportRenderedImages(generated, *renderer, target, step, options);
            else
                exportRenderedVideo(generated, *renderer, target, step, options);
            return {};
        };
        break;
    }
    case Kind::Features:
        if (sequence.features.rows() == 0) {
            ErrorReporter::report(m_window, what, path, tr("%1 has no face features (track it first)").arg(id));
            return nullptr;
        }
        title = tr("Export the features of %1").arg(id);
        work = [sequence, target](Feedback &) -> TaskRunner::Commit {
            writeFeatureCsv(target, sequence.features, {}, sequence.frameRate);
            return {};
        };
        break;
    case Kind::Alignment:
        if (sequence.phones.isEmpty()) {
            ErrorReporter::report(m_window, what, path, tr("%1 has no phone alignment (align it first)").arg(id));
            return nullptr;
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
            ErrorReporter::report(m_window, what, path, tr("%1 has no landmarks").arg(id));
            return nullptr;
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
    case Kind::Aam:
    case Kind::Model: {
        const ModelReference *reference = kind == Kind::Aam ? aam : model;
        if (!reference) {
            ErrorReporter::report(m_window, what, path,
                                  kind == Kind::Aam ? tr("the project has no AAM")
                                                    : tr("the project has no trained dynamic model"));
            return nullptr;
        }
        const std::string source = project.resolve(reference->file);
        title = tr("Export %1").arg(QString::fromStdString(reference->name));
        work = [source, target](Feedback &) -> TaskRunner::Commit {
            copyFileAtomically(source, target);
            return {};
        };
        break;
    }
    }
    Task *task = m_window->taskRunner()->start(title, std::move(work));
    connect(task, &Task::finished, this, [this, task, path, what](Task::State state) {
        if (state == Task::State::Finished) {
            m_window->statusBar()->showMessage(tr("Exported to %1").arg(QDir::toNativeSeparators(path)), 15000);
            emit exported(path);
        }
        else if (state == Task::State::Failed)
            ErrorReporter::report(m_window, what, path, task->errorMessage());
    });
    return task;
}

} // namespace lipsync::studio
