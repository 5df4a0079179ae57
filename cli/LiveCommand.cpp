// `lipsync live --input FILE --model M --aam A [--out OUT.mp4]`: the studio's Live view without a
// microphone (render/LiveSession): the file's sound fed block by block at real-time pace (or as
// fast as possible) through streaming phone recognition, streaming generation and rendering;
// reports the latency from sound to rendered frame, the recognised phones and, given the
// transcript, their error against a forced alignment.
#include "AlignerSupport.h"
#include "CommandLine.h"
#include "Compositing.h"
#include "DynamicModelOptions.h"

#include "aam/AamModel.h"
#include "align/Aligner.h"
#include "align/FrameLabels.h"
#include "align/Lexicon.h"
#include "align/PhoneErrorRate.h"
#include "align/ShippedAlignerModel.h"
#include "align/SphinxPhoneRecognizer.h"
#include "align/StreamingPhoneRecognizer.h"
#include "dynamics/ModelFile.h"
#include "io/AudioDecoder.h"
#include "io/MediaInfo.h"
#include "io/Transcript.h"
#include "io/VideoReader.h"
#include "render/CameraCompositor.h"
#include "render/FaceRenderer.h"
#include "render/LiveSession.h"
#include "render/VideoExporter.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <QJsonArray>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

using namespace lipsync;
using namespace lipsync::cli;

