#include "annotate/FacesController.h"

#include "aam/AamBuilder.h"
#include "aam/AamFitter.h"
#include "aam/AutoLandmarks.h"
#include "aam/FaceDetector.h"
#include "aam/FaceTracker.h"
#include "aam/LandmarkScheme.h"
#include "aam/PtsFile.h"
#include "annotate/FrameView.h"
#include "build/ModesView.h"
#include "context/CommandRegistry.h"
#include "context/ErrorReporter.h"
#include "context/ModelStore.h"
#include "context/SequenceMedia.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "io/VideoReader.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"

#include <QAction>
#include <QDir>
#include <QFileInfo>
#include <QInputDialog>
#include <QMenu>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace lipsync::studio {

namespace {

QAction *makeAction(QWidget *owner, const QString &text, const QKeySequence &key)
{
    auto *a = new QAction(text, owner);
    if (!key.isEmpty()) {
        a->setShortcut(key);
        a->setShortcutContext(Qt::WindowShortcut);
        a->setToolTip(QStringLiteral("%1 (%2)").arg(QString(text).remove(QLatin1Char('&')).remove(QStringLiteral("…")),
                                                    key.toString(QKeySequence::NativeText)));
    }
    owner->addAction(a);
    return a;
}

cv::Mat toBgr(const QImage &image)
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
    cv::Mat wrapped(rgb.height(), rgb.width(), CV_8UC3, const_cast<uchar *>(rgb.constBits()),
                    std::size_t(rgb.bytesPerLine()));
    cv::Mat bgr;
    cv::cvtColor(wrapped, bgr, cv::COLOR_RGB2BGR);
    return bgr;
}

bool isUserPoint(const LandmarkPoint &p)
{
    return p.state == PointState::Fixed || p.state == PointState::Placed;
}

// `shape` as automatic points, keeping the points a user placed or fixed in `existing`.
LandmarkSet mergeAutomatic(const std::optional<LandmarkSet> &existing, const Eigen::VectorXd &shape)
{
    LandmarkSet set = landmarkSetFromShape(shape, PointState::Automatic);
    if (existing)
        for (int i = 0; i < LandmarkSet::kPointCount; ++i)
            if (isUserPoint(existing->points[std::size_t(i)]))
                set.points[std::size_t(i)] = existing->points[std::size_t(i)];
    return set;
}

} // namespace

