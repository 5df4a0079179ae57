#include "build/ModelsPanel.h"

#include "aam/AamModel.h"
#include "align/ProjectAligner.h"
#include "animation/MouthMeasures.h"
#include "animation/MouthShapePrior.h"
#include "context/ErrorReporter.h"
#include "context/ModelKinds.h"
#include "context/ModelStore.h"
#include "context/StudioContext.h"
#include "document/ProjectDocument.h"
#include "dynamics/BrandModel.h"
#include "dynamics/ContextDependentModel.h"
#include "dynamics/DynamicModel.h"
#include "dynamics/ModelFile.h"
#include "dynamics/PhoneCoverage.h"
#include "dynamics/PhoneLabels.h"
#include "eval/Evaluation.h"
#include "eval/RealismReport.h"
#include "plots/EvaluationChart.h"
#include "plots/ObjectivePlot.h"
#include "plots/ResultsPage.h"
#include "plots/TrajectoryView.h"
#include "project/Project.h"
#include "tasks/Feedback.h"
#include "tasks/TaskRunner.h"
#include "util/Error.h"
#include "util/ResourceLocator.h"
#include "widgets/ElidedLabel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDir>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSpinBox>
#include <QTabWidget>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <QSignalBlocker>

#include <algorithm>
#include <chrono>
#include <mutex>

