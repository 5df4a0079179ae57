#include "align/SphinxPhoneRecognizer.h"

#include "align/SphinxAligner.h"
#include "align/SphinxBackend.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <malloc.h>
#include <utility>

namespace lipsync {

SphinxPhoneRecognizer::SphinxPhoneRecognizer(const SphinxPhoneOptions &options) : m_options(options)
{
    m_frames.sampleRate = SphinxAligner::kSampleRate;
    m_frames.shiftSeconds = 0.01;
    m_frames.windowSeconds = 0.025625; // pocketsphinx's -wlen
    if (m_options.lagFrames < 0)
        throw Error("the recognition lag must be 0 frames or more");
    const std::string hmm = SphinxAligner::resolveModelDir(m_options.modelDir);
    const std::string lm = (std::filesystem::path(hmm).parent_path() / "en-us-phone.lm.bin").string();
    for (const std::string &file : {hmm + "/mdef", lm})
        if (!std::filesystem::exists(file))
            throw Error("not found: CMU Sphinx's US-English phone models (Debian package pocketsphinx-en-us)", file);
    m_loop = std::make_unique<SphinxPhoneLoop>(
        hmm, lm,
        std::vector<std::pair<std::string, std::string>>{{"-lw", std::to_string(m_options.languageWeight)}});
    m_loop->start();
}

SphinxPhoneRecognizer::~SphinxPhoneRecognizer() = default;

int SphinxPhoneRecognizer::phoneIndex(const std::string &sphinxPhone)
{
    if (!sphinxPhone.empty() && sphinxPhone.front() == '+')
        return PhoneSet::kBreath; // +NSN+, +SPN+, +BREATH+ ...: noises
    const int index = PhoneSet::index(sphinxPhone);
    return index >= 0 ? index : int(PhoneSet::kSilence);
}

double SphinxPhoneRecognizer::latencySeconds() const
{
    return (m_options.lagFrames + kFeatureLookahead) * m_frames.shiftSeconds + m_frames.windowSeconds / 2;
}

void SphinxPhoneRecognizer::push(const float *samples, size_t count)
{
    const std::vector<short> pcm = toPcm16(samples, count);
    m_pcm.insert(m_pcm.end(), pcm.begin(), pcm.end());
    m_samples += long(count);
    m_loop->process(pcm.data(), pcm.size());
    decide(false);
}

void SphinxPhoneRecognizer::finish()
{
    m_loop->end();
    decide(true);
    // Ending an utterance does not always search its last frames (the deltas' look-ahead): those
    // keep the last decision, so every 10 ms of the sound has one.
    for (; m_decided < m_samples / shiftSamples(); ++m_decided)
        m_ready.push_back(m_last < 0 ? int(PhoneSet::kSilence) : m_last);
}

long SphinxPhoneRecognizer::shiftSamples() const
{
    return std::lround(m_frames.shiftSeconds * m_frames.sampleRate);
}

std::vector<int> SphinxPhoneRecognizer::takeDecided()
{
    return std::exchange(m_ready, {});
}

void SphinxPhoneRecognizer::decide(bool all)
{
    const int searched = m_loop->frames();
    const int until = m_utteranceStart + (all ? searched : searched - m_options.lagFrames);
    if (until <= m_decided)
        return;
    const std::vector<SphinxPhoneLoop::Segment> path = m_loop->segments();
    size_t s = 0;
    for (; m_decided < until; ++m_decided) {
        const int local = m_decided - m_utteranceStart;
        while (s < path.size() && path[s].last < local)
            ++s;
        m_last = s < path.size() && path[s].first <= local ? phoneIndex(path[s].phone) : int(PhoneSet::kSilence);
        m_ready.push_back(m_last);
    }
    // The sound before the first undecided frame is not needed again.
    const long drop = std::min(long(m_decided) * shiftSamples() - m_pcmFirst, long(m_pcm.size()));
    if (drop > 0) {
        m_pcm.erase(m_pcm.begin(), m_pcm.begin() + drop);
        m_pcmFirst += drop;
    }
    // A restart at a silence costs nothing; speech that never pauses is cut at three times that.
    const double running = (m_decided - m_utteranceStart) * m_frames.shiftSeconds;
    if (!all && ((m_last == PhoneSet::kSilence && running >= m_options.restartSeconds)
                 || running >= 3.0 * m_options.restartSeconds))
        restart();
}

void SphinxPhoneRecognizer::restart()
{
    m_loop->start();
    // The search frees its many small blocks when the utterance ends; glibc keeps the heap they
    // fragmented unless asked to give it back.
    malloc_trim(0);
    m_utteranceStart = m_decided;
    const std::vector<short> again(m_pcm.begin(), m_pcm.end());
    m_loop->process(again.data(), again.size());
}

} // namespace lipsync
