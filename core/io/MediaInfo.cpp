#include "io/MediaInfo.h"

#include "io/LibAv.h"

namespace lipsync {

MediaInfo MediaInfo::probe(const std::string &path)
{
    const auto scan = libav::scanMedia(path);
    MediaInfo info;
    info.path = path;
    info.format = scan->formatName;
    info.hasVideo = scan->videoStream >= 0;
    if (info.hasVideo) {
        info.videoCodec = scan->videoCodec;
        info.frameCount = int(scan->frameTimes.size());
        info.frames = scan->frames;
        info.frameRate = info.frames.rate();
        info.frameRateNum = scan->frameRateNum;
        info.frameRateDen = scan->frameRateDen;
        info.variableFrameRate = info.frames.isVariable();
        info.width = scan->width;
        info.height = scan->height;
        info.videoDuration = info.frames.duration();
        info.damagedFrames = scan->damagedFrames;
    }
    info.hasAudio = scan->audioStream >= 0;
    if (info.hasAudio) {
        info.audioCodec = scan->audioCodec;
        info.audioSampleRate = scan->audioSampleRate;
        info.audioChannels = scan->audioChannels;
        info.audioDuration = scan->audioSampleRate > 0
                                 ? double(scan->audioSamples) / scan->audioSampleRate
                                 : 0.0;
        info.audioStartTime = scan->audioStartTime;
        info.audioEndTime = scan->audioEndTime;
        const AudioTimeline &t = scan->audioTimeline;
        info.audioGaps = t.gapCount();
        info.audioGapSeconds = t.gapSeconds();
        info.audioOverlaps = t.overlapCount();
        info.audioOverlapSeconds = t.overlapSeconds();
        info.audioDiscontinuities = t.discontinuities();
        info.audioGapList = t.gaps();
    }
    return info;
}

} // namespace lipsync