FacesController::FacesController(StudioContext *context, FrameView *view, QWidget *window)
    : QObject(window), m_context(context), m_view(view), m_parent(window)
{
    m_detect = makeAction(window, tr("&Detect Landmarks"), QKeySequence(Qt::CTRL | Qt::Key_D));
    m_copyPrevious = makeAction(window, tr("&Copy Previous Frame's Points"), QKeySequence(Qt::Key_C));
    m_onionSkin = makeAction(window, tr("&Onion Skin of Previous Frame"), QKeySequence(Qt::Key_O));
    m_onionSkin->setCheckable(true);
    m_nextUnlabelled = makeAction(window, tr("Next &Unlabelled Frame"), QKeySequence(Qt::Key_N));
    m_nextWorst = makeAction(window, tr("Next &Worst-Fitted Frame"), QKeySequence(Qt::Key_W));
    m_pickFrames = makeAction(window, tr("&Pick Frames to Label…"), {});
    m_nextPicked = makeAction(window, tr("Next &Picked Frame to Review"), QKeySequence(Qt::SHIFT | Qt::Key_W));
    m_buildAam = makeAction(window, tr("&Build AAM"), {});
    m_trackSequence = makeAction(window, tr("&Track Sequence"), QKeySequence(Qt::CTRL | Qt::Key_T));
    m_trackAll = makeAction(window, tr("Track &All Sequences"), {});
    m_modes = makeAction(window, tr("&Modes of Variation…"), {});

    m_menu = new QMenu(tr("Fa&ces"), window);
    m_menu->addAction(m_detect);
    m_menu->addAction(m_copyPrevious);
    m_menu->addAction(m_onionSkin);
    m_menu->addSeparator();
    m_menu->addAction(m_nextUnlabelled);
    m_menu->addAction(m_nextWorst);
    m_menu->addSeparator();
    m_menu->addAction(m_pickFrames);
    m_menu->addAction(m_nextPicked);
    m_menu->addSeparator();
    m_menu->addAction(m_buildAam);
    m_menu->addAction(m_trackSequence);
    m_menu->addAction(m_trackAll);
    m_menu->addAction(m_modes);

    connect(m_detect, &QAction::triggered, this, [this] { detectLandmarks(); });
    connect(m_copyPrevious, &QAction::triggered, this, [this] { copyPreviousFrame(); });
    connect(m_onionSkin, &QAction::toggled, view, &FrameView::setOnionSkinVisible);
    connect(m_nextUnlabelled, &QAction::triggered, this, &FacesController::nextUnlabelledFrame);
    connect(m_nextWorst, &QAction::triggered, this, &FacesController::nextWorstFrame);
    connect(m_pickFrames, &QAction::triggered, this, [this] {
        const ProjectDocument *doc = m_context->document();
        int frames = 0;
        for (int row = 0; row < doc->sequenceCount(); ++row)
            frames += doc->sequence(row).frameCount;
        const int candidates = std::max(3, frames / FramePickingOptions{}.step);
        bool ok = false;
        const int count = QInputDialog::getInt(
            m_parent, tr("Pick Frames to Label"),
            tr("Frames to pick from the %n clip(s) (an AAM with the paper's 32 parameters wants 100-200):", nullptr,
               doc->sequenceCount()),
            std::min(150, candidates), 3, candidates, 1, &ok);
        if (ok)
            pickFramesToLabel(count);
    });
    connect(m_nextPicked, &QAction::triggered, this, [this] { nextPickedFrame(); });
    connect(context, &StudioContext::sequenceLoaded, this, [this] {
        if (m_pendingFrame >= 0) {
            m_context->setCurrentFrame(std::exchange(m_pendingFrame, -1));
            m_context->showStatus(reviewStatus()); // over the loaded sequence's own message
        }
    });
    connect(m_buildAam, &QAction::triggered, this, [this] { buildAam(); });
    connect(m_trackSequence, &QAction::triggered, this, [this] {
        if (m_context->currentSequence() >= 0)
            trackSequences({m_context->currentSequence()});
    });
    connect(m_trackAll, &QAction::triggered, this, [this] {
        QList<int> rows;
        for (int i = 0; i < m_context->document()->sequenceCount(); ++i)
            rows << i;
        trackSequences(rows);
    });
    connect(m_modes, &QAction::triggered, this, &FacesController::showModes);

    view->setEditable(true);
    connect(view, &FrameView::landmarksEdited, this, [this](const LandmarkSet &set, const QString &what) {
        const int row = m_context->currentSequence();
        if (row < 0 || !m_context->document()->requestLandmarks(row, m_context->currentFrame(), set, what))
            refreshFrame();
    });
    ProjectDocument *doc = context->document();
    connect(doc, &ProjectDocument::documentReset, this, &FacesController::onDocumentReset);
    connect(doc, &ProjectDocument::sequenceChanged, this, &FacesController::onSequenceChanged);
    connect(doc, &ProjectDocument::modelsChanged, this, &FacesController::onModelsChanged);
    connect(context, &StudioContext::currentFrameChanged, this, &FacesController::refreshFrame);
    adoptCommands();
}

FacesController::~FacesController() = default;

void FacesController::updateActions()
{
    m_context->commands()->revalidate();
}

void FacesController::adoptCommands()
{
    CommandRegistry *commands = m_context->commands();
    auto adopt = [&](const char *name, QAction *action, std::function<bool(const StudioContext &)> can) {
        commands->adopt(QLatin1String(name), action, std::move(can), this);
    };
    auto open = [](const StudioContext &c) { return c.document()->isOpen(); };
    // A sequence of sound alone has no face to point at or track.
    auto video = [](const StudioContext &c) { return c.document()->isOpen() && !(c.media() && c.media()->audioOnly); };
    adopt("faces/pick-frames", m_pickFrames, open);
    adopt("faces/build-aam", m_buildAam, open);
    adopt("faces/track-all", m_trackAll, open);
    adopt("faces/modes", m_modes, open);
    adopt("faces/detect", m_detect, video);
    adopt("faces/copy-previous", m_copyPrevious, video);
    adopt("faces/next-unlabelled", m_nextUnlabelled, video);
    adopt("faces/track-sequence", m_trackSequence, video);
    adopt("faces/next-picked", m_nextPicked, [this](const StudioContext &c) {
        return c.document()->isOpen() && !m_review.empty();
    });
    adopt("faces/next-worst", m_nextWorst, [](const StudioContext &c) {
        const ProjectDocument *doc = c.document();
        for (int row = 0; doc->isOpen() && row < doc->sequenceCount(); ++row)
            if (!doc->sequence(row).fitErrors.empty())
                return true;
        return false;
    });
}