namespace lipsync::studio {

namespace {

QString kindText(const std::string &kind)
{
    if (kind == "aam") return ModelsPanel::tr("Appearance model");
    if (kind == "aligner") return ModelsPanel::tr("Phoneme aligner");
    return ModelKinds::name(kind);
}

// What a trained dynamic model is beyond its kind: its states, Brand's full covariances, its
// compensation and whether it started from other speakers (§5.4).
QString modelSummary(const DynamicModel &model)
{
    const auto *context = dynamic_cast<const ContextDependentModel *>(&model);
    // At least one state per phone, so always a plural.
    QString states = context ? ModelsPanel::tr("%1 states for phones in context").arg(context->tree().stateCount())
                             : ModelsPanel::tr("one state per phone");
    const auto *brand = dynamic_cast<const BrandModel *>(context ? &context->inner() : &model);
    if (brand && brand->fullCovariance())
        states = ModelsPanel::tr("%1, full covariances").arg(states);
    QString summary = model.compensatesVariance()
                          ? ModelsPanel::tr("%1 parameters, %2, variance compensation").arg(model.dimension()).arg(states)
                          : ModelsPanel::tr("%1 parameters, %2").arg(model.dimension()).arg(states);
    return model.startedFromOtherSpeakers() ? ModelsPanel::tr("%1, started from other speakers").arg(summary) : summary;
}

} // namespace

// The kinds with their options, one row each, then the options of every kind.
QGridLayout *ModelsPanel::optionsGrid()
{
    auto *grid = new QGridLayout;
    grid->setContentsMargins(0, 0, 0, 0);
    m_dpdsOptimizer->addItem(tr("VarPro / Levenberg–Marquardt"), QStringLiteral("lm"));
    m_dpdsOptimizer->addItem(tr("Gradient ascent (paper)"), QStringLiteral("gradient"));
    m_sldsA->addItem(tr("Diagonal A"), false);
    m_sldsA->addItem(tr("Full A"), true);
    // Brand: the covariance chosen by cross-validation on the training sequences (docs/models.md §2.1).
    m_brandCovariance->setObjectName(QStringLiteral("brandCovariance"));
    m_brandCovariance->addItem(tr("Covariance by CV"), int(BrandCovariance::CrossValidated));
    m_brandCovariance->addItem(tr("Diagonal covariance"), int(BrandCovariance::Diagonal));
    m_brandCovariance->addItem(tr("Full covariance"), int(BrandCovariance::Full));
    m_brandCovariance->setToolTip(
        tr("Brand's output covariances. By CV: diagonal or full, whichever of the two generates held-out "
           "training sequences more closely (cross-validation). Diagonal: the paper's model."));
    const QHash<QString, QWidget *> options{{QString::fromLatin1(modelKindId(ModelKind::Dpds)), m_dpdsOptimizer},
                                            {QString::fromLatin1(modelKindId(ModelKind::Slds)), m_sldsA},
                                            {QString::fromLatin1(modelKindId(ModelKind::Brand)), m_brandCovariance}};
    const QStringList &kinds = ModelKinds::ids();
    for (int i = 0; i < kinds.size(); ++i) {
        auto *check = new QCheckBox(ModelKinds::name(kinds[i]), this);
        check->setObjectName(QStringLiteral("train_%1").arg(kinds[i]));
        check->setToolTip(ModelKinds::description(kinds[i]));
        check->setChecked(true);
        m_kinds.insert(kinds[i], check);
        grid->addWidget(check, i, 0);
        if (QWidget *option = options.value(kinds[i]))
            grid->addWidget(option, i, 1);
    }
    // Every kind: generated lips that move as much as the recorded ones (docs/models.md §5.1).
    m_compensateVariance->setObjectName(QStringLiteral("compensateVariance"));
    m_compensateVariance->setChecked(true);
    m_compensateVariance->setToolTip(
        tr("Scale each model's generated trajectories to the spread of the training features: lips that "
           "open and close as much as the recording's, at the cost of a larger error per frame. Off: the "
           "paper's models exactly."));
    grid->addWidget(m_compensateVariance, int(kinds.size()), 0);
    // Every kind: states for phones in context, tied by decision trees (docs/models.md §5.2).
    m_contextStates->setObjectName(QStringLiteral("contextStates"));
    m_contextStates->setChecked(true);
    m_contextStates->setToolTip(
        tr("Train each model on states for phones in their context (the neighbouring phones and the part "
           "of the phone), tied by decision trees: lips that anticipate the next sound. Off: one state per "
           "phone, the paper's models exactly."));
    grid->addWidget(m_contextStates, int(kinds.size()), 1);
    // HMM-mean and Brand: each phone's mouth learnt on other speakers, for little footage (§5.4).
    m_prior->setObjectName(QStringLiteral("mouthPrior"));
    m_prior->setToolTip(
        tr("For a person with little footage: HMM-mean's and Brand's mouth for each sound starts from the "
           "mouths of other speakers (GRID s1), carried onto this face, and moves to the person's own as their "
           "frames of that sound add up; how much the other speakers weigh is chosen on the person's own clips. "
           "Used by Train and Realism."));
    grid->addWidget(m_prior, int(kinds.size()) + 1, 0, 1, 2);
    // The paper preset (docs/models.md §8): every choice beyond the paper off, held off.
    m_paper->setObjectName(QStringLiteral("paperModels"));
    m_paper->setToolTip(
        tr("Train and evaluate the paper's models exactly: no compensation or phones in context, Brand with "
           "diagonal covariances, the DPDS by the paper's Algorithm 1 and gradient ascent without the variance "
           "prior; Realism renders without lip closure, colour matching or exemplar detail."));
    grid->addWidget(m_paper, int(kinds.size()) + 2, 0, 1, 2);
    connect(m_paper, &QCheckBox::toggled, this, &ModelsPanel::applyPaperPreset);
    return grid;
}

ModelsPanel::ModelsPanel(QWidget *parent)
    : QWidget(parent), m_list(new QTreeWidget(this)), m_buildAam(new QPushButton(tr("Build AAM…"), this)),
      m_train(new QPushButton(tr("Train"), this)), m_cancel(new QPushButton(tr("Cancel"), this)),
      m_evaluate(new QPushButton(tr("Evaluate (k-fold)"), this)), m_realism(new QPushButton(tr("Realism"), this)),
      m_dpdsOptimizer(new QComboBox(this)),
      m_sldsA(new QComboBox(this)), m_brandCovariance(new QComboBox(this)),
      m_compensateVariance(new QCheckBox(tr("Variance compensation"), this)),
      m_contextStates(new QCheckBox(tr("Phones in context"), this)),
      m_prior(new QCheckBox(tr("Start from other speakers"), this)), m_paper(new QCheckBox(tr("Paper's models"), this)), m_folds(new QSpinBox(this)),
      m_parameter(new QSpinBox(this)), m_status(new ElidedLabel(this))
{
    // The models and their options scroll; the actions and the status below them hold still
    // (always in view, never moved by models added or a longer status).
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->setSpacing(3);
    auto *scroll = new QScrollArea(this);
    scroll->setObjectName(QStringLiteral("modelsScroll"));
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    auto *optionsPage = new QWidget(scroll);
    auto *optionsLayout = new QVBoxLayout(optionsPage);
    optionsLayout->setContentsMargins(0, 0, 0, 0);
    m_list->setHeaderLabels({tr("Model"), tr("Kind"), tr("File")});
    m_list->setRootIsDecorated(false);
    m_list->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_list->header()->setStretchLastSection(false);
    m_list->setMinimumHeight(3 * fontMetrics().height() + 8);
    optionsLayout->addWidget(m_list, 1);

    optionsLayout->addLayout(optionsGrid());
    scroll->setWidget(optionsPage);
    // No least height of its own: a tall timeline (the spectrogram's) may squeeze the list away,
    // never the actions below it.
    scroll->setMinimumHeight(1);
    scroll->setMinimumWidth(optionsPage->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width());
    layout->addWidget(scroll, 1);

    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_buildAam);
    buttons->addWidget(m_train);
    buttons->addWidget(m_cancel);
    buttons->addStretch();
    layout->addLayout(buttons);
    auto *evaluation = new QHBoxLayout;
    m_folds->setRange(2, 100);
    m_folds->setValue(10);
    m_folds->setPrefix(tr("folds: "));
    evaluation->addWidget(m_evaluate);
    evaluation->addWidget(m_folds);
    evaluation->addWidget(m_realism);
    evaluation->addStretch();
    layout->addLayout(evaluation);
    m_status->setObjectName(QStringLiteral("modelsStatus"));
    layout->addWidget(m_status);

