#pragma once
// Live: speak into the microphone and watch the face move. The view of a LiveController: a
// microphone and a trained dynamic model to choose (DPDS first when trained), Start and Stop, the
// rendered face as its frames come, the recognised phones scrolling by (and which recogniser
// hears them: our aligner model's HMMs, or CMU Sphinx's when the timeline aligns with it), and
// the latency from sound to frame. After Stop the session can be saved as a new sequence of the
// project (one undo step) or exported as MP4 with its sound. Whatever is missing (a project, an
// AAM, a trained model, a microphone) the view says what to do instead of offering Start.
//
// Hiding the view (another tab, a closed panel) stops a running session: the microphone is
// never left listening unseen.
//
// The face is drawn into a still of the person, or over a camera chosen in the camera list: each
// frame over the camera's newest picture, wherever the face is found in it (LiveController::camera).
// Hiding the view closes the camera too.
#include <QMediaDevices>
#include <QWidget>

#include <functional>

class QComboBox;
class QLabel;
class QPushButton;

namespace lipsync::studio {

class FrameView;
class LiveController;
class PhoneStrip;
class StudioContext;

class LiveView : public QWidget
{
    Q_OBJECT
public:
    // `saveProject` saves the document (Save As for the read-only demo; true once saved): a saved
    // session's sound is written into the project's folder.
    LiveView(StudioContext *context, std::function<bool()> saveProject, QWidget *parent = nullptr);
    ~LiveView() override;

    LiveController *controller() const { return m_controller; }
    QComboBox *microphoneCombo() const { return m_microphones; }
    QComboBox *modelCombo() const { return m_models; }
    QComboBox *cameraCombo() const { return m_cameras; }
    QPushButton *startButton() const { return m_start; }
    QPushButton *stopButton() const { return m_stop; }
    QPushButton *saveButton() const { return m_save; }
    QPushButton *exportButton() const { return m_export; }
    FrameView *face() const { return m_face; }
    PhoneStrip *phoneStrip() const { return m_strip; }
    QLabel *latencyLabel() const { return m_latency; }
    // Which recogniser hears the phones (LiveController::recognisesWithSphinx).
    QLabel *recogniserLabel() const { return m_recogniser; }
    QLabel *messageLabel() const { return m_message; }
    // The model kind chosen ("dpds"), or empty.
    QString chosenKind() const;
    // Starts a session of the chosen model on sound fed from code (LiveController::feed) instead of
    // a microphone: tests and demonstrations drive the same pipeline. False (and said) if it cannot.
    bool startWithFedSound();
    // Starts a session of the chosen model on the sound of the audio or video file `path`, played
    // aloud unless `audible` is false (what Start does with "A recording…" chosen, after asking
    // for the file). False (and said) if it cannot.
    bool startWithFile(const QString &path, bool audible = true);
    // The microphone list's entry for a recording instead of a microphone.
    static constexpr const char *kFileInput = "file";

public slots:
    void start();
    void stop();
    void saveAsSequence();
    void exportVideo();

signals:
    // A session was saved as sequence `id`.
    void sequenceSaved(const QString &id);

protected:
    void showEvent(QShowEvent *event) override;
    void hideEvent(QHideEvent *event) override;

private:
    void connectControls();
    void fillMicrophones();
    void fillModels();
    void fillCameras();
    // Opens the camera chosen in the list (none: closes it).
    void useChosenCamera();
    void updateControls();
    void showFrames();
    void say(const QString &message);

    StudioContext *m_context;
    std::function<bool()> m_saveProject;
    LiveController *m_controller;
    QMediaDevices *m_devices;
    QComboBox *m_microphones;
    QComboBox *m_models;
    QComboBox *m_cameras;
    QPushButton *m_start;
    QPushButton *m_stop;
    QPushButton *m_save;
    QPushButton *m_export;
    FrameView *m_face;
    PhoneStrip *m_strip;
    QLabel *m_latency;
    QLabel *m_recogniser;
    QLabel *m_progress;
    QLabel *m_message;
    QString m_lastProblem; // the latest failure, shown until the next start
    QString m_playing;     // the recording a session from a file plays
    bool m_modelChosen = false; // the user picked a model: kept while it stays trained
};

} // namespace lipsync::studio