void FacesController::onDocumentReset()
{
    m_review.clear();
    m_reviewIndex = -1;
    m_pendingFrame = -1;
    const ModelReference *ref = m_context->document()->project().aam();
    m_aamFile = ref ? ref->file : std::string();
    if (m_modesView)
        m_modesView->setModel(nullptr);
    updateActions();
}

void FacesController::onSequenceChanged(int row)
{
    if (row == m_context->currentSequence())
        refreshFrame();
}

void FacesController::onModelsChanged()
{
    const ModelReference *ref = m_context->document()->project().aam();
    const std::string file = ref ? ref->file : std::string();
    if (file == m_aamFile)
        return; // the AAM in use is still the same
    m_aamFile = file;
    if (ref)
        ensureModel(); // reports a file that does not load
    if (m_modesView)
        m_modesView->setModel(model());
    updateActions();
    refreshFrame();
}

void FacesController::refreshFrame()
{
    FrameView *view = m_view;
    const int row = m_context->currentSequence();
    const int frame = m_context->currentFrame();
    if (row < 0 || row >= m_context->document()->sequenceCount()) {
        view->setLandmarks(std::nullopt);
        view->setOnionSkin(std::nullopt);
        view->setInfoText({});
        return;
    }
    const Sequence &s = m_context->document()->sequence(row);
    const auto it = s.landmarks.find(frame);
    view->setLandmarks(it != s.landmarks.end() ? std::optional<LandmarkSet>(it->second) : std::nullopt);
    const auto prev = s.landmarks.find(frame - 1);
    view->setOnionSkin(prev != s.landmarks.end() ? std::optional<LandmarkSet>(prev->second) : std::nullopt);
    QString info;
    const std::vector<double> &errors = s.fitErrors;
    if (frame >= 0 && frame < int(errors.size()))
        info = errors[std::size_t(frame)] >= 0 ? tr("Fit error %1").arg(errors[std::size_t(frame)], 0, 'f', 4)
                                               : tr("No face found by the tracker");
    view->setInfoText(info);
    updateActions();
}

void FacesController::reportFailure(Task *task, const QString &what)
{
    connect(task, &Task::finished, this, [this, task, what](Task::State state) {
        if (state == Task::State::Failed)
            ErrorReporter::report(m_parent, what, QString(), task->errorMessage());
    });
}

Task *FacesController::detectLandmarks()
{
    const int row = m_context->currentSequence();
    const int frame = m_context->currentFrame();
    const auto media = m_context->media();
    if (row < 0 || !media || media->audioOnly || frame < 0 || frame >= media->frameCount())
        return nullptr;
    const cv::Mat image = toBgr(media->frames[frame]);
    const std::shared_ptr<const AamModel> model = this->model();
    const QString sequenceId = QString::fromStdString(m_context->document()->sequence(row).id);
    Task *task = m_context->taskRunner()->start(
        tr("Detect landmarks in %1, frame %2").arg(sequenceId).arg(frame + 1),
        [this, image, model, row, frame, sequenceId](Feedback &feedback) -> TaskRunner::Commit {
            feedback.setStatus(tr("Finding the face…").toStdString());
            FaceDetector detector;
            feedback.throwIfCanceled();
            const std::vector<FaceDetection> faces = detector.detect(image);
            if (faces.empty())
                throw Error("no face found in frame " + std::to_string(frame + 1) + " (detectors: "
                                + detector.available() + ")",
                            sequenceId.toStdString());
            feedback.setProgress(0.5);
            // dlib's points, else the project's AAM fitted from the detection, else the template:
            // what `lipsync landmarks detect` and Pick Frames to Label place (core/aam/AutoLandmarks).
            std::optional<AamFitter> fitter; // only when dlib cannot place the points
            if (model && !detector.hasDlib())
                fitter.emplace(*model);
            const Eigen::VectorXd shape =
                detectAutoLandmarks(image, faces.front(), detector, AutoLandmarkMethod::Auto, fitter ? &*fitter : nullptr)
                    .shape;
            feedback.setProgress(1.0);
            return [this, shape, row, frame] {
                ProjectDocument *doc = m_context->document();
                if (row >= doc->sequenceCount())
                    return;
                const Sequence &s = doc->sequence(row);
                const auto it = s.landmarks.find(frame);
                const std::optional<LandmarkSet> existing =
                    it != s.landmarks.end() ? std::optional<LandmarkSet>(it->second) : std::nullopt;
                doc->requestLandmarks(row, frame, mergeAutomatic(existing, shape),
                                      tr("Detect landmarks in frame %1").arg(frame + 1));
            };
        });
    reportFailure(task, tr("No landmarks were detected."));
    return task;
}