    m_buildAam->setEnabled(false); // until attached to the Faces menu's action
    m_buildAam->setToolTip(tr("Build an Active Appearance Model from the labelled frames (Faces menu)."));
    m_train->setToolTip(tr("Train the checked models on every sequence with features and phonemes"));
    m_cancel->setToolTip(tr("Stop training or evaluation; the previous models stay"));
    m_evaluate->setToolTip(tr("k-fold cross-validation of the checked models (the paper's Figure 4)"));
    connect(m_train, &QPushButton::clicked, this, [this] { train(); });
    connect(m_cancel, &QPushButton::clicked, this, &ModelsPanel::cancel);
    connect(m_evaluate, &QPushButton::clicked, this, [this] { evaluate(); });
    m_realism->setObjectName(QStringLiteral("realismButton"));
    m_realism->setToolTip(tr("Render the held-out sequences of the same folds into their recordings and measure the lips "
                             "with dlib's landmarks: opening correlation, articulation, /p b m/ closures, lag, sharpness, "
                             "seam"));
    connect(m_realism, &QPushButton::clicked, this, [this] { evaluateRealism(); });
    updateActions();
}

ModelsPanel::~ModelsPanel() = default;

void ModelsPanel::setBuildAamAction(QAction *buildAam)
{
    // The button is another trigger of the Faces menu's action, so both stay in one state.
    m_buildAam->setEnabled(buildAam->isEnabled());
    connect(buildAam, &QAction::changed, m_buildAam, [this, buildAam] { m_buildAam->setEnabled(buildAam->isEnabled()); });
    connect(m_buildAam, &QPushButton::clicked, buildAam, &QAction::trigger);
}

