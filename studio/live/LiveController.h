#pragma once
// The Live view's engine, without widgets: speech from the microphone (or from code, for tests
// and demos) through a LiveSession on a worker thread (LiveWorker) to rendered frames back on the
// GUI thread, and the session's recording, saved as a project sequence or exported as MP4.
//
// A session: start() loads what it needs in the background through the studio's task runner
// (the phone recogniser: CMU Sphinx's when the timeline aligns with CMU Sphinx, else our aligner
// model and its phone bigram; and the face's background: the current sequence's video tracked
// with the project's AAM, its first frame a still of the person, or the AAM's mean face on grey
// without one), then opens the microphone and starts the worker. Blocks of sound go to the
// worker as they are captured; frames come back as they are ready. stop() ends the session
// cleanly: the worker flushes the last frames and the whole phone tier.
//
// The recording (sound, generated features and phone labels per frame, the phone tier) is kept
// for up to kMaxRecordedSeconds; later sound still animates the face but is not kept. Another
// project drops the session and the recording: the features are the old AAM's parameters.
#include "annotation/Tier.h"
#include "live/LiveWorker.h"
#include "tasks/Task.h"

#include <QAudioDevice>
#include <QImage>
#include <QObject>
#include <QPointer>
#include <QString>

#include <Eigen/Core>

#include <deque>
#include <memory>
#include <vector>

class QThread;

namespace lipsync {
class AamModel;
class AcousticModel;
class FaceRenderer;
class PhoneBigram;
}

namespace lipsync::studio {

class CameraFeed;
class FileInput;
class MicrophoneInput;
class StudioContext;

class LiveController : public QObject
{
    Q_OBJECT
public:
    enum class State { Idle, Preparing, Running, Finishing };
    Q_ENUM(State)
    // Where the sound comes from: a microphone, a recording played at its own pace (startFromFile),
    // or feed() (tests, and sound fed from code).
    enum class Input { Microphone, File, Fed };
    static constexpr double kMaxRecordedSeconds = 30 * 60;
    // The latency read-out's window: the frames of the last seconds.
    static constexpr double kLatencyWindowSeconds = 5.0;

    explicit LiveController(StudioContext *context, QObject *parent = nullptr);
    ~LiveController() override;

    // What stands in the way of going live with the model of `kind` (a sentence saying what to
    // do instead), or empty.
    QString problem(const QString &kind) const;
    // Whether the model's face waits for each phone to end (phones in context from a model file
    // without the guess Live streams them with): in pauses, seconds behind the sound.
    bool waitsForPhones(const QString &kind) const;
    // The dynamic model kinds the project has trained, in the studio's order.
    QStringList trainedKinds() const;

    // Starts a session with the model of `kind` on `input` (`device` for the microphone).
    // False, with `why`, when it cannot start.
    bool start(const QString &kind, Input input, const QAudioDevice &device = {}, QString *why = nullptr);
    // A session on the sound of the audio or video file `path`, played aloud (unless `audible` is
    // false) and fed at its own pace; the session ends by itself when the sound does. The file is
    // decoded while the session prepares: a bad or too long file fails it with a message naming it.
    bool startFromFile(const QString &kind, const QString &path, QString *why = nullptr, bool audible = true);
    // Input::Fed: mono sound at sampleRate() as if captured now (kept until the session runs).
    void feed(const std::vector<float> &samples);
    // Ends the session: the last frames arrive, then the state is Idle again.
    void stop();

    State state() const { return m_state; }
    Input input() const { return m_input; }
    bool isActive() const { return m_state != State::Idle; }
    // The phone recogniser's sample rate (what feed() takes).
    int sampleRate() const { return m_sampleRate; }
    // Whether CMU Sphinx's US-English phone recogniser (any speaker) recognises the phones, not our
    // HMMs: the running session's recogniser, else the one the next session takes (Sphinx's when
    // the timeline aligns with CMU Sphinx).
    bool recognisesWithSphinx() const;

    // This session's frames shown so far, the newest of them, the sound fed and the frame rate.
    int framesShown() const { return m_framesShown; }
    const QImage &lastImage() const { return m_lastImage; }
    double soundSeconds() const { return m_soundSeconds; }
    double frameRate() const { return m_frameRate; }
    // The recognised phones of the last seconds (LiveWorker::kRecentPhoneSeconds).
    const Tier &recentPhones() const { return m_recentPhones; }
    // The share of the latency the session's design imposes (LiveSession::latencySeconds: the
    // recogniser's lag and the generator's look-ahead), 0 before the session runs.
    double algorithmicLatency() const { return m_algorithmicLatency; }
    // Latency from sound to frame over the last kLatencyWindowSeconds: false before any frame.
    bool latency(double *meanSeconds, double *maxSeconds) const;