Task *FacesController::pickFramesToLabel(int count, int step)
{
    const ProjectDocument *doc = m_context->document();
    std::vector<std::string> videos;
    std::vector<int> rows;
    for (int row = 0; row < doc->sequenceCount(); ++row)
        if (doc->sequence(row).frameCount > 0) {
            videos.push_back(doc->mediaPath(row).toStdString());
            rows.push_back(row);
        }
    if (videos.empty())
        return nullptr;
    const std::shared_ptr<const AamModel> model = this->model();
    Task *task = m_context->taskRunner()->start(
        tr("Pick %n frame(s) to label", nullptr, count),
        [this, videos, rows, count, step, model](Feedback &feedback) -> TaskRunner::Commit {
            FramePickingOptions options;
            options.count = count;
            options.step = step;
            options.aam = model.get();
            FaceDetector detector;
            const FramePicking picked = lipsync::pickFramesToLabel(videos, options, detector, feedback);
            struct Pick
            {
                int row, frame;
                Eigen::VectorXd shape;
                double disagreement;
            };
            std::vector<Pick> picks;
            for (const PickedFrame &f : picked.frames)
                picks.push_back({rows[size_t(f.source)], f.frame, f.shape, f.disagreement});
            std::vector<int> order = picked.worstFirst;
            const int candidates = picked.candidates;
            return [this, picks, order, candidates] {
                ProjectDocument *doc = m_context->document();
                std::map<int, ProjectDocument::FaceData> byRow;
                for (const Pick &p : picks) {
                    if (p.row >= doc->sequenceCount())
                        return; // the project changed meanwhile
                    ProjectDocument::FaceData &data = byRow[p.row];
                    if (data.row < 0) {
                        const Sequence &s = doc->sequence(p.row);
                        data = {p.row, s.landmarks, s.features, s.fitErrors};
                    }
                    const auto it = data.landmarks.find(p.frame);
                    const std::optional<LandmarkSet> existing =
                        it != data.landmarks.end() ? std::optional<LandmarkSet>(it->second) : std::nullopt;
                    data.landmarks[p.frame] = mergeAutomatic(existing, p.shape);
                }
                std::vector<ProjectDocument::FaceData> faces;
                for (auto &[row, data] : byRow)
                    faces.push_back(std::move(data));
                doc->requestFaces(faces, tr("Pick %n frame(s) to label", nullptr, int(picks.size())));
                m_review.clear();
                for (int i : order)
                    m_review.push_back({doc->sequence(picks[size_t(i)].row).id, picks[size_t(i)].frame,
                                        picks[size_t(i)].disagreement});
                m_reviewIndex = -1;
                updateActions();
                m_context->showStatus(
                    tr("Picked %1 of %2 frames with a face from %n clip(s); Shift+W shows them, the most doubtful "
                       "first, then Build AAM.",
                       nullptr, int(faces.size()))
                        .arg(picks.size())
                        .arg(candidates),
                    10000);
            };
        });
    reportFailure(task, tr("No frames could be picked."));
    return task;
}