void ModelsPanel::attach(StudioContext *context, QTabWidget *plots)
{
    m_context = context;
    m_plots = plots;
    m_trajectoryPage = new QWidget(plots);
    auto *page = new QVBoxLayout(m_trajectoryPage);
    page->setContentsMargins(0, 0, 0, 0);
    auto *row = new QHBoxLayout;
    row->setContentsMargins(4, 2, 4, 0);
    m_parameter->setParent(m_trajectoryPage);
    m_parameter->setRange(0, 0);
    m_parameter->setPrefix(tr("AAM parameter "));
    m_parameter->setToolTip(tr("Which AAM parameter to plot over time"));
    row->addWidget(m_parameter);
    row->addStretch();
    page->addLayout(row);
    m_trajectory = new TrajectoryView(m_trajectoryPage);
    m_trajectory->setObjectName(QStringLiteral("trajectoryView"));
    page->addWidget(m_trajectory, 1);
    m_objective = new ObjectivePlot(plots);
    m_objective->setObjectName(QStringLiteral("objectivePlot"));
    // The k-fold errors and the realism report each keep their page: one does not replace the other.
    m_evaluation = new ResultsPage(tr("Not evaluated yet: Evaluate (k-fold) in the Models panel draws the paper's "
                                      "Figure 4 for the checked models."),
                                   plots);
    m_evaluation->setObjectName(QStringLiteral("evaluationPage"));
    m_evaluation->chart()->setObjectName(QStringLiteral("evaluationChart"));
    m_realismPage = new ResultsPage(tr("Not measured yet: Realism in the Models panel renders held-out sequences and "
                                   "measures the lips on them."),
                                plots);
    m_realismPage->setObjectName(QStringLiteral("realismPage"));
    m_realismPage->chart()->setObjectName(QStringLiteral("realismChart"));
    plots->addTab(m_trajectoryPage, tr("Trajectory"));
    plots->addTab(m_objective, tr("Training"));
    plots->addTab(m_evaluation, tr("Evaluation"));
    plots->addTab(m_realismPage, tr("Realism"));

    ProjectDocument *doc = context->document();
    connect(doc, &ProjectDocument::documentReset, this, &ModelsPanel::onDocumentReset);
    connect(doc, &ProjectDocument::locationChanged, this, &ModelsPanel::onLocationChanged);
    connect(doc, &ProjectDocument::modelsChanged, this, [this] {
        setProject(m_context->document()->project());
        refreshTrajectory();
    });
    connect(context, &StudioContext::lipClosureChanged, this, &ModelsPanel::refreshTrajectory);
    connect(doc, &ProjectDocument::sequenceChanged, this, [this](int row) {
        if (m_context && row == m_context->currentSequence())
            refreshTrajectory();
        updateActions();
    });
    connect(context, &StudioContext::sequenceLoaded, this, &ModelsPanel::refreshTrajectory);
    connect(context, &StudioContext::currentFrameChanged, m_trajectory, &TrajectoryView::setCurrentFrame);
    connect(m_parameter, &QSpinBox::valueChanged, this, &ModelsPanel::refreshTrajectory);
    updateActions();
}

void ModelsPanel::setProject(const Project &project)
{
    m_list->clear();
    for (const ModelReference &m : project.models) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setText(0, QString::fromStdString(m.name));
        item->setText(1, kindText(m.kind));
        item->setText(2, QString::fromStdString(m.file));
        item->setData(1, Qt::UserRole, QString::fromStdString(m.kind));
        const QString kind = QString::fromStdString(m.kind);
        if (m_context && m_context->modelStore()->isUnwritten(m.file))
            item->setToolTip(2, tr("Made in this session; written when the project is saved"));
        else
            item->setToolTip(2, QString::fromStdString(project.resolve(m.file)));
        if (isDynamicModelKind(m.kind)) {
            item->setForeground(1, ModelKinds::colour(kind));
            if (m_context)
                if (const auto model = m_context->modelStore()->dynamicModel(kind))
                    item->setToolTip(1, modelSummary(*model));
        }
    }
    if (project.models.empty()) {
        auto *item = new QTreeWidgetItem(m_list);
        item->setText(0, tr("No models yet"));
        item->setFlags(Qt::NoItemFlags);
        item->setFirstColumnSpanned(true);
    }
    updateActions();
}

std::vector<LabelledSequence> ModelsPanel::trainingData(QString *problem) const
{
    std::vector<LabelledSequence> out;
    if (!m_context)
        return out;
    const Project &project = m_context->document()->project();
    int withoutFeatures = 0, withoutPhones = 0;
    for (const Sequence &s : project.sequences) {
        if (s.features.size() == 0) {
            ++withoutFeatures;
            continue;
        }
        if (s.phones.isEmpty()) {
            ++withoutPhones;
            continue;
        }
        try {
            LabelledSequence l;
            l.name = s.id;
            l.labels = frameLabelsFromTier(s.phones, s.clock(), s.id);
            l.features = s.features;
            out.push_back(std::move(l));
        } catch (const Error &e) {
            if (problem)
                *problem = QString::fromUtf8(e.what());
            return {};
        }
    }
    if (out.empty() && problem)
        *problem = tr("No sequence has both features and phonemes (%1 without features, %2 without "
                      "phonemes): track the faces and align the speech first.")
                       .arg(withoutFeatures)
                       .arg(withoutPhones);
    return out;
}

QList<Task *> ModelsPanel::runningTasks() const
{
    QList<Task *> out;
    for (const QPointer<Task> &t : m_tasks)
        if (t && t->isRunning())
            out.append(t.data());
    return out;
}

