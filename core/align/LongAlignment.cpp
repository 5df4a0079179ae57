#include "align/LongAlignment.h"

#include "align/AcousticModel.h"
#include "annotation/Tier.h"
#include "io/Transcript.h"
#include "tasks/Feedback.h"
#include "util/Error.h"
#include "util/PhoneSet.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lipsync {

namespace {

// Back pointers of one window's Viterbi at most (frames x states, 4 bytes each: 240 MB).
constexpr double kMaxWindowTrellis = 6e7;
// A pause is only an anchor this far into the window: the first words must have room to settle.
constexpr double kMinimumKeptSeconds = 5.0;
// Cue times are the subtitler's, not the speech's: words of cues starting this soon after the
// window's end may still fall inside it.
constexpr double kCueSlackSeconds = 5.0;
constexpr size_t kCueSlackWords = 10;
constexpr size_t kRateSlackWords = 20;

std::string clockTime(double seconds)
{
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", s / 3600, (s / 60) % 60, s % 60);
    return text;
}

bool isSilence(const Interval &i)
{
    return PhoneSet::isSilence(i.label);
}

// Appends `i` shifted by `offset` seconds; a silence right after a silence (the two sides of a
// window's cut) extends it.
void append(Tier &tier, Interval i, double offset)
{
    i.start += offset;
    i.end += offset;
    if (!tier.intervals.empty() && isSilence(i) && isSilence(tier.intervals.back())) {
        tier.intervals.back().end = i.end;
        return;
    }
    tier.intervals.push_back(i);
}

// Appends the part of `from` before `cut` (seconds in the window), the interval across it cut short.
void appendBefore(Tier &tier, const Tier &from, double cut, double offset)
{
    for (Interval i : from.intervals) {
        if (i.start >= cut - 1e-9)
            break;
        i.end = std::min(i.end, cut);
        append(tier, i, offset);
    }
}

// Graph states ForcedAligner will build for these words (3 per phone of every variant, 3 per
// optional silence).
double graphStates(const std::vector<std::vector<Pronunciation>> &pronunciations, size_t first, size_t count)
{
    double phones = double(count + 1);
    for (size_t w = first; w < first + count; ++w)
        for (const Pronunciation &p : pronunciations[w])
            phones += double(p.size());
    return 3.0 * phones;
}

// Where the kept part of a window ends: the middle of the last pause (a silence in the words
// tier at least `minimumPause` long) between kMinimumKeptSeconds and `keepUntil`; failing that
// the last word boundary there; failing that `keepUntil` (a window without speech).
double cutOf(const AlignmentResult &r, double keepUntil, double minimumPause, double shift)
{
    double cut = -1.0;
    for (const Interval &i : r.words.intervals) {
        if (i.end > keepUntil)
            break;
        if (isSilence(i) && i.end - i.start >= minimumPause && i.start >= kMinimumKeptSeconds)
            cut = 0.5 * (i.start + i.end);
    }
    if (cut < 0)
        for (const Interval &i : r.words.intervals)
            if (i.end <= keepUntil && i.end >= kMinimumKeptSeconds)
                cut = i.end;
    if (cut < 0)
        cut = keepUntil;
    return std::round(cut / shift) * shift;
}

size_t wordsBefore(const AlignmentResult &r, double cut)
{
    return size_t(std::count_if(r.words.intervals.begin(), r.words.intervals.end(),
                                [&](const Interval &i) { return !isSilence(i) && i.end <= cut + 1e-9; }));
}

} // namespace

