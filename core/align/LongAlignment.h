#pragma once
// Forced alignment of a recording of any length in bounded memory: anchored, windowed alignment
// (after Moreno, Joerg, Van Thong & Glickman, "A recursive algorithm for the forced alignment of
// very long audio segments", ICSLP 1998, with pauses as the anchors; docs/pipeline.md, "Long
// recordings").
//
// ForcedAligner's Viterbi keeps a back pointer per frame and graph state, so one pass over an
// hour (360 000 frames x 100 000 states) cannot be held. Instead the recording is aligned a
// window at a time (a minute of audio): the window starts at an anchor (the start, or a pause
// found by the previous window) with the first word not yet placed, is given the words that
// can fall in it, and its Viterbi may end anywhere in them (UtteranceGraph::Options::openEnd).
// Only the part up to the last pause well inside the window (at least `guardSeconds` before its
// end, where the cut-off words can no longer pull the path) is kept; the middle of that pause is
// the next anchor. The last window holds the rest of the recording and must use every word left.
//
// The words a window is given follow the transcript's speaking rate over the whole recording
// (twice as many as expected, and more on a retry when the window's path used all it was given
// before the kept part ended), or the subtitle cues' times when the transcript has them (every
// word of a cue that starts before the window ends). Memory is one window's audio features and
// back pointers (about 6 000 frames x a few thousand states, under 100 MB), whatever the length.
#include "align/ForcedAligner.h"
#include "tasks/Feedback.h"

#include <string>
#include <vector>

namespace lipsync {

class AcousticModel;
struct Interval;

struct LongAlignmentOptions
{
    double windowSeconds = 60.0;
    double guardSeconds = 15.0;        // the kept part ends at least this long before the window's end
    double minimumPauseSeconds = 0.15; // a silence this long is an anchor
    ForcedAligner::Options aligner;
};

// Recordings longer than this are aligned in windows (ForcedAligner aligns shorter ones whole).
constexpr double kLongRecordingSeconds = 180.0;
// Longer ones are refused up front: their audio alone (mono float at 16 kHz) would pass 700 MB.
constexpr double kMaxRecordingSeconds = 3.0 * 3600.0;

// Aligns `samples` (mono at the model's sample rate) to `words`. `cues`, when not empty, are the
// transcript's subtitle cues (each interval's label its words, in the order of `words`); they are
// used only if their words add up to `words`. `feedback` gets progress and is polled for cancel.
// The result's logLikelihood is the sum of the windows' best paths (which overlap by the
// guard). Throws lipsync::Error when the words cannot fit the audio (naming the time and word
// from which they do not) and Canceled when canceled.
AlignmentResult alignLongRecording(const AcousticModel &model, const std::vector<float> &samples,
                                   const std::vector<std::string> &words,
                                   const std::vector<std::vector<Pronunciation>> &pronunciations,
                                   const std::vector<Interval> &cues = {}, Feedback &feedback = Feedback::none(),
                                   const LongAlignmentOptions &options = {});

} // namespace lipsync
