#pragma once
// The live session's thread side: one LiveSession (render/LiveSession: streaming phone
// recognition, generation and rendering) fed block by block on a QThread of its own, so that
// recognising, generating and drawing never hold up the GUI. Its functions run on that thread
// (the controller calls them through queued invocations); what they produce goes back to the GUI
// thread by queued signals: the frames that became ready, as images, with their features,
// phones and latency, and the recognised phones of the last seconds for the phone strip.
//
// With a camera (LiveSetup::camera), each frame is drawn again over the camera's newest picture
// (render/CameraCompositor tracks the face there); a picture without a face, or no picture yet,
// leaves the frame as the session drew it into the still.
//
// A frame's latency is the wall time from the capture of the newest sound it shows to the
// moment it is drawn: the block's last sample was captured at `captured`, the frame's newest
// sound (soundEnd) lies (fed - soundEnd) seconds before it, and the frame is drawn when push()
// returns (as `lipsync live` measures it).
#include "annotation/Tier.h"
#include "render/LiveSession.h"

#include <QImage>
#include <QMetaType>
#include <QObject>

#include <Eigen/Core>

#include <atomic>
#include <chrono>
#include <memory>
#include <vector>

namespace lipsync {
class AamModel;
class AcousticModel;
class CameraCompositor;
class DynamicModel;
class FaceRenderer;
class PhoneBigram;
}

namespace lipsync::studio {

class CameraFeed;

// What a session runs on, kept alive by the worker for as long as the session lives.
struct LiveSetup
{
    // The phone recogniser: our HMMs with the phone bigram, or (both null) CMU Sphinx's, loaded
    // by the preparation and taken over by the session as it begins (shared only to be copied
    // along until then).
    std::shared_ptr<const AcousticModel> acoustic;
    std::shared_ptr<const PhoneBigram> bigram;
    std::shared_ptr<std::unique_ptr<PhoneStream>> sphinx;
    int sampleRate = 16000; // the recogniser's: what push() takes
    std::shared_ptr<const DynamicModel> model;
    std::shared_ptr<const AamModel> aam; // the renderer's
    std::shared_ptr<FaceRenderer> renderer;
    std::shared_ptr<CameraFeed> camera; // null: the still of the person
    LiveOptions options;
};

// Frames that became ready in one block, in order.
struct LiveFrames
{
    std::vector<QImage> images;
    std::vector<int> labels;                // PhoneSet indices
    std::vector<Eigen::VectorXd> features;  // generated AAM parameters
    std::vector<double> latencies;          // seconds; NaN for the frames Stop flushes out
    Tier phones{"phones", {}};              // the last seconds' recognised phones (all of them when last)
    double soundSeconds = 0.0;              // sound fed so far
    bool last = false;                      // the session's final frames (finish)
};

class LiveWorker : public QObject
{
    Q_OBJECT
public:
    using Clock = std::chrono::steady_clock;
    // Seconds of recognised phones each batch carries for the phone strip.
    static constexpr double kRecentPhoneSeconds = 8.0;

    explicit LiveWorker(LiveSetup setup);
    ~LiveWorker() override;

    // On the worker's thread. Creates the session: started(), or failed() with the reason.
    void begin();
    // Sound at the recogniser's rate (LiveSetup::sampleRate) whose last sample was captured at
    // `captured`.
    void push(const std::vector<float> &samples, Clock::time_point captured);
    // The sound has ended: the remaining frames and the whole phone tier (LiveFrames::last).
    void finish();
    // Any thread: the blocks still queued are dropped (the studio is closing the session).
    void abandon() { m_abandoned = true; }

signals:
    void started(double frameRate, double algorithmicLatency);
    void framesReady(const lipsync::studio::LiveFrames &frames);
    void failed(const QString &why);

private:
    LiveFrames collect(std::vector<LiveFrame> ready, double fed, Clock::time_point captured, bool last);
    // Draws the frame again over the camera's newest picture when there is one with a face.
    void drawOverCamera(LiveFrame &frame);

    LiveSetup m_setup;
    std::unique_ptr<LiveSession> m_session;
    std::unique_ptr<CameraCompositor> m_camera;
    std::atomic<bool> m_abandoned{false};
};

} // namespace lipsync::studio

Q_DECLARE_METATYPE(lipsync::studio::LiveFrames)