AlignmentResult alignLongRecording(const AcousticModel &model, const std::vector<float> &samples,
                                   const std::vector<std::string> &words,
                                   const std::vector<std::vector<Pronunciation>> &pronunciations,
                                   const std::vector<Interval> &cues, Feedback &feedback,
                                   const LongAlignmentOptions &options)
{
    const MfccOptions &fo = model.featureOptions();
    const double shift = fo.shiftSeconds;
    const size_t hop = size_t(std::lround(shift * fo.sampleRate));
    const size_t analysis = size_t(std::lround(fo.windowSeconds * fo.sampleRate));
    const double duration = double(samples.size()) / fo.sampleRate;
    const size_t total = words.size();
    if (pronunciations.size() != total)
        throw Error("every word needs its pronunciations");

    // Words placed by the end of each cue, when the cues hold exactly the transcript's words.
    std::vector<double> cueStarts;
    std::vector<size_t> wordsThroughCue;
    for (const Interval &cue : cues) {
        cueStarts.push_back(cue.start);
        wordsThroughCue.push_back((wordsThroughCue.empty() ? 0 : wordsThroughCue.back())
                                  + parsePlainTranscript(cue.label).words.size());
    }
    const bool useCues = !wordsThroughCue.empty() && wordsThroughCue.back() == total;
    const double wordsPerSecond = duration > 0 ? double(total) / duration : 0.0;

    ForcedAligner::Options openOptions = options.aligner;
    openOptions.graph.openEnd = true;
    const ForcedAligner openAligner(model, openOptions);
    const ForcedAligner closedAligner(model, options.aligner);

    AlignmentResult out;
    size_t next = 0;       // the first word not yet placed
    long anchorFrame = 0;  // where the window starts
    double enlarge = 1.0;  // more words for a window whose path ran out of them
    for (;;) {
        const double anchor = double(anchorFrame) * shift;
        feedback.throwIfCanceled();
        feedback.setProgress(duration > 0 ? anchor / duration : 1.0);
        const bool last = duration - anchor <= options.windowSeconds + options.guardSeconds;
        size_t count = total - next;
        if (!last) {
            double wanted;
            if (useCues) {
                const double until = anchor + options.windowSeconds + kCueSlackSeconds;
                const auto endCue = std::lower_bound(cueStarts.begin(), cueStarts.end(), until);
                const size_t through = endCue == cueStarts.begin() ? 0 : wordsThroughCue[size_t(endCue - cueStarts.begin() - 1)];
                wanted = double(through > next ? through - next : 0) + kCueSlackWords;
            } else {
                wanted = 2.0 * wordsPerSecond * options.windowSeconds + kRateSlackWords;
            }
            count = std::min(count, size_t(std::ceil(wanted * enlarge)));
        }
        const size_t begin = size_t(anchorFrame) * hop;
        const size_t end = last ? samples.size()
                                : std::min(samples.size(),
                                           begin + size_t(std::lround(options.windowSeconds / shift)) * hop + analysis - hop);
        if (count == 0) {
            // No words left: the rest is silence (or noise) to the end.
            append(out.words, Interval{0.0, duration - anchor, std::string(PhoneSet::kSilenceLabel), false}, anchor);
            append(out.phones, Interval{0.0, duration - anchor, std::string(PhoneSet::kSilenceLabel), false}, anchor);
            break;
        }
        const std::string from = "from " + clockTime(anchor) + " (word " + std::to_string(next + 1) + ", \""
                                 + words[next] + "\")";
        const Eigen::MatrixXf features =
            model.features(std::vector<float>(samples.begin() + long(begin), samples.begin() + long(end)));
        if (double(features.rows()) * graphStates(pronunciations, next, count) > kMaxWindowTrellis)
            throw Error("the transcript has more words than the recording speaks: " + std::to_string(total - next)
                        + " words are left for the last " + clockTime(duration - anchor) + " " + from);
        const std::vector<std::string> windowWords(words.begin() + long(next), words.begin() + long(next + count));
        const std::vector<std::vector<Pronunciation>> windowPronunciations(
            pronunciations.begin() + long(next), pronunciations.begin() + long(next + count));
        AlignmentResult r;
        try {
            r = last ? closedAligner.align(features, windowWords, windowPronunciations, duration - anchor)
                     : openAligner.align(features, windowWords, windowPronunciations, 0.0);
        } catch (const Error &e) {
            throw Error(e.reason() + " " + from);
        }
        out.logLikelihood += r.logLikelihood;
        if (last) {
            out.frames += r.frames;
            appendBefore(out.words, r.words, INFINITY, anchor);
            appendBefore(out.phones, r.phones, INFINITY, anchor);
            break;
        }
        const double cut = cutOf(r, options.windowSeconds - options.guardSeconds, options.minimumPauseSeconds, shift);
        const size_t placed = wordsBefore(r, cut);
        if (placed == count && next + count < total) {
            // The path used up its words before the kept part ended: the speech there is faster
            // than the words given allowed for. Again with more.
            out.logLikelihood -= r.logLikelihood;
            enlarge *= 2.0;
            continue;
        }
        appendBefore(out.words, r.words, cut, anchor);
        appendBefore(out.phones, r.phones, cut, anchor);
        const long cutFrames = std::lround(cut / shift);
        out.frames += int(cutFrames);
        anchorFrame += cutFrames;
        next += placed;
        enlarge = 1.0;
    }
    feedback.setProgress(1.0);
    return out;
}

} // namespace lipsync