QString FacesController::reviewStatus() const
{
    if (m_reviewIndex < 0 || m_reviewIndex >= int(m_review.size()))
        return {};
    const ReviewItem &item = m_review[size_t(m_reviewIndex)];
    const QString where = tr("Picked frame %1 of %2: %3, frame %4")
                              .arg(m_reviewIndex + 1)
                              .arg(m_review.size())
                              .arg(QString::fromStdString(item.sequenceId))
                              .arg(item.frame + 1);
    if (item.disagreement < 0)
        return where + tr(" (fit not measured)");
    // normalisedMeanError (core/aam/LandmarkScheme.h): the mean point distance over the distance
    // between the outer eye corners.
    return where + tr("; an AAM built without it moves its points by %1 % of the eye distance (most doubtful first)")
                       .arg(100.0 * item.disagreement, 0, 'f', 1);
}

bool FacesController::nextPickedFrame()
{
    if (m_review.empty())
        return false;
    m_reviewIndex = (m_reviewIndex + 1) % int(m_review.size());
    const std::string &id = m_review[size_t(m_reviewIndex)].sequenceId;
    const int frame = m_review[size_t(m_reviewIndex)].frame;
    m_context->showStatus(reviewStatus());
    const ProjectDocument *doc = m_context->document();
    for (int row = 0; row < doc->sequenceCount(); ++row) {
        if (doc->sequence(row).id != id)
            continue;
        if (row == m_context->currentSequence() && m_context->media()) {
            m_context->setCurrentFrame(frame);
        } else {
            m_pendingFrame = frame;
            m_context->selectSequence(row);
        }
        return true;
    }
    return false;
}

bool FacesController::copyPreviousFrame()
{
    const int row = m_context->currentSequence();
    const int frame = m_context->currentFrame();
    if (row < 0 || frame <= 0)
        return false;
    const Sequence &s = m_context->document()->sequence(row);
    // The nearest labelled frame before this one.
    auto it = s.landmarks.lower_bound(frame);
    if (it == s.landmarks.begin())
        return false;
    --it;
    LandmarkSet copy = it->second;
    for (LandmarkPoint &p : copy.points)
        if (p.isDefined())
            p.state = PointState::Automatic; // not confirmed on this frame until the user touches it
    return m_context->document()->requestLandmarks(row, frame, copy,
                                                  tr("Copy points of frame %1 to frame %2").arg(it->first + 1).arg(frame + 1));
}

void FacesController::nextUnlabelledFrame()
{
    const int row = m_context->currentSequence();
    const auto media = m_context->media();
    if (row < 0 || !media || media->frameCount() == 0)
        return;
    const Sequence &s = m_context->document()->sequence(row);
    const int n = media->frameCount();
    for (int k = 1; k <= n; ++k) {
        const int f = (m_context->currentFrame() + k) % n;
        const auto it = s.landmarks.find(f);
        if (it == s.landmarks.end() || !it->second.isComplete()) {
            m_context->setCurrentFrame(f);
            return;
        }
    }
    m_context->showStatus(tr("Every frame of this sequence is labelled."), 4000);
}

void FacesController::nextWorstFrame()
{
    const int row = m_context->currentSequence();
    if (row < 0)
        return;
    const std::vector<double> &errors = m_context->document()->sequence(row).fitErrors;
    if (errors.empty()) {
        m_context->showStatus(tr("Track this sequence first to rank its frames by fit error."), 4000);
        return;
    }
    // Frames by falling fit error (no face first): W starts at the worst and, pressed again on the
    // frame it went to, walks down that queue.
    std::vector<int> order(errors.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = int(i);
    auto key = [&](int f) { return errors[std::size_t(f)] < 0 ? 1e300 : errors[std::size_t(f)]; };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key(a) > key(b); });
    const int current = m_context->currentFrame();
    int rank = 0;
    if (m_worstRank >= 0 && m_worstRank < int(order.size()) && order[std::size_t(m_worstRank)] == current)
        rank = (m_worstRank + 1) % int(order.size());
    m_worstRank = rank;
    m_context->setCurrentFrame(order[std::size_t(rank)]);
}

std::shared_ptr<const AamModel> FacesController::model() const
{
    return m_context->modelStore()->aam();
}

