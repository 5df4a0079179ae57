#pragma once
// The studio's main window: the workflow areas (Annotate, Preview & compare and Live as tabs, the
// sequence list, Timeline, Plots and Models as docks), one view of the StudioContext (the
// document with its undo stack, the task runner, the model store, the player, the current
// sequence and frame).
#include <QMainWindow>

#include <memory>
#include <utility>
#include <vector>

class QDockWidget;
class QLabel;
class QMenu;
class QTableView;
class QTabWidget;
class QUndoStack;

namespace lipsync {
class TaskRunner;
}

namespace lipsync::studio {

class ExportMenu;
class FacesController;
class FrameView;
class LineChartView;
class LiveView;
class LongRecordingImporter;
class ModelStore;
class ModelsPanel;
class PlaybackController;
class PreviewPanel;
class ProjectDocument;
class ProjectFiles;
class SequenceDetailsView;
class SequenceListModel;
class StudioContext;
class TaskStatusWidget;
class TimelinePanel;
class TranscriptProposer;
class TransportBar;
class WaveformView;
struct SequenceMedia;
struct StudioActions;

class MainWindow : public QMainWindow
{
    Q_OBJECT
public:
    explicit MainWindow(QWidget *parent = nullptr);
    ~MainWindow() override;

    // The document, its undo stack, the task runner, the models, the player and the current
    // sequence and frame: the context's (every panel's view of them).
    StudioContext *context() const { return m_context; }
    ProjectFiles *files() const { return m_files; }
    TaskStatusWidget *taskStatus() const { return m_taskStatus; }
    QTableView *sequenceView() const { return m_sequenceView; }
    FrameView *frameView() const { return m_frameView; }
    WaveformView *waveformView() const;
    LineChartView *chartView() const { return m_chart; }
    // Shows the window at the last session's geometry if that fits the screen, else maximised.
    void showAsLastTime();
    PreviewPanel *preview() const { return m_preview; }
    LiveView *liveView() const { return m_live; }
    ModelsPanel *modelsPanel() const { return m_models; }
    const StudioActions &actions() const { return *m_actions; }
    FacesController *faces() const { return m_faces; }
    ExportMenu *exportMenu() const { return m_export; }
    LongRecordingImporter *longRecordingImporter() const { return m_importer; }
    // Edit ▸ Propose Transcript and Accept Proposed Transcript (also in the sequence list's
    // context menu).
    TranscriptProposer *transcriptProposer() const { return m_proposer; }
    TimelinePanel *timeline() const { return m_timeline; }

public slots:
    // View > Panels > Reset Layout: every dock shown, docked where it starts, at its default size.
    void resetLayout();

protected:
    void closeEvent(QCloseEvent *event) override;
    void showEvent(QShowEvent *event) override;

private:
    static constexpr int kSpectrogramTimelineHeight = 360;
    void createDocks();
    void applyDefaultDockSizes();
    void updateActiveModels();
    void createMenus();
    void addGeneratedFaceMenu(QMenu *view);
    // The window's own views of a sequence emptied.
    void clearViews();
    void onDocumentReset();
    void onSelectionChanged();
    // The sequence list shows `row` selected (-1: none) without asking for it again.
    void showSequenceRow(int row);
    void onSequenceLoaded();
    void showChart();
    void showFrame(int frame); // the views of the context's current frame
    void updateTitle();
    void restoreSettings();

    StudioContext *m_context;
    std::unique_ptr<StudioActions> m_actions;
    ProjectFiles *m_files = nullptr;
    SequenceListModel *m_sequenceModel = nullptr;
    QTableView *m_sequenceView = nullptr;
    SequenceDetailsView *m_details = nullptr;
    QTabWidget *m_tabs = nullptr;
    std::vector<std::pair<QDockWidget *, Qt::DockWidgetArea>> m_defaultDockAreas; // Reset Layout
    FrameView *m_frameView = nullptr;
    PreviewPanel *m_preview = nullptr;
    LiveView *m_live = nullptr;
    TransportBar *m_transport = nullptr;
    TimelinePanel *m_timeline = nullptr;
    LineChartView *m_chart = nullptr;
    ModelsPanel *m_models = nullptr;
    TaskStatusWidget *m_taskStatus = nullptr;
    QLabel *m_activeModels = nullptr; // status bar: the AAM and dynamic models in use
    FacesController *m_faces = nullptr;
    ExportMenu *m_export = nullptr;
    LongRecordingImporter *m_importer = nullptr;
    TranscriptProposer *m_proposer = nullptr;

    bool m_geometryRestored = false;
    bool m_layoutRestored = false;
    bool m_shownOnce = false;
};

} // namespace lipsync::studio
