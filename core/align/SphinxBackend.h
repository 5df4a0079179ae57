#pragma once
// The one file pair that touches libpocketsphinx (Debian's 0.8+5prealpha): what SphinxAligner
// needs of it, in its own types.
//  - SphinxDecoder: a decoder configuration (ps_init) for a model folder — the expanded model
//    files and feature options, and the log table senone scores are in.
//  - SphinxUtterance: one utterance's features and senone scorer (pocketsphinx's acmod, whose
//    functions the library exports but declares only in a private header; the signatures and
//    the start of its struct are pinned in the .cpp and checked at run time).
//  - SphinxPhoneLoop: pocketsphinx's all-phone search (a phone loop under a phone language
//    model) fed block by block, with the best phone path so far.
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lipsync {

// Samples in [-1, 1] (clipped beyond) as the 16-bit PCM pocketsphinx reads.
std::vector<short> toPcm16(const float *samples, size_t count);
std::vector<short> toPcm16(const std::vector<float> &samples);

class SphinxDecoder
{
public:
    // Senone scores are costs in the log base's units shifted right by this (SENSCR_SHIFT).
    static constexpr int kScoreShift = 10;
    // pocketsphinx's frames: 10 ms apart.
    static constexpr double kFrameSeconds = 0.01;

    // `arguments`: pocketsphinx options (name, value) after "-hmm modelDir". Throws
    // lipsync::Error naming the folder when the options or the model do not load.
    SphinxDecoder(const std::string &modelDir, const std::vector<std::pair<std::string, std::string>> &arguments);
    ~SphinxDecoder();
    SphinxDecoder(const SphinxDecoder &) = delete;
    SphinxDecoder &operator=(const SphinxDecoder &) = delete;

    // The base of the log table (1.0001): a cost c is a log-likelihood of -c * 2^kScoreShift * ln(base).
    double logBase() const;
    // The model's variance floor (-varfloor).
    float varianceFloor() const;

    struct Word
    {
        std::string word;  // the dictionary's spelling; "<s>", "</s>", "<sil>", "[NOISE]" and the
                           // like are left out
        int first = 0;     // first 10 ms frame
        int last = 0;      // last 10 ms frame, inclusive
        // The word's posterior probability in the decoder's lattice (forward-backward over
        // every path the search kept): near 1 when no other word competed for its time, low
        // where the recogniser was unsure. NaN when the decoder made no lattice.
        double confidence = std::numeric_limits<double>::quiet_NaN();
    };
    // Decodes 16 kHz `pcm` with the language model and dictionary the decoder was made with
    // (-lm, -dict), as one utterance. Throws lipsync::Error when pocketsphinx fails.
    std::vector<Word> recognize(const std::vector<short> &pcm) const;

private:
    friend class SphinxUtterance;
    friend class SphinxPhoneLoop;
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

class SphinxUtterance
{
public:
    // Computes the features of all of 16 kHz `pcm` at once (as a batch front end), every frame
    // kept. A scorer of its own per utterance: pocketsphinx's front end carries its noise
    // estimate, cepstral mean and Gaussian selection over from one utterance to the next.
    // Throws lipsync::Error (an unsupported library, audio too short for one frame).
    SphinxUtterance(const SphinxDecoder &decoder, const std::vector<short> &pcm);
    ~SphinxUtterance();
    SphinxUtterance(const SphinxUtterance &) = delete;
    SphinxUtterance &operator=(const SphinxUtterance &) = delete;

    int frames() const { return m_frames; }
    // The scores of frame t for `senones` (only those are computed; the array holds every
    // senone's slot): costs, 0 for the best senone scored.
    const short *score(int t, const std::vector<int> &senones);
    // The feature vectors of frame t, one array per stream.
    const float *const *features(int t);
    // Transforms the model's Gaussians by a speaker adaptation in pocketsphinx's MLLR text form
    // (SphinxAdaptation::pocketsphinxText); frames are scored under it from then on.
    void applyTransform(const std::string &pocketsphinxText);

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
    int m_frames = 0;
};

class SphinxPhoneLoop
{
public:
    struct Segment
    {
        std::string phone; // the model's phone: "AA" ... "ZH", "SIL", fillers such as "+NSN+"
        int first = 0;     // first 10 ms frame of the utterance
        int last = 0;      // last, inclusive
    };

    // The all-phone search of the acoustic model's context-independent phones in `modelDir` under
    // the phone language model `phoneLm` (-allphone, -allphone_ci), with further pocketsphinx
    // options. Frames keep the sound's timing:
    // no silence or noise removal. Throws lipsync::Error naming the file that does not load.
    SphinxPhoneLoop(const std::string &modelDir, const std::string &phoneLm,
                    const std::vector<std::pair<std::string, std::string>> &arguments);
    ~SphinxPhoneLoop();
    SphinxPhoneLoop(const SphinxPhoneLoop &) = delete;
    SphinxPhoneLoop &operator=(const SphinxPhoneLoop &) = delete;

    // Starts an utterance (ending one that runs); the cepstral mean carries over ("-cmn prior").
    void start();
    // Feeds 16 kHz PCM to the running utterance.
    void process(const short *pcm, size_t count);
    // Ends the utterance: its last frames are searched.
    void end();
    // Frames of the utterance searched so far.
    int frames() const;
    // The best phone path through the frames searched so far.
    std::vector<Segment> segments() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace lipsync
