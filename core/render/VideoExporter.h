#pragma once
// MP4 export with sound: H.264 video (libx264, yuv420p) and the original audio as AAC (FFmpeg's
// native encoder), muxed by libavformat. OpenCV's VideoWriter cannot write audio, hence FFmpeg.
//
// Timestamps: each frame is written at its presentation time on the export's FrameClock (evenly
// spaced frames in the time base 1/fps, 30000/1001 exact; a variable frame rate keeps every
// frame's own time, in units of 1/90000 s); audio pts count samples in the time base 1/sampleRate.
// Both streams start at t = 0 (the muxer's edit list hides the AAC encoder delay and the B-frame
// reorder delay), so sound and picture are aligned to the sample. The file holds exactly the
// clock's frames and lasts exactly as long as they are on screen: the sound is cut at the last
// frame's end, or continued with silence up to it.
//
// Atomic: everything is written to a temporary file in the target directory (".<name>.XXXXXX.part")
// that is renamed over the target only when the file is complete. On error, cancel or
// destruction before finish() the temporary file is removed: a half-written file never appears
// under the final name, and an existing file there is left untouched.
#include "annotation/FrameClock.h"
#include "io/AudioDecoder.h"

#include <opencv2/core.hpp>

#include <functional>
#include <memory>
#include <string>

namespace lipsync {

class Feedback;

struct VideoExportOptions
{
    // Frame rate as a fraction (25/1 for GRID, 30000/1001 for NTSC).
    int frameRateNumerator = 25;
    int frameRateDenominator = 1;
    // x264 constant rate factor (0 lossless ... 51; 18-23 look transparent) and speed preset.
    int crf = 20;
    std::string preset = "veryfast";
    // Colour at the picture's full resolution (4:4:4, H.264's High 4:4:4 profile) instead of
    // 4:2:0, which halves it and which every player decodes. With crf 0 the encode is lossless.
    bool fullChroma = false;
    // Encoder threads (0: libx264 chooses, about 1.5 per core).
    int threads = 0;
    // Bits per second of the AAC stream.
    int audioBitRate = 128000;
    // When each frame is shown (its times relative to the first frame's are written). Empty:
    // frames every 1 / frameRate() from 0, as many as are added. With a clock, exactly
    // frames.count() frames are written (more are ignored, fewer hold the last one) and the sound
    // is fitted to its duration.
    FrameClock frames;

    double frameRate() const { return double(frameRateNumerator) / frameRateDenominator; }
    // From frames per second: 25 -> 25/1, 29.97 -> 30000/1001, else in thousandths.
    void setFrameRate(double fps);
    // The clock and its rate (setFrameRate(clock.rate())).
    void setFrames(const FrameClock &clock);
};

// Streaming writer: construct (opens the temporary file), addFrame() for every frame, finish().
// Frames are BGR cv::Mat (CV_8UC3; CV_8UC1 and CV_8UC4 are converted) of one size, fixed by the
// first frame. H.264 in yuv420p needs even dimensions: an odd width or height is padded by
// repeating the last column or row (the output is then one pixel wider or taller).
class VideoExporter
{
public:
    // `audio` (mono float PCM, copied) may be null for a silent video. Its first sample plays
    // with the first frame (AudioBuffer::startTime is not applied; see alignAudioToVideo()).
    // Without options.frames, the whole sound is written.
    // Throws lipsync::Error naming `path` if the target directory does not exist or is not
    // writable, or if the audio is empty.
    explicit VideoExporter(const std::string &path, const VideoExportOptions &options = {},
                           const AudioBuffer *audio = nullptr);
    // Abandons the export (removes the temporary file) unless finish() succeeded.
    ~VideoExporter();
    VideoExporter(const VideoExporter &) = delete;
    VideoExporter &operator=(const VideoExporter &) = delete;

    // Encodes one frame. Frames beyond targetFrameCount() are ignored.
    void addFrame(const cv::Mat &frame);
    // Writes the rest of the audio, flushes the encoders, writes the index and renames the
    // temporary file to the final path. Throws lipsync::Error if no frame was added.
    void finish();
    // Stops and removes the temporary file. Safe to call more than once.
    void abandon();

    const std::string &path() const;
    // Frames the file will hold: options.frames.count(), or -1 without a clock.
    int targetFrameCount() const;
    int framesAdded() const;

private:
    struct Impl;
    std::unique_ptr<Impl> d;
};

// The sound re-timed so that its first sample plays with a video frame shown at
// `firstFrameTime` (seconds, the time base of AudioBuffer::startTime and VideoReader::timestamp):
// leading silence is added when the sound starts later, samples are dropped when it starts
// earlier. The result has startTime = firstFrameTime.
AudioBuffer alignAudioToVideo(const AudioBuffer &audio, double firstFrameTime);

// One-call export of `frameCount` frames produced by `frameAt(i)` (rendered on demand so a long
// clip never sits in memory), with progress and cancel through `feedback`. On cancel throws
// lipsync::Canceled and leaves no file at `path`. The file holds exactly `frameCount` frames, at
// options.frames' times (which must have `frameCount` frames) or every 1 / fps, and the sound
// is fitted to them. Returns the number of frames in the file.
int exportVideo(const std::string &path, int frameCount,
                 const std::function<cv::Mat(int)> &frameAt, const AudioBuffer *audio,
                 Feedback &feedback, const VideoExportOptions &options = {});

} // namespace lipsync