void ModelsPanel::applyPaperPreset(bool on)
{
    // The controls show what the preset trains; unticked, the user's own settings come back.
    if (on)
        m_beforePaper = {m_compensateVariance->isChecked(), m_contextStates->isChecked(), m_prior->isChecked(),
                         m_brandCovariance->currentIndex(), m_dpdsOptimizer->currentIndex()};
    m_compensateVariance->setChecked(on ? false : m_beforePaper.compensate);
    m_contextStates->setChecked(on ? false : m_beforePaper.context);
    m_prior->setChecked(on ? false : m_beforePaper.prior);
    m_brandCovariance->setCurrentIndex(on ? m_brandCovariance->findData(int(BrandCovariance::Diagonal))
                                          : m_beforePaper.covariance);
    m_dpdsOptimizer->setCurrentIndex(on ? m_dpdsOptimizer->findData(QStringLiteral("gradient"))
                                        : m_beforePaper.optimizer);
    for (QWidget *w : std::initializer_list<QWidget *>{m_compensateVariance, m_contextStates, m_prior, m_brandCovariance,
                                                       m_dpdsOptimizer})
        w->setEnabled(!on);
}

ModelOptions ModelsPanel::modelOptions() const
{
    if (m_paper->isChecked())
        return ModelOptions::paper();
    ModelOptions options;
    options.dpds.optimizer = m_dpdsOptimizer->currentData().toString() == QLatin1String("gradient")
                                 ? DpdsOptions::Optimizer::GradientAscent
                                 : DpdsOptions::Optimizer::LevenbergMarquardt;
    options.slds.fullA = m_sldsA->currentData().toBool();
    options.brand.covariance = BrandCovariance(m_brandCovariance->currentData().toInt());
    options.compensateVariance = m_compensateVariance->isChecked();
    options.contextStates = m_contextStates->isChecked();
    return options;
}

std::shared_ptr<const MouthShapePrior> ModelsPanel::mouthPrior(bool *failed)
{
    *failed = false;
    if (!m_prior->isChecked())
        return nullptr;
    const std::string path = ResourceLocator::find("prior/grid-s1.mouthprior");
    try {
        if (path.empty())
            throw Error("the shipped mouth prior (prior/grid-s1.mouthprior) was not found");
        return std::make_shared<const MouthShapePrior>(MouthShapePrior::load(path));
    } catch (const Error &e) {
        *failed = true;
        m_status->setText(tr("Cannot start from other speakers: %1").arg(QString::fromUtf8(e.what())));
        return nullptr;
    }
}

QString ModelsPanel::coverageAdvice(const PhoneCoverage &coverage)
{
    // The footage's gaps for these options, in the user's language (PhoneCoverage::advice).
    QStringList said;
    if (!coverage.unseen.empty())
        said << (coverage.prior ? tr("%1 of %2 phones never occur in the footage: their face comes from other "
                                     "speakers' mouths")
                                : tr("%1 of %2 phones never occur in the footage: their face is guessed from the average"))
                    .arg(coverage.unseen.size())
                    .arg(PhoneCoverage::kSpeechPhones);
    if (!coverage.rare.empty())
        said << tr("%1 have fewer than %2 frames").arg(coverage.rare.size()).arg(kMinimumVarianceFrames);
    if (coverage.contextStates > 0 && coverage.contextStates <= PhoneSet::kCount)
        said << tr("Phones in context made no context states: too little footage for them");
    if (said.isEmpty())
        return {};
    return said.join(QStringLiteral("; ")) + QLatin1Char('.') + QLatin1Char(' ')
           + tr("More footage of the person (%1 s of speech now) covers more.").arg(qRound(coverage.speechSeconds))
           + (coverage.takesPrior && !coverage.prior && !coverage.priorTried
                  ? QLatin1Char(' ') + tr("Tick Start from other speakers to take the phones it lacks from other people's mouths.")
                  : QString());
}

