#pragma once
// One recorded utterance of the project: a media file plus everything derived from it.
#include "annotation/FrameClock.h"
#include "annotation/LandmarkSet.h"
#include "annotation/Tier.h"
#include "project/TranscriptFit.h"

#include <Eigen/Core>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lipsync {

struct Sequence
{
    std::string id;          // unique within the project, used for file names ("bbaf2n")
    std::string mediaFile;   // relative to the project folder (or absolute)
    double frameRate = 25.0; // video frames per second (the stream's nominal rate)
    int frameCount = 0;
    // When each frame is on screen, on the media timeline (seconds from the file's start, the
    // time base of the tiers): frame 0 at firstFrameTime and then every 1 / frameRate, or, for a
    // variable frame rate, at frameTimes (frameCount entries; empty when evenly spaced).
    double firstFrameTime = 0.0;
    std::vector<double> frameTimes;
    std::string transcript;  // plain words
    // The transcript is a speech recogniser's proposal (`lipsync transcribe`, the timeline's
    // Propose Transcript) that nobody has checked: shown as unverified until it is edited or
    // accepted.
    bool transcriptProposed = false;
    // With a proposed transcript: the recogniser's posterior of each of its words (SpeechRecognizer,
    // one per word of `transcript`), for reviewing the doubtful ones first; empty otherwise.
    std::vector<double> transcriptConfidence;
    // How well the transcript fits the sound, by the alignment that made the tiers, with that
    // aligner's threshold (AlignerOutput::transcriptFit); none when it was not measured.
    std::optional<TranscriptFit> transcriptFit;

    std::map<int, LandmarkSet> landmarks; // video frame index -> 23 points
    Tier words{"words", {}};
    Tier phones{"phones", {}};
    // Per-frame face features y_t (the AAM parameters): frameCount rows x d columns; empty
    // until the AAM has been fitted. Stored beside the manifest as features/<id>.csv.
    Eigen::MatrixXd features;
    // Per-frame AAM fit error of the tracking that produced the features (the mean squared
    // normalised texture residual; kNoFace where the tracker found no face): frameCount values,
    // or empty when the sequence has not been tracked. It orders the worst-fit queue, so it is
    // saved with the project (manifest version 2, "fitErrors", null for kNoFace).
    std::vector<double> fitErrors;
    static constexpr double kNoFace = -1.0;

    // The words of a transcript (split at white space), to which transcriptConfidence
    // corresponds one to one.
    static std::vector<std::string> transcriptWords(const std::string &transcript);

    FrameClock clock() const;
    // Sets frameRate, frameCount, firstFrameTime and frameTimes from `clock`.
    void setClock(const FrameClock &clock);
    // How long the frames are on screen (first frame to the end of the last).
    double duration() const { return clock().duration(); }
    bool operator==(const Sequence &other) const;
};

} // namespace lipsync
