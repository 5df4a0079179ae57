#pragma once
// CMU Sphinx's US-English phones as the sound comes in, for any speaker (Debian's
// pocketsphinx-en-us: the en-us acoustic model and its phone language model en-us-phone.lm.bin):
// pocketsphinx's all-phone search over its context-independent phones (-allphone_ci: with the
// triphones the search ran at 1-7 x real time on one core, here 18 x faster) fed block by block
// (SphinxBackend's SphinxPhoneLoop). After each block the best phone path so far is read, and the
// frames `lagFrames` behind the newest frame searched are decided from it, never revised (as
// StreamingPhoneRecognizer's fixed lag).
//
// The search keeps every frame of its utterance, so memory would grow with the session: once
// `restartSeconds` have been decided and the newest decision is silence (or three times that
// without one), the utterance is ended and a new one is started on the sound from the first
// undecided frame on (kept for that), the cepstral mean carried over; the ended utterance's freed
// blocks are handed back to the system. The model's phones map to
// PhoneSet's 39 ARPAbet labels; SIL is silence, the fillers (+NSN+, +SPN+, ...) breath/noise.
#include "align/PhoneStream.h"

#include <deque>
#include <memory>
#include <string>
#include <vector>

namespace lipsync {

class SphinxPhoneLoop;

struct SphinxPhoneOptions
{
    std::string modelDir;          // empty: SphinxAligner::resolveModelDir (Debian's en-us)
    int lagFrames = 10;            // 10 ms frames between the newest searched and a decision
    double languageWeight = 2.0;   // pocketsphinx -lw: the phone language model's weight
    double restartSeconds = 20.0;  // decided sound after which the search restarts at a silence
};

class SphinxPhoneRecognizer : public PhoneStream
{
public:
    // Sphinx's frames run 10 ms apart over 25.625 ms windows; its features reach this many frames
    // past a frame (the deltas' window), so a frame is searched that much after its sound.
    static constexpr int kFeatureLookahead = 4;

    // Throws lipsync::Error naming the folder or file of the models when they do not load.
    explicit SphinxPhoneRecognizer(const SphinxPhoneOptions &options = {});
    ~SphinxPhoneRecognizer() override;

    void push(const float *samples, size_t count) override;
    void finish() override;
    std::vector<int> takeDecided() override;
    int decidedFrames() const override { return m_decided; }
    double latencySeconds() const override;
    const MfccOptions &frameOptions() const override { return m_frames; }

    // The PhoneSet index of one of the model's phones.
    static int phoneIndex(const std::string &sphinxPhone);

private:
    void decide(bool all);
    long shiftSamples() const; // samples between frames
    void restart();

    SphinxPhoneOptions m_options;
    MfccOptions m_frames;
    std::unique_ptr<SphinxPhoneLoop> m_loop;
    int m_utteranceStart = 0;     // sound frame of the running utterance's frame 0
    std::deque<short> m_pcm;      // the sound from the first undecided frame on
    long m_pcmFirst = 0;          // sample index of m_pcm.front()
    long m_samples = 0;           // samples pushed
    int m_decided = 0;
    std::vector<int> m_ready;
    int m_last = -1;              // the newest decision
};

} // namespace lipsync
