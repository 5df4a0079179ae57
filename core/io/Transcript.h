#pragma once
// Word transcripts for alignment and training, from any of the formats the CLI accepts:
//   .align (GRID word timings), .lab (HTK timed labels, or MFA-style plain text),
//   .txt (plain text), .TextGrid (the "words" tier, else the first interval tier),
//   .srt and .vtt (subtitles: io/Subtitles, the cues' spoken words and their times);
//   .mlf is not a per-utterance transcript and is rejected here.
// Silence labels ("sil", "sp", "", "<sil>") are dropped from the word list.
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

struct Transcript
{
    std::vector<std::string> words;
    Tier timing{"words", {}}; // reference word timings when the file has them (.align, timed .lab, TextGrid)
    bool hasTiming() const { return !timing.intervals.empty(); }
    // Subtitles: one interval per cue (its words, its times), anchors for a long recording.
    Tier cues{"cues", {}};
    std::string text() const;
};

// Throws lipsync::Error naming the file (and line where it applies); an empty transcript is an
// error.
Transcript readTranscript(const std::string &path);
// The same from the file's bytes; the format is chosen by the extension of `path`.
Transcript parseTranscript(const std::string &bytes, const std::string &path);
// Plain text: whitespace-separated words, any line breaks.
Transcript parsePlainTranscript(const std::string &text);
// Writes plain text, one line.
void writePlainTranscript(const std::string &path, const Transcript &transcript);
// Extensions readTranscript() understands, lower case with the dot, in order of preference
// when several files share a stem.
const std::vector<std::string> &transcriptExtensions();

} // namespace lipsync