    // The camera the face is drawn over while it delivers pictures with a face in them (else the
    // still of the person). Its pictures are not recorded: the recording's video is drawn into
    // the still.
    CameraFeed *camera() const { return m_camera.get(); }

    // The last finished session's recording (sound, features and phones), kept for Save and Export.
    bool hasRecording() const;
    double recordedSeconds() const;
    int recordedFrames() const { return int(m_recording.features.size()); }
    // Sound beyond kMaxRecordedSeconds was not kept.
    bool recordingTruncated() const { return m_recording.truncated; }

    // Adds the recording to the project as a new sequence ("live_0001": its sound written to
    // PROJECT/live/<id>.wav, its generated features, phones and frame rate), one undo step.
    // Returns the id, or empty with `why`.
    QString saveAsSequence(QString *why = nullptr);
    // Writes the recording's frames with its sound as MP4 to `path` in the background; the task,
    // or null with `why`.
    Task *exportVideo(const QString &path, QString *why = nullptr);
    bool isExporting() const { return m_exportTask != nullptr; }

signals:
    void stateChanged(lipsync::studio::LiveController::State state);
    // New frames arrived (lastImage, framesShown, recentPhones and latency changed).
    void framesShownChanged();
    // A recording became available or went away.
    void recordingChanged();
    // The session could not start or broke off.
    void failed(const QString &why);
    // A video export started, and ended (the path written, or empty on cancel or failure).
    void exportStarted();
    void exportEnded(const QString &path);

private:
    struct Recording
    {
        std::vector<float> sound;
        std::vector<Eigen::VectorXd> features;
        std::vector<int> labels;
        Tier phones{"phones", {}};
        double frameRate = 25.0;
        int sampleRate = 16000;
        bool truncated = false;
        bool complete = false; // the session ended (stop)
        std::shared_ptr<const AamModel> aam;
        std::shared_ptr<FaceRenderer> renderer; // for the export, drawn as the session drew
        bool still = true;
    };
    void setState(State state);
    void launch(LiveSetup setup);
    void take(const std::vector<float> &samples, LiveWorker::Clock::time_point captured);
    void onFrames(const LiveFrames &frames);
    void onWorkerFailed(const QString &why);
    void endThread(bool abandon);
    // Forgets what the last session showed: frames waiting, counts, the last image, phones and
    // latencies (a new session starts, or the controller resets).
    void clearShown();
    void reset();
    QString alignerModelPath() const;
    // The timeline aligns with CMU Sphinx, whose model folder (empty: the default) goes in `modelDir`.
    bool sphinxChosen(std::string *modelDir = nullptr) const;

    StudioContext *m_context;
    State m_state = State::Idle;
    Input m_input = Input::Fed;
    QAudioDevice m_device;
    int m_epoch = 0; // counts sessions and documents: an older preparation's result is dropped
    QPointer<Task> m_prepareTask;
    QPointer<Task> m_exportTask;
    MicrophoneInput *m_microphone;
    FileInput *m_file;
    QString m_inputPath;  // Input::File: the recording
    bool m_audible = true; // Input::File: played aloud
    std::shared_ptr<const std::vector<float>> m_fileSound; // Input::File: decoded while preparing
    QThread *m_thread = nullptr;
    LiveWorker *m_worker = nullptr; // lives on m_thread
    std::vector<float> m_pending;   // fed while preparing

    // Loaded once and shared by the sessions (and the export, which reads the renderer).
    std::shared_ptr<const AcousticModel> m_acoustic;
    std::string m_acousticPath;
    std::shared_ptr<const PhoneBigram> m_bigram;
    bool m_sessionSphinx = false; // the session's recogniser is CMU Sphinx's
    std::shared_ptr<const AamModel> m_rendererAam;
    QString m_rendererMedia;
    std::shared_ptr<FaceRenderer> m_renderer;
    std::shared_ptr<CameraFeed> m_camera;

    int m_sampleRate = 16000;
    double m_frameRate = 25.0;
    double m_algorithmicLatency = 0.0;
    int m_framesShown = 0;
    double m_soundSeconds = 0.0;
    QImage m_lastImage;
    Tier m_recentPhones{"phones", {}};
    std::deque<double> m_latencies; // of the frames of the last kLatencyWindowSeconds
    Recording m_recording;
};

} // namespace lipsync::studio