QList<Task *> ModelsPanel::train()
{
    QList<Task *> started;
    if (!m_context || !runningTasks().isEmpty())
        return started;
    QString problem;
    auto data = std::make_shared<const std::vector<LabelledSequence>>(trainingData(&problem));
    if (data->empty()) {
        m_status->setText(problem);
        return started;
    }
    const ModelOptions options = modelOptions();
    bool priorFailed = false;
    const std::shared_ptr<const MouthShapePrior> prior = mouthPrior(&priorFailed);
    if (priorFailed)
        return started;
    // The prior is carried onto this face through the project's AAM and its tracked frames.
    const auto project = prior ? std::make_shared<const Project>(m_context->document()->project()) : nullptr;
    const std::shared_ptr<const AamModel> aam = prior ? m_context->modelStore()->aam() : nullptr;
    if (prior && !aam) {
        m_status->setText(tr("Cannot start from other speakers without the project's AAM."));
        return started;
    }
    // The prior's shift is the same for every kind trained here (the same sequences, prior and
    // AAM): the first task that needs it measures the tracks and cross-validates its weight, the
    // others take what it found.
    struct PriorShift
    {
        std::once_flag once;
        Eigen::MatrixXd shift;
        double weight = 0.0;
    };
    const auto priorShift = prior ? std::make_shared<PriorShift>() : nullptr;
    // Recorded in each model: new speech for this speaker is aligned as its phones were.
    const std::optional<AlignerChoice> aligner = projectAlignerChoice(m_context->document()->project());

    // What a trained model records as its AAM: the content identifier of the project's AAM, which
    // `lipsync render` and the preview check against whichever AAM file they are given.
    ModelStore *store = m_context->modelStore();
    const std::string aamId = store->aamIdentifier();
    if (m_plots)
        m_plots->setCurrentWidget(m_objective);
    for (const QString &kind : ModelKinds::ids()) {
        if (!m_kinds[kind]->isChecked() || !m_kinds[kind]->isEnabled())
            continue;
        const QString name = ModelKinds::name(kind);
        // A file of its own: undoing this training brings back the previous model's file.
        const QString file = store->reserveFile(kind);
        m_objective->startRun(kind, name, ModelKinds::colour(kind));
        QPointer<ModelsPanel> self(this);
        Task *task = m_context->taskRunner()->start(
            tr("Train %1").arg(name),
            [self, kind, name, file, data, options, aamId, prior, project, aam, priorShift, aligner](Feedback &feedback) -> TaskRunner::Commit {
                feedback.setStatus(tr("Training %1 on %n sequence(s)…", "", int(data->size())).arg(name).toStdString());
                ModelOptions own = options;
                if (prior && modelKindTakesPrior(*parseModelKind(kind.toStdString()))) {
                    std::call_once(priorShift->once, [&] {
                        priorShift->shift = projectPriorShift(*prior, MouthMeasurer(*aam), *project, *data,
                                                              MouthShapePrior::kCrossValidated, &priorShift->weight);
                    });
                    own.meanShift = priorShift->shift;
                    own.priorWeight = priorShift->weight;
                }
                std::shared_ptr<DynamicModel> model = createDynamicModel(kind.toStdString(), own);
                const auto start = std::chrono::steady_clock::now();
                model->train(*data, feedback);
                model->setTrainingAligner(aligner);
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                long long frames = 0;
                double ll = 0.0;
                for (const LabelledSequence &s : *data) {
                    frames += s.frameCount();
                    ll += model->trajectoryLogLikelihood(s.labels, s.features); // comparable (§6.2)
                }
                PhoneCoverage coverage = PhoneCoverage::of(*data, *model);
                coverage.priorTried = prior != nullptr;
                // Written on the GUI thread by the commit (a small JSON file), so a canceled
                // training never replaces the model file either.
                return [self, kind, name, file, model, seconds, ll, frames, aamId, coverage] {
                    if (!self)
                        return;
                    const QString lacking = coverageAdvice(coverage);
                    self->m_status->setText(tr("%1 trained in %2 s: log-likelihood %3 nats/frame")
                                                .arg(name)
                                                .arg(seconds, 0, 'f', 2)
                                                .arg(frames > 0 ? ll / double(frames) : 0.0, 0, 'f', 3)
                                            + (lacking.isEmpty() ? QString() : QStringLiteral(". ") + lacking));
                    if (!lacking.isEmpty())
                        self->m_context->showStatus(lacking, 20000);
                    const QString problem = self->m_context->modelStore()->addDynamicModel(file, model, aamId);
                    if (!problem.isEmpty())
                        self->m_status->setText(tr("The %1 model could not be saved: %2").arg(name, problem));
                    self->m_context->document()->requestAddModel(
                        {kind.toStdString(), name.toStdString(), file.toStdString()},
                        tr("Train %1").arg(name));
                    self->refreshTrajectory();
                    emit self->modelTrained(kind);
                };
            });
        connect(task, &Task::iterationReported, m_objective,
                [plot = m_objective, kind](int i, double value) { plot->addIteration(kind, i, value); });
        connect(task, &Task::finished, this, [this, name, task, file](Task::State state) {
            if (state != Task::State::Finished && m_context)
                m_context->modelStore()->releaseFile(file);
            if (state == Task::State::Canceled)
                m_status->setText(tr("Training %1 canceled: the previous model stays.").arg(name));
            else if (state == Task::State::Failed)
                m_status->setText(tr("Training %1 failed: %2").arg(name, task->errorMessage()));
            updateActions();
        });
        m_tasks.append(task);
        started.append(task);
    }
    if (started.isEmpty())
        m_status->setText(tr("Check at least one model kind to train."));
    updateActions();
    return started;
}