namespace {

using Clock = std::chrono::steady_clock;

double secondsBetween(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

// Encodes the recorded frames on a thread of its own, so that H.264 encoding never holds up the
// next block of sound (the frames wait in a queue; a live session makes 25 a second). The queue
// holds at most kMaxQueued frames: fed faster than the encoder writes (--as-fast-as-possible),
// add() waits for room, so memory stays bounded whatever the input's length.
class FrameRecorder
{
public:
    static constexpr size_t kMaxQueued = 50; // 2 s at 25 frames/s

    explicit FrameRecorder(std::unique_ptr<VideoExporter> exporter)
        : m_exporter(std::move(exporter)), m_thread([this] { run(); })
    {
    }
    ~FrameRecorder()
    {
        stop();
    }
    void add(const cv::Mat &frame)
    {
        std::unique_lock lock(m_mutex);
        m_room.wait(lock, [this] { return m_frames.size() < kMaxQueued || m_done; });
        m_frames.push_back(frame);
        m_ready.notify_one();
    }
    // Writes what is queued and the file's end; rethrows an encoding error.
    void finish()
    {
        stop();
        if (m_error)
            std::rethrow_exception(m_error);
        m_exporter->finish();
    }

private:
    void stop()
    {
        {
            const std::lock_guard lock(m_mutex);
            m_done = true;
            m_ready.notify_one();
        }
        if (m_thread.joinable())
            m_thread.join();
    }
    void run()
    {
        for (;;) {
            cv::Mat frame;
            {
                std::unique_lock lock(m_mutex);
                m_ready.wait(lock, [this] { return m_done || !m_frames.empty(); });
                if (m_frames.empty())
                    return;
                frame = std::move(m_frames.front());
                m_frames.pop_front();
                m_room.notify_one();
            }
            try {
                if (!m_error)
                    m_exporter->addFrame(frame);
            } catch (...) {
                m_error = std::current_exception();
            }
        }
    }

    std::unique_ptr<VideoExporter> m_exporter;
    std::mutex m_mutex;
    std::condition_variable m_ready, m_room;
    std::deque<cv::Mat> m_frames;
    bool m_done = false;
    std::exception_ptr m_error;
    std::thread m_thread;
};

// The reference of --transcript: the forced alignment's phones, by the same acoustic model.
Tier referencePhones(const QString &aligner, const QString &input, const QString &transcriptPath,
                     const QString &pronunciations)
{
    const std::unique_ptr<Aligner> forced = createAligner(AlignerChoice{aligner.toStdString(), false});
    const auto lexicon = makeLexicon(pronunciations);
    const Transcript transcript = readTranscript(transcriptPath.toStdString());
    return forced
        ->align(input.toStdString(), transcript.words, *lexicon, Feedback::none(), transcriptPath.toStdString())
        .alignment.phones;
}

// The recogniser: our HMMs of the speaker with a phone bigram (loaded into `acoustic` and
// `bigram`, which it reads), or CMU Sphinx's for anyone.
std::unique_ptr<PhoneStream> makeRecognizer(const CommandLine &a, const AlignerChoice &choice,
                                            std::optional<AcousticModel> &acoustic, PhoneBigram &bigram)
{
    if (choice.isSphinx()) {
        if (a.isSet("bigram"))
            throw UsageError(QStringLiteral("--bigram is for our aligner models; CMU Sphinx has its own phone "
                                            "language model"));
        SphinxPhoneOptions sphinxOptions;
        sphinxOptions.modelDir = choice.sphinxModelDir();
        if (a.isSet("lag"))
            sphinxOptions.lagFrames = a.integer("lag", 0);
        return std::make_unique<SphinxPhoneRecognizer>(sphinxOptions);
    }
    QString bigramPath = a.value("bigram");
    if (bigramPath.isEmpty())
        bigramPath = QString::fromStdString(shippedPhoneBigramPath());
    if (bigramPath.isEmpty())
        throw Error("no phone bigram: give one with --bigram (lipsync aligner bigram)");
    acoustic = AcousticModel::load(choice.model);
    bigram = PhoneBigram::load(bigramPath.toStdString());
    PhoneRecognizerOptions ours;
    if (a.isSet("lag"))
        ours.lagFrames = a.integer("lag", 0);
    return std::make_unique<StreamingPhoneRecognizer>(*acoustic, bigram, ours);
}

struct LatencySummary
{
    double mean = 0, worst = 0, p95 = 0; // seconds
};

LatencySummary summarise(const std::vector<double> &latencies)
{
    LatencySummary s;
    for (double l : latencies) {
        s.mean += l;
        s.worst = std::max(s.worst, l);
    }
    s.mean /= double(std::max<size_t>(1, latencies.size()));
    std::vector<double> sorted = latencies;
    std::sort(sorted.begin(), sorted.end());
    s.p95 = sorted.empty() ? 0.0 : sorted[std::min(sorted.size() - 1, sorted.size() * 95 / 100)];
    return s;
}

// The --json report of a session: frames, pace, latencies, the phones recognised.
QJsonObject sessionReport(const LiveSession &session, const std::vector<int> &recognised, const LatencySummary &latency,
                          int frames, double seconds, double soundSeconds)
{
    QJsonArray phones;
    for (int p : recognised)
        phones.append(QString::fromStdString(PhoneSet::label(p)));
    return QJsonObject{{QStringLiteral("frames"), frames},
                       {QStringLiteral("frameRate"), session.frameRate()},
                       {QStringLiteral("soundSeconds"), soundSeconds},
                       {QStringLiteral("seconds"), seconds},
                       {QStringLiteral("fps"), frames / std::max(seconds, 1e-9)},
                       {QStringLiteral("latency_ms_mean"), 1000 * latency.mean},
                       {QStringLiteral("latency_ms_max"), 1000 * latency.worst},
                       {QStringLiteral("latency_ms_p95"), 1000 * latency.p95},
                       {QStringLiteral("latency_ms_algorithmic"), 1000 * session.latencySeconds()},
                       // -1: the model's face waits for each phone to end (phones in context, a model
                       // file without the guess of them).
                       {QStringLiteral("generator_latency_frames"), session.generatorLatencyFrames()},
                       {QStringLiteral("phones"), phones}};
}

// Against the transcript's forced alignment: the phone error rate of what was recognised, and the
// share of frames whose label matches the alignment's vote.
void addAccuracy(QJsonObject &o, const Tier &reference, const LiveSession &session, const std::vector<int> &recognised,
                 int frames)
{
    o[QStringLiteral("phone_error_rate")] = phoneErrorRate(spokenPhones(reference), recognised);
    const std::vector<std::string> truth =
        voteFrameLabels(reference, FrameClock::uniform(session.frameRate(), frames), session.audioFrames());
    int same = 0;
    for (int i = 0; i < frames; ++i)
        same += PhoneSet::index(truth[size_t(i)]) == session.frameLabels()[size_t(i)];
    o[QStringLiteral("frame_accuracy")] = frames ? double(same) / frames : 0.0;
}

void printReport(const QJsonObject &o, size_t phones)
{
    std::printf("%d frames at %.3g frames/s in %.2f s (%.0f frames/s); latency from sound to frame %.0f ms mean, "
                "%.0f ms max; %zu phones recognised",
                o.value("frames").toInt(), o.value("frameRate").toDouble(), o.value("seconds").toDouble(),
                o.value("fps").toDouble(), o.value("latency_ms_mean").toDouble(), o.value("latency_ms_max").toDouble(),
                phones);
    if (o.contains(QStringLiteral("phone_error_rate")))
        std::printf("; phone error rate %.1f %%, frame labels %.1f %% right",
                    100 * o.value("phone_error_rate").toDouble(), 100 * o.value("frame_accuracy").toDouble());
    std::printf("\n");
}

int runLive(const CommandLine &a)
{
    const QString input = a.value("input");
    const QString alignerPath = alignerModelOrDefault(a.value("aligner"), QStringLiteral("live"));
    const AlignerChoice alignerChoice{alignerPath.toStdString()};
    const double blockSeconds = a.positiveNumber("block-ms") / 1000.0;
    const bool fast = a.isSet("as-fast-as-possible");

    std::optional<AcousticModel> acoustic;
    PhoneBigram bigram;
    std::unique_ptr<PhoneStream> recognizer = makeRecognizer(a, alignerChoice, acoustic, bigram);
    const int sampleRate = recognizer->frameOptions().sampleRate;
    const AamModel aam = AamModel::load(a.value("aam").toStdString());
    const std::shared_ptr<DynamicModel> model = loadModel(a.value("model").toStdString(), aam.identifier);
    LiveOptions options;
    options.stillBackground = a.isSet("still");
    options.closeBilabials = Compositing::closesLips(a);
    options.keepPosture = Compositing::keepsPosture(a);
    if (a.isSet("fps"))
        options.frameRate = a.positiveNumber("fps");

    if (a.isSet("camera") && (a.isSet("background") || a.isSet("still")))
        throw UsageError(QStringLiteral("--camera is the background: not with --background or --still"));
    // The background: --background, else the input's own video, else the mean face on grey;
    // with --camera, each frame is drawn again into that video's frame as it comes (the Live
    // view's camera), the session's own rendering standing for the frames without a face.
    const QString background = a.isSet("camera")       ? QString()
                               : a.isSet("background") ? a.value("background")
                               : MediaInfo::probe(input.toStdString()).hasVideo ? input
                                                                                 : QString();
    std::unique_ptr<VideoReader> camera;
    std::unique_ptr<CameraCompositor> cameraCompositor;
    if (a.isSet("camera")) {
        camera = std::make_unique<VideoReader>(a.value("camera").toStdString());
        cameraCompositor = std::make_unique<CameraCompositor>(aam);
    }
    int cameraFaces = 0;
    Feedback tracking;
    const std::unique_ptr<FaceRenderer> renderer =
        background.isEmpty() ? std::make_unique<FaceRenderer>(aam)
                             : std::make_unique<FaceRenderer>(aam, background.toStdString(), tracking, nullptr,
                                                              options.stillBackground ? 1 : 0);
    const CompositeOptions composite = Compositing::from(a);
    renderer->setCompositeOptions(composite);
    const AudioBuffer sound = AudioDecoder::decode(input.toStdString(), sampleRate);
    LiveSession session(std::move(recognizer), *model, renderer.get(), options);

    std::unique_ptr<FrameRecorder> recorder;
    if (a.isSet("out")) {
        // The frames Live draws (one per 1 / rate for as long as the sound lasts), the sound
        // fitted to them.
        VideoExportOptions v;
        v.setFrames(FrameClock::uniform(session.frameRate(), int(std::lround(sound.duration() * session.frameRate()))));
        recorder = std::make_unique<FrameRecorder>(std::make_unique<VideoExporter>(a.value("out").toStdString(), v, &sound));
    }
    std::vector<double> latencies;
    int frames = 0;
    // A frame's latency: from the moment the newest sound it shows was spoken to the moment it is
    // rendered. Spoken at start + soundEnd when fed at real-time pace; as fast as possible, the
    // sound fed so far stands for the time, plus the processing of the block that made it ready.
    auto take = [&](const std::vector<LiveFrame> &ready, double fedSeconds, double processing, double now) {
        for (const LiveFrame &f : ready) {
            cv::Mat image = f.image;
            double composing = 0.0;
            if (camera) {
                // The camera's frame on screen at this frame's time (its last one once it has ended).
                const Clock::time_point t0 = Clock::now();
                const double shown = FrameClock::uniform(session.frameRate(), f.index + 1).time(f.index);
                cv::Mat frame = camera->frame(camera->clock().frameAt(shown)).clone();
                if (cameraCompositor->compose(frame, f.features, composite)) {
                    ++cameraFaces;
                    image = frame;
                } else {
                    cv::resize(f.image, image, frame.size());
                }
                composing = secondsBetween(t0, Clock::now());
            }
            latencies.push_back(fast ? fedSeconds - f.soundEnd + processing + composing
                                     : now + composing - f.soundEnd);
            if (recorder)
                recorder->add(image);
            ++frames;
        }
    };
    const size_t block = std::max<size_t>(1, size_t(std::lround(blockSeconds * sound.sampleRate)));
    const Clock::time_point start = Clock::now();
    for (size_t at = 0; at < sound.samples.size(); at += block) {
        const size_t n = std::min(block, sound.samples.size() - at);
        const double fed = double(at + n) / sound.sampleRate;
        if (!fast)
            std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(
                                                      std::chrono::duration<double>(fed)));
        const Clock::time_point before = Clock::now();
        const std::vector<LiveFrame> ready = session.push(sound.samples.data() + at, n);
        const Clock::time_point after = Clock::now();
        take(ready, fed, secondsBetween(before, after), secondsBetween(start, after));
    }
    const Clock::time_point before = Clock::now();
    const std::vector<LiveFrame> rest = session.finish();
    take(rest, sound.duration(), secondsBetween(before, Clock::now()), secondsBetween(start, Clock::now()));
    const double seconds = secondsBetween(start, Clock::now());
    if (recorder)
        recorder->finish();

    const std::vector<int> recognised = spokenPhones(session.phones());
    QJsonObject o = sessionReport(session, recognised, summarise(latencies), frames, seconds, sound.duration());
    o[QStringLiteral("input")] = input;
    if (a.isSet("transcript"))
        addAccuracy(o, referencePhones(alignerPath, input, a.value("transcript"), a.value("pronunciations")), session,
                    recognised, frames);
    if (recorder)
        o[QStringLiteral("out")] = a.value("out");
    if (camera)
        o[QStringLiteral("camera_frames_with_face")] = cameraFaces;
    if (a.isSet("json"))
        printJson(o);
    else
        printReport(o, recognised.size());
    return 0;
}

const CommandRegistration registration{
    CommandSpec{
        QStringLiteral("live"),
        QStringLiteral("speech to a moving face as the sound comes in, from a file (the Live view, headless)"),
        QStringLiteral("Feeds the sound of a file block by block, at real-time pace unless --as-fast-as-possible, "
                       "through what the studio's Live view runs on the microphone: phone recognition without a "
                       "transcript (the aligner's HMMs in a phone loop with a phone bigram, fixed-lag Viterbi), "
                       "the dynamic model's frame-by-frame generation and the AAM face rendered into the "
                       "background. Reports the latency from sound to rendered frame (the newest sound a frame "
                       "shows to the frame drawn) and the recognised phones; with --transcript, their error "
                       "rate against the forced alignment and the share of frames with the right phone."),
        {{QStringLiteral("input"), QStringLiteral("FILE"), QStringLiteral("the sound (any audio or video file)"), {},
          CommandOption::Required},
         {QStringLiteral("model"), QStringLiteral("MODEL"),
          QStringLiteral("a trained dynamic model (lipsync train); phones in context (--context-states) wait "
                         "for their phone to end 4 frames at most, then are guessed (a model file written without "
                         "that guess waits for each phone to end: generator_latency_frames -1)"),
          {}, CommandOption::Required},
         {QStringLiteral("aam"), QStringLiteral("AAM"), QStringLiteral("the AAM the model generates parameters of"), {},
          CommandOption::Required},
         {QStringLiteral("out"), QStringLiteral("OUT.mp4"), QStringLiteral("record the session (frames and sound)")},
         {QStringLiteral("aligner"), QStringLiteral("MODEL|sphinx[:DIR]"),
          QStringLiteral("the aligner model whose HMMs recognise (default: the shipped GRID s1 model), or sphinx for "
                         "CMU Sphinx's US-English phone recogniser, for any speaker (Debian's pocketsphinx-en-us)")},
         {QStringLiteral("bigram"), QStringLiteral("FILE"),
          QStringLiteral("the phone bigram of our aligner models (lipsync aligner bigram; default: the shipped GRID s1 "
                         "one)")},
         {QStringLiteral("transcript"), QStringLiteral("FILE"),
          QStringLiteral("the words spoken, to measure the recognised phones against their forced alignment")},
         {QStringLiteral("background"), QStringLiteral("MEDIA"),
          QStringLiteral("the video to draw the face into (default: the input's video, else the mean face on grey)")},
         {QStringLiteral("still"), {}, QStringLiteral("draw every frame into the background's first frame")},
         {QStringLiteral("camera"), QStringLiteral("VIDEO"),
          QStringLiteral("a video standing for a camera: each frame's face is found as the frame comes, not "
                         "tracked beforehand, and the generated face drawn over it (the Live view's camera)")},
         {QStringLiteral("lag"), QStringLiteral("FRAMES"),
          QStringLiteral("100 Hz frames the phone decisions wait for (latency against accuracy; default: 6 with our "
                         "models, 10 with sphinx)")},
         {QStringLiteral("block-ms"), QStringLiteral("MS"), QStringLiteral("milliseconds of sound per block fed"),
          QStringLiteral("10")},
         {QStringLiteral("fps"), QStringLiteral("RATE"),
          QStringLiteral("frames per second (default: the rate the model was trained at)")},
         {QStringLiteral("as-fast-as-possible"), {}, QStringLiteral("feed the sound without waiting for real time")},
         pronunciationsOption()},
        {}}
        .add(Compositing::options()),
    &runLive};

} // namespace
