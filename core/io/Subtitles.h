#pragma once
// Subtitles as transcripts: SubRip (.srt) and WebVTT (.vtt) cues, their times and their words.
// What a user has for broadcast or own footage; the cue times are utterance-level anchors for
// aligning a long recording, the words its transcript.
//  - SubRip: blocks separated by blank lines, an optional number, "HH:MM:SS,mmm --> HH:MM:SS,mmm"
//    (a '.' accepted for the ',', coordinates after the times ignored), then the text lines.
//  - WebVTT: "WEBVTT" first (after an optional byte-order mark), header lines until a blank
//    line, then cues: an optional identifier, "[HH:]MM:SS.mmm --> [HH:]MM:SS.mmm [settings]",
//    the text lines; NOTE, STYLE and REGION blocks skipped.
// Cue text loses its markup (<i>, <v Speaker>, <c.class>, inline timestamps, {\an8}), HTML
// entities (&amp; &lt; &gt; &nbsp; &quot; &apos;), what is not speech ([Music], (laughs), ♪ and
// the text between two ♪) and leading dialogue dashes.
#include "annotation/Tier.h"

#include <string>
#include <vector>

namespace lipsync {

enum class SubtitleFormat { SubRip, WebVtt };

// One interval per cue with speech (label: its words, single-spaced), in time order. Throws
// lipsync::Error naming `pathForErrors` and the line for a malformed time line, an end before
// its start or a WebVTT file without its header. readTranscript() picks the format by extension.
Tier parseSubtitles(const std::string &bytes, SubtitleFormat format, const std::string &pathForErrors);

// The spoken words of one cue's text (the cleaning above), single-spaced.
std::string subtitleSpeech(const std::string &cueText);

} // namespace lipsync
