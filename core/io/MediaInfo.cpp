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
        info.frameRate = scan->frameRate;
        if (info.frameRate <= 0 && info.frameCount > 1)
            info.frameRate = (info.frameCount - 1)
                             / (scan->frameTimes.back() - scan->frameTimes.front());
        info.width = scan->width;
        info.height = scan->height;
        info.videoDuration = info.frameRate > 0 ? info.frameCount / info.frameRate : 0.0;
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
    }
    return info;
}

} // namespace lipsync
