#include "project/Sequence.h"

#include <sstream>

namespace lipsync {

bool Sequence::operator==(const Sequence &other) const
{
    // Eigen's == on matrices of different sizes asserts, so compare the shapes first.
    const bool sameFeatures = features.rows() == other.features.rows()
                              && features.cols() == other.features.cols()
                              && (features.size() == 0 || features == other.features);
    return sameFeatures && id == other.id && mediaFile == other.mediaFile
           && frameRate == other.frameRate && frameCount == other.frameCount
           && firstFrameTime == other.firstFrameTime && frameTimes == other.frameTimes
           && transcript == other.transcript
           && transcriptProposed == other.transcriptProposed && transcriptFit == other.transcriptFit
           && transcriptConfidence == other.transcriptConfidence
           && landmarks == other.landmarks
           && words == other.words && phones == other.phones && fitErrors == other.fitErrors;
}

std::vector<std::string> Sequence::transcriptWords(const std::string &transcript)
{
    std::vector<std::string> words;
    std::istringstream in(transcript);
    for (std::string word; in >> word;)
        words.push_back(word);
    return words;
}

FrameClock Sequence::clock() const
{
    if (!frameTimes.empty() && int(frameTimes.size()) == frameCount)
        return FrameClock::fromTimes(frameTimes, frameRate);
    return FrameClock::uniform(frameRate, frameCount, firstFrameTime);
}

void Sequence::setClock(const FrameClock &clock)
{
    frameRate = clock.rate();
    frameCount = clock.count();
    firstFrameTime = clock.startTime();
    frameTimes = clock.isVariable() ? clock.times() : std::vector<double>{};
}

} // namespace lipsync