bool FacesController::ensureModel()
{
    QString problem;
    if (m_context->modelStore()->aam(&problem))
        return true;
    if (const ModelReference *ref = m_context->document()->project().aam())
        ErrorReporter::report(m_parent, tr("The project's AAM could not be loaded."),
                              QString::fromStdString(m_context->document()->project().resolve(ref->file)), problem);
    return false;
}

Task *FacesController::buildAam()
{
    ProjectDocument *doc = m_context->document();
    struct Labelled
    {
        std::string media;
        std::string name;
        int frame;
        Eigen::VectorXd shape;
    };
    std::vector<Labelled> labelled;
    for (int row = 0; row < doc->sequenceCount(); ++row) {
        const Sequence &s = doc->sequence(row);
        for (const auto &[frame, set] : s.landmarks)
            if (set.isComplete())
                labelled.push_back({doc->mediaPath(row).toStdString(), s.id + " frame " + std::to_string(frame + 1),
                                    frame, shapeFromLandmarkSet(set)});
    }
    if (labelled.size() < 3) {
        ErrorReporter::report(m_parent, tr("An AAM needs at least 3 frames with all 23 points; this project has %1.")
                                            .arg(labelled.size()),
                              QString(), tr("Label more frames (Detect Landmarks, then correct the points)."));
        return nullptr;
    }
    // One AAM in use per project: building again replaces its reference, with a file of its own so
    // that undoing the build brings back the previous AAM.
    const QString name = QStringLiteral("faces");
    const QString file = m_context->modelStore()->reserveFile(QStringLiteral("aam"));
    const QString target = m_context->modelStore()->writablePath(file);
    Task *task = m_context->taskRunner()->start(
        tr("Build AAM from %n frame(s)", "", int(labelled.size())),
        [this, labelled, name, file, target](Feedback &feedback) -> TaskRunner::Commit {
            feedback.setStatus(tr("Reading the labelled frames…").toStdString());
            std::vector<AamTrainingExample> examples;
            std::map<std::string, std::unique_ptr<VideoReader>> readers;
            for (std::size_t i = 0; i < labelled.size(); ++i) {
                feedback.throwIfCanceled();
                const Labelled &l = labelled[i];
                auto &reader = readers[l.media];
                if (!reader)
                    reader = std::make_unique<VideoReader>(l.media);
                examples.push_back({l.name, {}, reader->frame(l.frame), l.shape});
                feedback.setProgress(0.2 * double(i + 1) / double(labelled.size()));
            }
            readers.clear();
            FaceDetector detector(FaceDetectorPaths::boxesOnly());
            AamBuildOptions options;
            if (detector.hasYunet() || detector.hasHaar())
                options.detector = &detector;
            Feedback sub(feedback, 0.2, 0.95);
            std::vector<std::string> warnings;
            auto model = std::make_shared<AamModel>(lipsync::buildAam(std::move(examples), options, sub, &warnings));
            if (!target.isEmpty()) {
                QDir().mkpath(QFileInfo(target).absolutePath());
                model->save(target.toStdString());
            }
            feedback.setProgress(1.0);
            return [this, model, name, file, target, warnings] {
                m_context->modelStore()->addAam(file, model, !target.isEmpty());
                m_context->document()->requestAddModel({"aam", name.toStdString(), file.toStdString()},
                                                      tr("Build AAM %1").arg(name));
                m_context->showStatus(
                    tr("AAM %1 built from %2 frames: %3 combined modes%4")
                        .arg(name)
                        .arg(model->trainingImages)
                        .arg(model->combinedModes())
                        .arg(warnings.empty() ? QString() : tr(" (%n frame(s) skipped)", "", int(warnings.size()))),
                    8000);
                updateActions();
            };
        });
    reportFailure(task, tr("The AAM could not be built."));
    connect(task, &Task::finished, this, [this, file](Task::State state) {
        if (state != Task::State::Finished)
            m_context->modelStore()->releaseFile(file);
    });
    return task;
}

