#pragma once
// A long recording's alignment cut into utterances at its pauses, for importing it as sequences
// of a project (docs/pipeline.md, "Long recordings"): each utterance runs from a pause to a pause,
// at least `shortest` seconds where pauses allow and at most `longest` where words allow, holds a
// little of the silence either side (`margin`) and none of a long stretch without words.
#include "annotation/FrameClock.h"
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

struct UtteranceSplitOptions
{
    double minimumPause = 0.3; // a silence this long ends an utterance...
    double shortest = 2.0;     // ...once it has lasted this long
    double longest = 12.0;     // beyond this, the longest silence (or else a word boundary) ends it
    double margin = 0.25;      // silence kept before the first word and after the last
    FrameClock frames;         // not empty: start and end fall on these frames' boundaries
};

struct UtteranceSpan
{
    double start = 0.0; // seconds in the recording
    double end = 0.0;
    Tier words{"words", {}};   // from 0 at `start`
    Tier phones{"phones", {}};
    std::string transcript;    // its words, single-spaced
};

// `words` and `phones` tile [0, duration] (an alignment); silences are labelled as
// PhoneSet::isSilence says. Utterances without words are not returned.
std::vector<UtteranceSpan> splitAtPauses(const Tier &words, const Tier &phones, double duration,
                                         const UtteranceSplitOptions &options = {});

} // namespace lipsync
