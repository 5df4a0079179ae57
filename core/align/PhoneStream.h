#pragma once
// Phone recognition as the sound comes in, without a transcript (docs/pipeline.md, "Live"), behind
// one interface: the aligner's own monophone HMMs in a phone loop (StreamingPhoneRecognizer,
// trained on the speaker) and CMU Sphinx's US-English all-phone search (SphinxPhoneRecognizer,
// any speaker). Both decide one phone per 10 ms audio frame, a fixed number of frames behind the
// newest sound, and never revise a decision.
#include "audio/Mfcc.h"

#include <cstddef>
#include <vector>

namespace lipsync {

class PhoneStream
{
public:
    virtual ~PhoneStream() = default;

    // Feeds mono samples at frameOptions().sampleRate, in [-1, 1].
    virtual void push(const float *samples, size_t count) = 0;
    // No more sound: every frame left is decided.
    virtual void finish() = 0;
    // The phones decided since the last call, one per audio frame, in order (PhoneSet indices);
    // frame j of the sound is the j-th label handed out overall.
    virtual std::vector<int> takeDecided() = 0;
    virtual int decidedFrames() const = 0;
    // Sound a decision waits for after its frame's centre.
    virtual double latencySeconds() const = 0;
    // The audio frames' timing (mfccFrameCentre) and the sample rate push() expects.
    virtual const MfccOptions &frameOptions() const = 0;
};

} // namespace lipsync