Task *FacesController::trackSequences(const QList<int> &rows)
{
    if (rows.isEmpty())
        return nullptr;
    if (!ensureModel()) {
        // A project's AAM that failed to load has been reported (file and reason) by ensureModel.
        if (!m_context->document()->project().aam())
            ErrorReporter::report(m_parent, tr("Tracking needs an AAM."), QString(),
                                  tr("Label a few frames and choose Faces ▸ Build AAM first."));
        return nullptr;
    }
    ProjectDocument *doc = m_context->document();
    struct Job
    {
        int row;
        QString id;
        std::string media;
        int frameCount;
        std::map<int, LandmarkSet> landmarks;
    };
    std::vector<Job> jobs;
    for (int row : rows) {
        const Sequence &s = doc->sequence(row);
        jobs.push_back({row, QString::fromStdString(s.id), doc->mediaPath(row).toStdString(), s.frameCount, s.landmarks});
    }
    const std::shared_ptr<const AamModel> model = this->model();
    const QString title = jobs.size() == 1 ? tr("Track %1").arg(jobs.front().id) : tr("Track %n sequence(s)", "", int(jobs.size()));
    Task *task = m_context->taskRunner()->start(title, [this, jobs, model, title](Feedback &feedback) -> TaskRunner::Commit {
        FaceDetector detector(FaceDetectorPaths::boxesOnly());
        std::vector<ProjectDocument::FaceData> results;
        for (std::size_t j = 0; j < jobs.size(); ++j) {
            const Job &job = jobs[j];
            feedback.setStatus(job.id.toStdString());
            VideoReader video(job.media);
            FaceTracker tracker(*model, detector.hasYunet() || detector.hasHaar() ? &detector : nullptr);
            const int n = job.frameCount;
            Eigen::MatrixXd features = Eigen::MatrixXd::Zero(n, model->combinedModes());
            std::map<int, LandmarkSet> landmarks = job.landmarks;
            std::vector<double> frameErrors(std::size_t(n), Sequence::kNoFace);
            bool any = false;
            for (int f = 0; f < n; ++f) {
                feedback.throwIfCanceled();
                feedback.setProgress((double(j) + double(f) / n) / double(jobs.size()));
                const cv::Mat image = f < video.frameCount() ? video.frame(f) : cv::Mat();
                const auto existing = landmarks.find(f);
                std::optional<LandmarkSet> before;
                if (existing != landmarks.end())
                    before = existing->second;
                AamFitOptions options;
                if (before) {
                    options.fixedShape = shapeFromLandmarkSet(*before);
                    options.fixedMask.assign(std::size_t(LandmarkSet::kPointCount), false);
                    bool anyFixed = false;
                    for (int i = 0; i < LandmarkSet::kPointCount; ++i) {
                        const bool user = isUserPoint(before->points[std::size_t(i)]);
                        options.fixedMask[std::size_t(i)] = user;
                        anyFixed = anyFixed || user;
                    }
                    if (!anyFixed) {
                        options.fixedShape = {};
                        options.fixedMask.clear();
                    }
                }
                TrackedFrame tracked;
                if (!image.empty())
                    tracked = tracker.track(image, options);
                if (!tracked.found) {
                    if (!image.empty())
                        tracker.reset();
                    if (f > 0)
                        features.row(f) = features.row(f - 1); // a gap holds the last face
                    continue;
                }
                any = true;
                features.row(f) = tracked.features.transpose();
                frameErrors[std::size_t(f)] = tracked.fit.error;
                landmarks[f] = mergeAutomatic(before, tracked.fit.shape);
            }
            if (!any)
                throw Error("no face found in any of the " + std::to_string(n) + " frames", job.media);
            // Frames before the first face take its features.
            int first = 0;
            while (first < n && frameErrors[std::size_t(first)] < 0)
                ++first;
            for (int f = 0; f < first; ++f)
                features.row(f) = features.row(first);
            results.push_back({job.row, std::move(landmarks), std::move(features), std::move(frameErrors)});
        }
        feedback.setProgress(1.0);
        return [this, results, title] {
            m_context->document()->requestFaces(results, title);
            refreshFrame();
        };
    });
    reportFailure(task, tr("Tracking failed."));
    return task;
}

void FacesController::showModes()
{
    ensureModel();
    if (!m_modesView) {
        m_modesView = new ModesView(m_parent);
        m_modesView->setAttribute(Qt::WA_DeleteOnClose);
    }
    m_modesView->setModel(model());
    m_modesView->show();
    m_modesView->raise();
}

} // namespace lipsync::studio
