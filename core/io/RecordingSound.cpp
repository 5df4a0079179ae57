#include "io/RecordingSound.h"

#include "io/SoundResampler.h"

#include <algorithm>

namespace lipsync {

std::shared_ptr<const AudioBuffer> RecordingSound::own() const
{
    const std::lock_guard lock(m_mutex);
    if (!m_own)
        m_own = std::make_shared<const AudioBuffer>(AudioDecoder::decode(m_path, 0));
    return m_own;
}

std::shared_ptr<const AudioBuffer> RecordingSound::at(int sampleRate) const
{
    std::shared_ptr<const AudioBuffer> kept;
    {
        const std::lock_guard lock(m_mutex);
        kept = m_own;
    }
    if (!kept)
        return sampleRate <= 0 ? own() : std::make_shared<const AudioBuffer>(AudioDecoder::decode(m_path, sampleRate));
    if (sampleRate <= 0 || sampleRate == kept->sampleRate)
        return kept;
    auto out = std::make_shared<AudioBuffer>();
    out->sampleRate = sampleRate;
    out->startTime = kept->startTime;
    if (kept->samples.empty())
        return out;
    SoundResampler resampler(kept->sampleRate, 1, sampleRate);
    out->samples = resampler.push(kept->samples.data(), kept->samples.size());
    const std::vector<float> rest = resampler.flush();
    out->samples.insert(out->samples.end(), rest.begin(), rest.end());
    for (float &s : out->samples) // as AudioDecoder leaves them
        s = std::clamp(s, -1.0f, 1.0f);
    return out;
}

} // namespace lipsync
