#pragma once
// Starts the background task that decodes a sequence's audio (waveform peaks, per-frame RMS)
// and video frames (full size and thumbnails). The work only reads the media file; its result
// reaches the GUI through `apply`, which the task runner calls on the GUI thread unless the
// task was canceled or failed.
#include "context/SequenceMedia.h"

#include <QString>

#include <functional>
#include <memory>

namespace lipsync {
class Task;
class TaskRunner;
}

namespace lipsync::studio {

struct SequenceSource
{
    QString id;
    QString mediaPath; // absolute
    double frameRate = 25.0;
};

class SequenceLoader
{
public:
    static constexpr int kAudioRate = 16000;
    static constexpr int kThumbnailHeight = 40;
    // Above this many bytes of decoded frames, frames are stored downscaled to fit.
    static constexpr qint64 kFrameBudgetBytes = qint64(768) << 20;

    using Apply = std::function<void(std::shared_ptr<const SequenceMedia>)>;
    static Task *start(TaskRunner &runner, const SequenceSource &source, Apply apply);
};

} // namespace lipsync::studio
