#pragma once
// The Models dock: the AAMs and dynamic models the project refers to, and the dynamics workflow:
// choose model kinds and options, train them as TaskRunner tasks with a live plot of the objective
// per iteration (cancel keeps the previous model), compare them by k-fold cross-validation (the
// paper's Figure 4, or the realism report on the rendered lips), and look at the trajectories they
// generate for the current sequence. Trained
// models live in the ModelStore and in the document as ModelReferences (kind dpds/slds/brand/hmm,
// each training a file of its own, models/<kind>[-n].model), so Train is undone like any edit.
#include <QHash>
#include <QList>
#include <QPointer>
#include <QWidget>

#include "eval/Evaluation.h"
#include "tasks/Task.h"

#include <memory>
#include <optional>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QGridLayout;
class QLabel;
class QPushButton;
class QSpinBox;
class QTabWidget;
class QTreeWidget;

namespace lipsync {
class DynamicModel;
struct ModelOptions;
class MouthShapePrior;
class Project;
struct PhoneCoverage;
struct LabelledSequence;
}

namespace lipsync::studio {

class ElidedLabel;
class EvaluationChart;
class StudioContext;
class ObjectivePlot;
class ResultsPage;
class TrajectoryView;

class ModelsPanel : public QWidget
{
    Q_OBJECT
public:
    explicit ModelsPanel(QWidget *parent = nullptr);
    ~ModelsPanel() override;

    // Connects the panel to the context's document, task runner, model store and current frame,
    // and adds the Trajectory, Training, Evaluation and Realism plots as tabs of `plots` (the Plots
    // dock).
    void attach(StudioContext *context, QTabWidget *plots);
    // The Build AAM button becomes another trigger of `buildAam` (the Faces menu's action).
    void setBuildAamAction(QAction *buildAam);

    void setProject(const Project &project);
    QTreeWidget *list() const { return m_list; }
    QPushButton *buildAamButton() const { return m_buildAam; }
    QPushButton *trainButton() const { return m_train; }
    QPushButton *cancelButton() const { return m_cancel; }
    QPushButton *evaluateButton() const { return m_evaluate; }
    QPushButton *realismButton() const { return m_realism; }
    // By kind id (ModelKinds::ids()).
    QCheckBox *kindCheck(const QString &kind) const { return m_kinds.value(kind); }
    QComboBox *dpdsOptimizer() const { return m_dpdsOptimizer; }
    QComboBox *sldsTransition() const { return m_sldsA; }
    QComboBox *brandCovariance() const { return m_brandCovariance; }
    QCheckBox *compensateVarianceCheck() const { return m_compensateVariance; }
    QCheckBox *contextStatesCheck() const { return m_contextStates; }
    QCheckBox *priorCheck() const { return m_prior; }
    QCheckBox *paperModelsCheck() const { return m_paper; }
    QSpinBox *foldsSpin() const { return m_folds; }
    QSpinBox *parameterSpin() const { return m_parameter; }
    TrajectoryView *trajectoryView() const { return m_trajectory; }
    ObjectivePlot *objectivePlot() const { return m_objective; }
    // The k-fold evaluation's page and the realism report's, each a chart and its table.
    ResultsPage *evaluationPage() const { return m_evaluation; }
    ResultsPage *realismPage() const { return m_realismPage; }
    EvaluationChart *evaluationChart() const;
    QTabWidget *plotTabs() const { return m_plots; }
    ElidedLabel *statusLabel() const { return m_status; }

    // Training and evaluation tasks still running.
    QList<Task *> runningTasks() const;

    // The actions behind the buttons (return the tasks started; empty/null when nothing to do).
    QList<Task *> train();
    Task *evaluate();
    // The realism report (docs/models.md §6.5) of the checked models on the same folds, as a chart.
    Task *evaluateRealism();
    void cancel();

signals:
    // A model was trained and added to the document (kind).
    void modelTrained(const QString &kind);
    // An evaluation finished and is shown.
    void evaluated();

private:
    std::vector<LabelledSequence> trainingData(QString *problem) const;
    ModelOptions modelOptions() const; // the options the controls choose
    // The mouth prior when "Start from other speakers" is ticked, else null; a prior that cannot be
    // read is said in the status and also null (`failed` set).
    std::shared_ptr<const MouthShapePrior> mouthPrior(bool *failed);
    // The folds, kinds and model options of the controls for an evaluation of `data` (set to
    // trainingData()), or nothing when one cannot start (the reason shown in the panel).
    std::optional<EvaluationOptions> evaluationToStart(std::vector<LabelledSequence> *data);
    void showEvaluation(ResultsPage *page, const QString &status); // a finished evaluation's page and status
    void watchEvaluation(Task *task, ResultsPage *page);
    void onDocumentReset();
    void onLocationChanged();
    void refreshTrajectory();
    void updateActions();
    void applyPaperPreset(bool on);
    QGridLayout *optionsGrid(); // the kinds' and every kind's options (the constructor's)
    // What the training footage lacks for the options (PhoneCoverage), or empty.
    static QString coverageAdvice(const PhoneCoverage &coverage);

    QTreeWidget *m_list;
    QPushButton *m_buildAam;
    QPushButton *m_train;
    QPushButton *m_cancel;
    QPushButton *m_evaluate;
    QPushButton *m_realism;
    QHash<QString, QCheckBox *> m_kinds;
    QComboBox *m_dpdsOptimizer;
    QComboBox *m_sldsA;
    QComboBox *m_brandCovariance;
    QCheckBox *m_compensateVariance;
    QCheckBox *m_contextStates;
    QCheckBox *m_prior; // HMM-mean's and Brand's phone means start from other speakers' mouths
    QCheckBox *m_paper;
    struct Settings
    {
        bool compensate = true, context = true, prior = false;
        int covariance = 0, optimizer = 0;
    } m_beforePaper; // the controls' settings before the paper preset was ticked
    QSpinBox *m_folds;
    QSpinBox *m_parameter;
    ElidedLabel *m_status; // one line under the buttons, the whole text as tooltip

    StudioContext *m_context = nullptr;
    QPointer<QTabWidget> m_plots;
    TrajectoryView *m_trajectory = nullptr;
    ObjectivePlot *m_objective = nullptr;
    ResultsPage *m_evaluation = nullptr;
    ResultsPage *m_realismPage = nullptr;
    QWidget *m_trajectoryPage = nullptr;

    QList<QPointer<Task>> m_tasks;
};

} // namespace lipsync::studio