Task *ModelsPanel::evaluate()
{
    std::vector<LabelledSequence> sequences;
    const std::optional<EvaluationOptions> options = evaluationToStart(&sequences);
    if (!options)
        return nullptr;
    auto data = std::make_shared<const std::vector<LabelledSequence>>(std::move(sequences));
    QPointer<ModelsPanel> self(this);
    Task *task = m_context->taskRunner()->run<EvaluationResult>(
        tr("Evaluate %n model(s) (%1-fold)", "", int(options->kinds.size())).arg(options->folds),
        [data, options = *options](Feedback &feedback) { return evaluateModels(*data, options, feedback); },
        [self](EvaluationResult result) {
            if (!self)
                return;
            const QString what = tr("Evaluated %n model(s) on %1 sequences, %2 folds: mean and 95 % interval over "
                                    "the folds.",
                                    "", int(result.models.size()))
                                     .arg(result.sequences)
                                     .arg(result.folds);
            self->m_evaluation->setResult(result, what);
            self->showEvaluation(self->m_evaluation, what);
        });
    watchEvaluation(task, m_evaluation);
    return task;
}

Task *ModelsPanel::evaluateRealism()
{
    std::vector<LabelledSequence> sequences; // the realism report takes them from the project
    const std::optional<EvaluationOptions> options = evaluationToStart(&sequences);
    if (!options)
        return nullptr;
    RealismOptions realism;
    realism.crossValidation = *options;
    bool priorFailed = false;
    realism.mouthPrior = mouthPrior(&priorFailed);
    if (priorFailed)
        return nullptr;
    realism.closeBilabials = m_context->closesLips(); // the models' faces as the studio renders them
    if (m_paper->isChecked()) {
        realism.closeBilabials = false;
        realism.composite = CompositeOptions::paper();
    }
    auto project = std::make_shared<const Project>(m_context->document()->project());
    QPointer<ModelsPanel> self(this);
    Task *task = m_context->taskRunner()->run<RealismResult>(
        tr("Realism of %n model(s) (%1-fold)", "", int(options->kinds.size())).arg(options->folds),
        [project, realism](Feedback &feedback) { return lipsync::evaluateRealism(*project, realism, feedback); },
        [self](RealismResult result) {
            if (!self)
                return;
            const QString what = tr("Rendered %1 held-out sequences (%2 folds) and measured the lips with dlib's "
                                    "landmarks: the AAM's re-synthesis and %n model(s).",
                                    "", int(result.methods.size()) - 1)
                                     .arg(result.sequences)
                                     .arg(result.folds);
            self->m_realismPage->setRealism(result, what);
            self->showEvaluation(self->m_realismPage, what);
        });
    watchEvaluation(task, m_realismPage);
    return task;
}

std::optional<EvaluationOptions> ModelsPanel::evaluationToStart(std::vector<LabelledSequence> *data)
{
    if (!m_context || !runningTasks().isEmpty())
        return std::nullopt;
    QString problem;
    *data = trainingData(&problem);
    EvaluationOptions options;
    options.folds = std::min(m_folds->value(), int(data->size()));
    options.kinds.clear();
    for (const QString &kind : ModelKinds::ids())
        if (m_kinds[kind]->isChecked() && m_kinds[kind]->isEnabled())
            options.kinds.push_back(kind.toStdString());
    if (data->empty() || options.kinds.empty() || options.folds < 2) {
        m_status->setText(data->empty()            ? problem
                          : options.kinds.empty() ? tr("Check at least one model kind to evaluate.")
                                                  : tr("Cross-validation needs at least two sequences."));
        return std::nullopt;
    }
    options.modelOptions = modelOptions();
    return options;
}

EvaluationChart *ModelsPanel::evaluationChart() const
{
    return m_evaluation->chart();
}

void ModelsPanel::showEvaluation(ResultsPage *page, const QString &status)
{
    if (m_plots)
        m_plots->setCurrentWidget(page);
    m_status->setText(status);
    emit evaluated();
}

