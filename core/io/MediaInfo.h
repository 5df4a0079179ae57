#pragma once
// What a media file holds, as `lipsync info` and the project import report it.
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
    double videoDuration = 0.0; // seconds
    bool hasAudio = false;
    int audioSampleRate = 0;
    int audioChannels = 0;
    double audioDuration = 0.0; // seconds

    // Probes `path` with libavformat (streams, rates) and OpenCV (frame count by decoding).
    // Throws lipsync::Error naming the file for missing, empty, truncated or unsupported media.
    static MediaInfo probe(const std::string &path);
};

} // namespace lipsync
