#pragma once
// The forced aligners behind one interface, chosen the same way everywhere an aligner is used
// (`lipsync align`, `render`, the studio's timeline and its generation from new speech):
//   - ours (MonophoneAligner): monophone HMMs trained on the speaker (`lipsync aligner train`),
//     by default the shipped GRID s1 model, ForcedAligner's Viterbi;
//   - CMU Sphinx's generic US-English triphone model (SphinxAligner), for other speakers.
// Both can adapt to the recording's speaker first, and both re-align stretches of an alignment
// while keeping the rest (Realignment).
#include "align/AlignerChoice.h"
#include "align/ForcedAligner.h"
#include "align/SpeakerAdaptation.h"
#include "audio/Mfcc.h"
#include "io/RecordingSound.h"
#include "project/TranscriptFit.h"
#include "tasks/Feedback.h"

#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

class AcousticModel;
class Lexicon;
class Realignment;

struct AlignerOutput
{
    AlignmentResult alignment;
    double duration = 0;         // seconds of audio
    MfccOptions audioFrames;     // the aligner's audio frames (voteFrameLabels)
    AdaptationReport adaptation; // ours with adaptation: log-likelihood per frame per pass
    // How well the transcript fits the sound, with the aligner's threshold (TranscriptFit), when
    // AlignerChoice::transcriptFit asked for it on a whole recording; none otherwise.
    std::optional<TranscriptFit> transcriptFit;
};

class Aligner
{
public:
    virtual ~Aligner() = default;

    // What aligns: "sphinx:DIR" or the path of our model file.
    virtual std::string name() const = 0;
    // Our acoustic model, null for CMU Sphinx's.
    virtual const AcousticModel *acousticModel() const { return nullptr; }

    // Aligns the recording of `sound` to `words`, pronounced by `lexicon`, taking its sound at
    // the aligner's rate from `sound` (resampled from the recording's own when a job decoded that
    // already). Errors name the media (and `transcriptPath`, when given, if the words do not fit
    // the audio); `feedback` gets progress and is polled for cancel (Canceled). Thread-safe.
    virtual AlignerOutput align(const RecordingSound &sound, const std::vector<std::string> &words,
                                const Lexicon &lexicon, Feedback &feedback = Feedback::none(),
                                const std::string &transcriptPath = {}) const = 0;
    // The same for the recording at `mediaPath`, decoded at the aligner's rate.
    AlignerOutput align(const std::string &mediaPath, const std::vector<std::string> &words, const Lexicon &lexicon,
                        Feedback &feedback = Feedback::none(), const std::string &transcriptPath = {}) const
    {
        return align(RecordingSound(mediaPath), words, lexicon, feedback, transcriptPath);
    }
    // Aligns the stretches of `realignment` again in the recording at `mediaPath`, everything
    // else kept. Errors as align().
    virtual AlignerOutput realign(const std::string &mediaPath, const Realignment &realignment,
                                  const Lexicon &lexicon, Feedback &feedback = Feedback::none()) const = 0;
};

// The aligner `choice` names, loaded. Throws lipsync::Error naming the model file or folder (or
// saying that no shipped model exists).
std::unique_ptr<Aligner> createAligner(const AlignerChoice &choice);

// Aligners kept for reuse by every job that asks for the same choice (a model's or CMU Sphinx's
// decoders take up to a second to load). Thread-safe.
class AlignerCache
{
public:
    // The aligner of `choice`, created on first use (createAligner's errors; a failed creation is
    // not kept, so a later call tries again).
    std::shared_ptr<const Aligner> get(const AlignerChoice &choice);
    // Whether the aligner of `choice` is loaded.
    bool holds(const AlignerChoice &choice) const;

private:
    mutable std::mutex m_mutex;
    std::map<AlignerChoice, std::shared_ptr<const Aligner>> m_aligners;
};

} // namespace lipsync
