#pragma once
// A long recording (a broadcast, a lecture, an hour of one speaker) brought into a project as
// utterance sequences (docs/pipeline.md, "Long recordings"): aligned to its transcript in bounded
// memory (the aligner's LongAlignment for recordings over three minutes), cut at its pauses
// (UtteranceSplit), each utterance written as a clip of its own — H.264 + AAC MP4 from a video
// (VideoExporter), 16-bit WAV from a sound-only file (WavWriter), both with the sound at the
// recording's own rate, mono — and added to the project with its words and its alignment. The
// recording's picture and sound are each read once, front to back, and every clip is written as
// soon as its sound is decoded (AudioDecoder::decodeRanges): memory for one clip, not the recording.
#include "align/Aligner.h"
#include "project/Sequence.h"
#include "project/UtteranceSplit.h"
#include "tasks/Feedback.h"

#include <optional>
#include <string>
#include <vector>

namespace lipsync {

class Lexicon;
class Project;

struct LongRecordingImportOptions
{
    UtteranceSplitOptions split;    // frameRate is the recording's own
    std::string clipFolder = "clips"; // relative to the project folder
    int crf = 18;                   // x264 quality of the video clips
};

struct LongRecordingImportResult
{
    std::vector<Sequence> sequences;      // to add to the project, in time order
    double duration = 0.0;                // seconds of audio aligned
    double spokenSeconds = 0.0;           // of it inside the utterances
    int words = 0;
    // How well the whole transcript fits the recording's sound, when the aligner measured it
    // (AlignerChoice::transcriptFit); each sequence carries it too, its words being the
    // transcript's.
    std::optional<TranscriptFit> transcriptFit;
};

// The utterances of `mediaPath` as sequences for `project` (the caller adds them) with ids
// "<stem>_0001"..., their clips written into the project's `clipFolder`. `words` are the transcript's
// (`transcriptPath` names it in errors and gives subtitle cues). Throws lipsync::Error naming the
// file for media that cannot be read, words that do not fit, a clip that cannot be written, and
// ids the project already has; Canceled on cancel. On any error the clips written so far are
// removed.
LongRecordingImportResult importLongRecording(const Project &project, const std::string &mediaPath,
                                              const std::vector<std::string> &words,
                                              const std::string &transcriptPath, const Aligner &aligner,
                                              const Lexicon &lexicon, const LongRecordingImportOptions &options = {},
                                              Feedback &feedback = Feedback::none());

} // namespace lipsync
