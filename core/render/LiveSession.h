#pragma once
// Speech to a moving face as the sound comes in (docs/pipeline.md, "Live"): sound in blocks ->
// a PhoneStream (no transcript: the speaker's own HMMs in StreamingPhoneRecognizer, or CMU
// Sphinx's in SphinxPhoneRecognizer) -> the phone of each video frame by the vote of
// docs/models.md §0 as soon as all its 100 Hz audio frames are decided -> the dynamic model's
// streaming generator (DPDS, SLDS and HMM-mean at once, Brand after its fixed lag) -> the AAM
// face rendered into its background (FaceRenderer: a still frame of the person, a video, or the
// mean face on grey), frame by frame.
//
// Frame i shows the sound of [i/f, (i+1)/f); it is ready once the recogniser has decided the
// audio frames up to that interval's end, which is PhoneStream::latencySeconds()
// after it, plus the generator's own look-ahead. Memory does not grow with the session beyond
// the recognised phones kept for phones().
#include "align/PhoneBigram.h"
#include "align/StreamingPhoneRecognizer.h"
#include "annotation/Tier.h"
#include "render/BilabialClosure.h"
#include "render/PostureTransfer.h"

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include <deque>
#include <memory>
#include <optional>
#include <vector>

namespace lipsync {

class AcousticModel;
class DynamicModel;
class FaceRenderer;
class StreamingGenerator;

struct LiveOptions
{
    double frameRate = 0.0; // video frames per second; 0: the dynamic model's (25 if it records none)
    bool stillBackground = false; // every frame into the background's first frame (a still of the person)
    // Close the lips on frames heard as /p b m/ (render/BilabialClosure, with the renderer's AAM;
    // features-only sessions have no AAM and are left as generated).
    bool closeBilabials = true;
    // Draw the face in the background's own posture (render/PostureTransfer).
    bool keepPosture = true;
    PhoneRecognizerOptions recognizer;
};

struct LiveFrame
{
    int index = 0;
    int label = 0;            // the frame's phone (PhoneSet index)
    Eigen::VectorXd features; // generated AAM parameters as rendered: lips closed on /p b m/, the
                              // background's posture kept
    cv::Mat image;            // rendered (empty without a renderer)
    double soundEnd = 0.0;    // seconds: the newest sound the frame shows, (index + 1) / frameRate
};

class LiveSession
{
public:
    // `renderer` may be null (features only); it must outlive the session. Throws lipsync::Error
    // for an untrained model, one whose dimension is not the renderer's AAM's, or an acoustic
    // model the recogniser cannot use.
    LiveSession(const AcousticModel &acoustic, const PhoneBigram &bigram, const DynamicModel &model,
                FaceRenderer *renderer, const LiveOptions &options = {});
    // The same with another recogniser (options.recognizer is then not used); push() takes sound
    // at its frameOptions().sampleRate.
    LiveSession(std::unique_ptr<PhoneStream> recognizer, const DynamicModel &model, FaceRenderer *renderer,
                const LiveOptions &options = {});
    ~LiveSession();

    // Feeds mono sound at the acoustic model's sample rate; returns the frames that became ready.
    std::vector<LiveFrame> push(const float *samples, size_t count);
    // The sound has ended: the frames it lasts (round(duration x frameRate)) are all made ready.
    std::vector<LiveFrame> finish();

    double frameRate() const { return m_frameRate; }
    // The recogniser's audio frames (their timing, and the sample rate push() takes).
    const MfccOptions &audioFrames() const { return m_audio; }
    double soundSeconds() const;
    // The recognised phones so far, one interval per run of 100 Hz frames with the same phone.
    const Tier &phones() const { return m_phones; }
    // The phone of every frame handed out so far.
    const std::vector<int> &frameLabels() const { return m_labels; }
    // Sound a frame waits for after its interval's end: the recogniser's look-ahead and the
    // generator's when it is fixed (generatorLatencyFrames() >= 0).
    double latencySeconds() const;
    // The generator's look-ahead in frames, -1 when it varies: a model over phones in context
    // (§5.2) holds each phone's frames until the next phone starts.
    int generatorLatencyFrames() const;

private:
    void takeDecisions();
    void labelReadyFrames(bool final, std::vector<LiveFrame> &out);
    void generate(int label, std::vector<LiveFrame> &out);
    void drain(std::vector<LiveFrame> &out);

    const DynamicModel &m_model;
    FaceRenderer *m_renderer;
    std::unique_ptr<PhoneStream> m_recognizer;
    std::unique_ptr<StreamingGenerator> m_generator;
    MfccOptions m_audio;
    double m_frameRate = 25.0;
    bool m_still = false;
    std::optional<BilabialClosure> m_closure;
    std::shared_ptr<const PostureTransfer> m_posture;
    long m_samples = 0;
    std::deque<int> m_recent;   // decided audio frames not yet needed by every later frame's vote
    long m_recentFirst = 0;     // audio frame index of m_recent.front()
    long m_decided = 0;
    int m_labelled = 0;         // video frames labelled (pushed to the generator)
    int m_generated = 0;        // frames handed out
    std::vector<int> m_labels;
    Tier m_phones{"phones", {}};
};

} // namespace lipsync
