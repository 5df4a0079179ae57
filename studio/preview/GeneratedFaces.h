#pragma once
// The faces the preview shows beside (or instead of) the recorded video: for each dynamic model
// its generated AAM parameters for a sequence's frame labels (DynamicModel::generate, the most
// likely trajectory), drawn by the AAM synthesiser (Cootes et al. 2001, eq. 5) into a frame at
// the head pose of that frame. For a recorded sequence the poses are the tracked ones, so the
// generated mouth moves in the speaker's own head; for new speech there is one neutral frame and
// pose (the first frame of a sequence, or the mean face on grey).
//
// Drawing one frame is one synthesis (about 0.25 ms for the GRID AAM) and a copy of the
// background, so the preview renders on demand on the GUI thread and keeps up with playback.
#include "aam/AamModel.h"
#include "aam/AamSynthesizer.h"
#include "project/LandmarkSet.h"

#include <QColor>
#include <QImage>
#include <QString>
#include <QVector>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace lipsync {
struct VideoTrackingResult;
}

namespace lipsync::studio {

// Head pose per frame of a recorded sequence, from tracking it with the AAM.
struct SequencePoses
{
    std::vector<Similarity> poses;   // model coordinates -> frame, one per frame
    Eigen::MatrixXd shapes;          // frames x 46: the tracked 23 points (landmarks overlay)
};

// Pose of each tracked frame: the similarity that takes the model shape of the tracked
// parameters onto the tracked points (least squares over the 23 points).
SequencePoses posesFromTracking(const AamSynthesizer &synthesizer, const VideoTrackingResult &tracking);

class GeneratedFaces
{
public:
    struct Track
    {
        QString kind;            // "dpds", ...
        QString name;            // shown above the panel
        QColor color;
        Eigen::MatrixXd params;  // frames x combined modes
    };

    GeneratedFaces(std::shared_ptr<const AamModel> aam, double frameRate);

    const AamModel &aam() const { return *m_aam; }
    const AamSynthesizer &synthesizer() const { return *m_synth; }
    double frameRate() const { return m_frameRate; }

    // Poses per frame (a recorded sequence) ...
    void setPoses(std::shared_ptr<const SequencePoses> poses) { m_poses = std::move(poses); }
    const SequencePoses *poses() const { return m_poses.get(); }
    // ... or one background and pose for every frame (new speech).
    void setNeutralFrame(const QImage &background, const Similarity &pose);
    // A neutral frame with the mean face in the middle of a grey `size` frame.
    void setMeanFaceFrame(QSize size);

    void addTrack(Track track) { m_tracks.push_back(std::move(track)); }
    const std::vector<Track> &tracks() const { return m_tracks; }
    int frameCount() const; // of the longest track

    // Track `track`'s face at `frame` drawn into `background` (the recorded frame; ignored with a
    // neutral frame). Frames past a track's end hold its last frame.
    QImage render(int track, int frame, const QImage &background = {}) const;
    // Where the generated face's 23 points are in the rendered frame.
    LandmarkSet landmarks(int track, int frame) const;
    // The tracked points of the recorded frame (empty set without poses).
    std::optional<LandmarkSet> trackedLandmarks(int frame) const;

private:
    Similarity poseAt(int frame) const;
    Eigen::VectorXd paramsAt(int track, int frame) const;

    std::shared_ptr<const AamModel> m_aam;
    std::unique_ptr<AamSynthesizer> m_synth;
    double m_frameRate;
    std::shared_ptr<const SequencePoses> m_poses;
    QImage m_neutral;
    Similarity m_neutralPose;
    std::vector<Track> m_tracks;
};

} // namespace lipsync::studio
