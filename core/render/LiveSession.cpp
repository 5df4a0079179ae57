#include "render/LiveSession.h"

#include "align/AcousticModel.h"
#include "align/FrameLabels.h"
#include "dynamics/DynamicModel.h"
#include "render/FaceRenderer.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>

namespace lipsync {

LiveSession::LiveSession(const AcousticModel &acoustic, const PhoneBigram &bigram, const DynamicModel &model,
                         FaceRenderer *renderer, const LiveOptions &options)
    : LiveSession(std::make_unique<StreamingPhoneRecognizer>(acoustic, bigram, options.recognizer), model, renderer,
                  options)
{
}

LiveSession::LiveSession(std::unique_ptr<PhoneStream> recognizer, const DynamicModel &model, FaceRenderer *renderer,
                         const LiveOptions &options)
    : m_model(model), m_renderer(renderer), m_recognizer(std::move(recognizer)),
      m_audio(m_recognizer->frameOptions())
{
    if (!model.isTrained())
        throw Error("the dynamic model is not trained");
    if (renderer && renderer->aam().combinedModes() != model.dimension())
        throw Error("the model generates " + std::to_string(model.dimension()) + " parameters, the AAM has "
                    + std::to_string(renderer->aam().combinedModes()));
    m_frameRate = options.frameRate > 0 ? options.frameRate : model.frameRate() > 0 ? model.frameRate() : 25.0;
    m_generator = model.promptStreamer();
    m_still = options.stillBackground;
    if (renderer && options.closeBilabials)
        m_closure = BilabialClosure::forAam(renderer->aam());
    if (renderer && options.keepPosture)
        m_posture = PostureTransfer::forModel(model, renderer->aam());
}

LiveSession::~LiveSession() = default;

double LiveSession::soundSeconds() const
{
    return double(m_samples) / m_audio.sampleRate;
}

double LiveSession::latencySeconds() const
{
    // The decision a frame waits for is that of the first audio frame centred past its end.
    return m_recognizer->latencySeconds() + m_audio.shiftSeconds + std::max(0, m_generator->latency()) / m_frameRate;
}

int LiveSession::generatorLatencyFrames() const
{
    return m_generator->latency();
}

std::vector<LiveFrame> LiveSession::push(const float *samples, size_t count)
{
    std::vector<LiveFrame> out;
    m_recognizer->push(samples, count);
    m_samples += long(count);
    takeDecisions();
    labelReadyFrames(false, out);
    return out;
}

std::vector<LiveFrame> LiveSession::finish()
{
    std::vector<LiveFrame> out;
    m_recognizer->finish();
    takeDecisions();
    labelReadyFrames(true, out);
    m_generator->finish();
    drain(out);
    return out;
}

void LiveSession::takeDecisions()
{
    const std::vector<int> decided = m_recognizer->takeDecided();
    StreamingPhoneRecognizer::appendToTier(m_phones, int(m_decided), decided, m_audio);
    m_recent.insert(m_recent.end(), decided.begin(), decided.end());
    m_decided += long(decided.size());
}

void LiveSession::labelReadyFrames(bool final, std::vector<LiveFrame> &out)
{
    const double half = m_audio.shiftSeconds / 2;
    const int total = int(std::lround(soundSeconds() * m_frameRate));
    for (;;) {
        const int i = m_labelled;
        // Live frames are shown every 1 / rate from the first sound.
        const FrameClock clock = FrameClock::uniform(m_frameRate, i + 1);
        const double end = clock.endTime(i);
        if (final ? i >= total : mfccFrameCentre(int(m_decided), m_audio) < end - 1e-12)
            return;
        // The decided audio frames this frame's vote reads, as a tier (docs/models.md §0).
        Tier recent{"phones", {}};
        for (size_t k = 0; k < m_recent.size(); ++k) {
            const double c = mfccFrameCentre(int(m_recentFirst + long(k)), m_audio);
            recent.intervals.push_back(Interval{c - half, c + half, PhoneSet::label(m_recent[k]), false});
        }
        const int label = PhoneSet::index(voteFrameLabels(recent, clock, i, 1, m_audio).front());
        ++m_labelled;
        m_labels.push_back(label < 0 ? int(PhoneSet::kSilence) : label);
        // The next frame's vote starts at its own interval.
        while (!m_recent.empty() && mfccFrameCentre(int(m_recentFirst), m_audio) < end - m_audio.shiftSeconds) {
            m_recent.pop_front();
            ++m_recentFirst;
        }
        generate(m_labels.back(), out);
    }
}

void LiveSession::generate(int label, std::vector<LiveFrame> &out)
{
    m_generator->push(label);
    drain(out);
}

void LiveSession::drain(std::vector<LiveFrame> &out)
{
    Eigen::VectorXd y(m_model.dimension());
    while (m_generator->pop(y)) {
        LiveFrame frame;
        frame.index = m_generated++;
        frame.label = m_labels[size_t(frame.index)];
        frame.features = y;
        if (m_closure && PhoneSet::isBilabial(frame.label))
            frame.features = m_closure->apply(y.transpose(), {1.0}).transpose();
        if (m_renderer) {
            const int shown = m_still ? 0 : frame.index;
            if (m_posture)
                frame.features = m_posture->apply(frame.features, m_renderer->posture(shown));
            frame.image = m_renderer->render(shown, frame.features);
        }
        frame.soundEnd = (frame.index + 1) / m_frameRate;
        out.push_back(std::move(frame));
    }
}

} // namespace lipsync