void ModelsPanel::watchEvaluation(Task *task, ResultsPage *page)
{
    // Its page says it is computing from the start (and shown, so the wait is visible).
    page->setComputing(task->title());
    if (m_plots)
        m_plots->setCurrentWidget(page);
    connect(task, &Task::finished, this, [this, task, page](Task::State state) {
        if (state == Task::State::Failed) {
            m_status->setText(tr("Evaluation failed: %1").arg(task->errorMessage()));
            page->setStopped(tr("Failed: %1.").arg(task->errorMessage()));
        } else if (state == Task::State::Canceled) {
            page->setStopped(tr("Canceled."));
        }
        updateActions();
    });
    m_tasks.append(task);
    updateActions();
}

void ModelsPanel::cancel()
{
    for (Task *task : runningTasks())
        task->cancel();
    updateActions();
}

void ModelsPanel::onDocumentReset()
{
    setProject(m_context->document()->project());
    // Models of the new project: load the dynamic ones it uses (small JSON files), so a damaged
    // one is reported now rather than when it is first drawn.
    m_objective->clearRuns();
    m_evaluation->clear();
    m_realismPage->clear();
    const Project &project = m_context->document()->project();
    QStringList failed;
    for (const QString &kind : ModelKinds::ids()) {
        QString problem;
        if (m_context->modelStore()->dynamicModel(kind, &problem) || problem.isEmpty())
            continue;
        // One message box for the first damaged model (which file, why); the rest are listed here.
        if (failed.isEmpty())
            ErrorReporter::report(this, tr("A model of this project could not be loaded."),
                                  QString::fromStdString(project.resolve(project.model(kind.toStdString())->file)),
                                  problem);
        failed.append(problem);
    }
    m_status->setText(failed.isEmpty() ? QString() : tr("Some models could not be loaded: %1").arg(failed.join(QStringLiteral("; "))));
    refreshTrajectory();
    updateActions();
}

void ModelsPanel::onLocationChanged()
{
    // The store wrote the models made meanwhile into the new folder: their tooltips change.
    setProject(m_context->document()->project());
}

void ModelsPanel::refreshTrajectory()
{
    if (!m_context || !m_trajectory)
        return;
    const int row = m_context->currentSequence();
    const ProjectDocument *doc = m_context->document();
    if (row < 0 || row >= doc->sequenceCount()) {
        m_trajectory->clear();
        return;
    }
    const Sequence &s = doc->sequence(row);
    if (s.features.size() == 0) {
        m_parameter->setRange(0, 0);
        m_trajectory->setData(tr("%1: no features yet (track the faces first)").arg(QString::fromStdString(s.id)),
                              s.clock(), s.phones, {});
        return;
    }
    {
        const QSignalBlocker block(m_parameter);
        m_parameter->setRange(0, int(s.features.cols()) - 1);
    }
    const int k = m_parameter->value();
    QVector<TrajectoryView::Series> series;
    TrajectoryView::Series real{tr("real"), {}, QColor(0x1e, 0x88, 0xe5)};
    for (Eigen::Index t = 0; t < s.features.rows(); ++t)
        real.values.append(s.features(t, k));
    series.append(real);
    // Each trained model the document uses, in the panel's order, as the preview draws it (the
    // lips closed on /p b m/ when they are there).
    const std::shared_ptr<const AamModel> aam = m_context->modelStore()->aam();
    for (const StudioContext::GeneratedTrajectory &generated :
         m_context->generatedTrajectories(row, aam && aam->combinedModes() == s.features.cols() ? aam.get() : nullptr)) {
        TrajectoryView::Series g{ModelKinds::name(generated.kind), {}, ModelKinds::colour(generated.kind)};
        for (Eigen::Index t = 0; t < generated.features.rows(); ++t)
            g.values.append(generated.features(t, k));
        series.append(g);
    }
    m_trajectory->setData(tr("%1 — AAM parameter %2").arg(QString::fromStdString(s.id)).arg(k), s.clock(),
                          s.phones, series);
    m_trajectory->setCurrentFrame(m_context->currentFrame());
}

void ModelsPanel::updateActions()
{
    const bool busy = !runningTasks().isEmpty();
    const bool ready = m_context && m_context->document()->isOpen();
    m_train->setEnabled(ready && !busy);
    m_evaluate->setEnabled(ready && !busy);
    m_realism->setEnabled(ready && !busy);
    m_cancel->setEnabled(busy);
}

} // namespace lipsync::studio
