#pragma once
// One utterance's mouth, frame by frame, as the exports read it: when each frame is shown, its
// phone, the mouth measured on it and its 23 pose-free points. Made from tracked features (a
// project's sequence) or generated ones (SpeechToFaceResult) alike.
#include "animation/MouthMapping.h"
#include "animation/MouthMeasures.h"
#include "annotation/FrameClock.h"

#include <Eigen/Core>

#include <string>
#include <utility>
#include <vector>

namespace lipsync {

class Project;
struct Sequence;
struct SpeechToFaceResult;

struct MouthTrack
{
    FrameClock frames;
    std::vector<int> phones;            // PhoneSet index of every frame
    std::vector<MouthMeasures> measures; // one per frame
    Eigen::MatrixXd points;             // frames x 46: the 23 points in the AAM's normalised frame
    Eigen::MatrixXd features;           // frames x combined modes: the AAM parameters measured
    std::string soundFile;              // the recording the cues and controls go with
    std::string sequenceId;             // the project's sequence it was measured on (empty: generated)

    int frameCount() const { return frames.count(); }
};

// From AAM parameters (frames x combined modes) with the frames' phones.
MouthTrack makeMouthTrack(const MouthMeasurer &measurer, const Eigen::MatrixXd &features, const FrameClock &frames,
                          std::vector<int> phones, std::string soundFile);
// A project's sequence: its tracked features and its aligned phones (voted per frame). Throws
// lipsync::Error naming the sequence when it has no features (not tracked) or no phones.
MouthTrack mouthTrackOfSequence(const MouthMeasurer &measurer, const Project &project, const Sequence &sequence);
// Generated from speech: its features (lips closed on /p b m/ as rendered) and frame labels.
MouthTrack mouthTrackOfGenerated(const MouthMeasurer &measurer, const SpeechToFaceResult &result);

// Every sequence of the project with both features and phones (what MouthMapping learns from).
std::vector<MouthTrack> projectMouthTracks(const MouthMeasurer &measurer, const Project &project);
// This person's mapping: learned from projectMouthTracks (`tracks`, when given, receives them),
// the user's own shapes (Project::mouthShapes) applied. MouthMapping::learn's errors.
MouthMapping projectMouthMapping(const MouthMeasurer &measurer, const Project &project,
                                 std::vector<MouthTrack> *tracks = nullptr);
// The mapping and the track of `sequence`, measured once: the track is the one the mapping learned
// from. Errors as projectMouthMapping and mouthTrackOfSequence.
std::pair<MouthMapping, MouthTrack> projectMouthMappingAndTrack(const MouthMeasurer &measurer, const Project &project,
                                                                const Sequence &sequence);
// The frame of `tracks` whose cue features are nearest shape `shape` of `mapping`, as
// {track, frame}; {-1, -1} for no frames.
std::pair<int, int> nearestFrameOfShape(const std::vector<MouthTrack> &tracks, const MouthMapping &mapping,
                                        MouthShape shape);

} // namespace lipsync
