#pragma once
// Everything the views show of one sequence's media, decoded off the GUI thread by
// SequenceLoader and handed to the main window in one piece (so a canceled or failed load
// leaves the views exactly as they were).
#include "annotation/FrameClock.h"
#include "audio/Spectrogram.h"
#include "audio/WaveformPeaks.h"

#include <QImage>
#include <QString>
#include <QVector>

#include <memory>

namespace lipsync::studio {

struct SequenceMedia
{
    QString sequenceId;
    QString mediaPath;
    double frameRate = 25.0;
    // When each frame is shown on the media timeline (the video's timestamps; audio only: every
    // 1 / frameRate from 0). Every frame <-> time conversion of the views goes through it.
    FrameClock clock;
    // Every video frame (downscaled only if the sequence is huge). A recording without video
    // (audioOnly) has null images at the sequence's frame rate over its sound.
    QVector<QImage> frames;
    bool audioOnly = false;
    QVector<QImage> thumbnails; // the same frames, small, for the timeline strip
    std::shared_ptr<const WaveformPeaks> peaks; // null if the file has no readable audio
    std::shared_ptr<const Spectrogram> spectrogram; // of the same audio (timeline lane), or null
    QVector<double> frameRms;   // audio RMS over each video frame's interval
    QString audioError;         // why there is no audio, if there is none

    int frameCount() const { return int(frames.size()); }
};

} // namespace lipsync::studio
