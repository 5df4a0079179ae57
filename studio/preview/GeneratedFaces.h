#pragma once
// The faces the preview shows beside (or instead of) the recorded video: for each dynamic model
// its generated AAM parameters for a sequence's frame labels (DynamicModel::generate, the most
// likely trajectory), drawn by core/render's FaceRenderer into a frame at the head pose of that
// frame. For a recorded sequence the poses are the ones tracked in its clip, so the generated
// mouth moves in the speaker's own head; for new speech every frame is drawn into one neutral
// frame (the first frame of a sequence at its pose, or the mean face on grey).
//
// Drawing one frame is one synthesis (about 0.25 ms for the GRID AAM) and a copy of the
// background, so the preview renders on demand on the GUI thread and keeps up with playback.
#include "annotation/FrameClock.h"
#include "aam/AamModel.h"
#include "annotation/LandmarkSet.h"
#include "render/FaceRenderer.h"
#include "render/PostureTransfer.h"

#include <algorithm>
#include <QVector>
#include <QColor>
#include <QImage>
#include <QString>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <vector>

namespace lipsync::studio {

class GeneratedFaces
{
public:
    struct Track
    {
        QString kind;            // "dpds", ...
        QString name;            // shown above the panel
        QColor color;
        Eigen::MatrixXd params;  // frames x combined modes
        // Drawn in the background's own posture (render/PostureTransfer); null: as generated.
        std::shared_ptr<const PostureTransfer> posture = nullptr;
    };

    // `renderer` holds the poses (tracked in a clip, or the neutral frame's); it refers to `aam`.
    // `frames`: when each generated frame is shown (the clip's own frames, or the new speech's).
    GeneratedFaces(std::shared_ptr<const AamModel> aam, std::shared_ptr<const FaceRenderer> renderer,
                   const FrameClock &frames);

    const AamModel &aam() const { return *m_aam; }
    double frameRate() const { return m_frames.rate(); }
    const FrameClock &frames() const { return m_frames; }
    // Every frame drawn into `background` at the pose of the renderer's frame `poseFrame`.
    void setFixedFrame(const QImage &background, int poseFrame);
    // Frame i drawn into `images[frames[i]]` at the pose of the renderer's frame `frames[i]`: new
    // speech in the person's own video, re-timed (render/BackgroundRetiming).
    void setRetimedBackground(std::vector<int> frames, QVector<QImage> images);

    void addTrack(Track track) { m_tracks.push_back(std::move(track)); }
    const std::vector<Track> &tracks() const { return m_tracks; }
    int frameCount() const; // of the longest track

    // Track `track`'s face at `frame` drawn into `background` (the recorded frame; ignored with a
    // fixed frame) as `options` say. Frames past a track's end hold its last frame.
    QImage render(int track, int frame, const CompositeOptions &options, const QImage &background = {}) const;
    // Where the generated face's 23 points are in the frame rendered as `options` say.
    LandmarkSet landmarks(int track, int frame, const CompositeOptions &options) const;
    // The points tracked in the recorded frame (none for new speech).
    std::optional<LandmarkSet> trackedLandmarks(int frame) const;

private:
    int poseFrame(int frame) const
    {
        if (!m_retimed.empty())
            return m_retimed[std::size_t(std::clamp(frame, 0, int(m_retimed.size()) - 1))];
        return m_fixedPose >= 0 ? m_fixedPose : frame;
    }
    Eigen::VectorXd paramsAt(int track, int frame) const;

    std::shared_ptr<const AamModel> m_aam;
    std::shared_ptr<const FaceRenderer> m_renderer;
    FrameClock m_frames;
    QImage m_fixed;
    int m_fixedPose = -1;
    std::vector<int> m_retimed;     // background frame of each frame (re-timed), or empty
    QVector<QImage> m_retimedImages;
    std::vector<Track> m_tracks;
};

} // namespace lipsync::studio
