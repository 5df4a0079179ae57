#pragma once
// What a media file holds, as `lipsync info` and the project import report it.
//
// Damaged files, the policy all of core/io shares (MediaInfo::probe, VideoReader,
// AudioDecoder::decode): a truncated file is an error, not a shorter clip. "Truncated" means
// the file ends inside a packet: the last picture needs concealment, the last MPEG audio frame
// is shorter than its header says, a video packet yields no picture, the demuxer reports a
// packet cut short, or a container that states its length (WAV, MP4) decodes shorter. The
// error reads "<file>: truncated or damaged file: <why>". Concealed damage in the middle of a
// stream is tolerated and counted (damagedFrames); frames before a stream's first keyframe
// decode (often flat grey) and count as frames.
#include "annotation/FrameClock.h"
#include "io/AudioTimeline.h"

#include <string>

namespace lipsync {

struct MediaInfo
{
    std::string path;
    bool hasVideo = false;
    int frameCount = 0;     // decoded frame count (not the container's estimate)
    double frameRate = 0.0; // frames per second
    int width = 0;
    int height = 0;
    double videoDuration = 0.0; // seconds the frames are on screen (first frame to the last's end)
    int frameRateNum = 0, frameRateDen = 0; // the stream's rate as a fraction (30000/1001)
    FrameClock frames;      // every frame's presentation time on the media timeline
    bool variableFrameRate = false;
    bool hasAudio = false;
    int audioSampleRate = 0;
    int audioChannels = 0;
    double audioDuration = 0.0; // seconds of sound decoded (decoded samples / rate)
    double audioEndTime = 0.0;  // where the sound ends on the timeline (start offset and gaps included)
    int audioGaps = 0;          // timestamp gaps filled with silence
    double audioGapSeconds = 0.0;
    int audioOverlaps = 0;      // overlapping stretches dropped
    double audioOverlapSeconds = 0.0;
    int audioDiscontinuities = 0; // timestamp jumps past the container's end, not filled
    std::vector<AudioGap> audioGapList; // the first AudioTimeline::kMaxListed gaps and overlaps

    std::string format;     // container, libavformat's name ("mpeg", "mov,mp4,m4a,3gp,3g2,mj2", "wav")
    std::string videoCodec; // "mpeg1video", "h264", ... (empty without video)
    std::string audioCodec; // "mp2", "pcm_s16le", ... (empty without audio)
    double audioStartTime = 0.0; // first audio sample, seconds from the file start
    int damagedFrames = 0;  // video frames the decoder had to conceal (tolerated unless last)

    double videoStartTime() const { return frames.startTime(); }
    double videoEndTime() const { return frames.endTime(); }
    // Where the sound ends minus where the picture ends (negative: the sound stops first).
    double audioVideoEndDifference() const { return audioEndTime - videoEndTime(); }

    // Probes `path` with libavformat (streams, rates) and counts frames and audio samples by
    // decoding the whole file once with libavcodec (the decoder OpenCV uses too; cached per
    // file). A file without audio is fine (hasAudio = false). Throws lipsync::Error naming the
    // file for missing, empty, truncated or unsupported media.
    static MediaInfo probe(const std::string &path);
};

} // namespace lipsync
