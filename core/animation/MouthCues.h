#pragma once
// Mouth cues as Rhubarb Lip Sync writes them, so that the plug-ins and scripts that read its
// output (Blender, Godot, Spine, After Effects, OpenToonz, Moho) read ours unchanged:
//   tsv   "start<TAB>shape" lines, then a last line with the end time and X;
//   json  {"metadata": {"soundFile", "duration"}, "mouthCues": [{"start", "end", "value"}]};
//   xml   <rhubarbResult><metadata>…</metadata><mouthCues><mouthCue start end>shape</…>;
//   dat   Moho switch data: "MohoSwitch1", then "frame shape" lines (1-based frames at the
//         chosen rate, 24..100 fps; Preston Blair names by default), a last line of rest.
// Times are seconds on the sound file's timeline, to the hundredth as Rhubarb writes them.
#include "animation/MouthShape.h"

#include <string>
#include <vector>

namespace lipsync {

class MouthMapping;
struct MouthTrack;

struct MouthCue
{
    double start = 0;
    double end = 0;
    MouthShape shape = MouthShape::X;
    bool operator==(const MouthCue &) const = default;
};

struct MouthCueTrack
{
    std::string soundFile;
    double duration = 0; // seconds from 0 to the end of the last cue
    std::vector<MouthCue> cues;
};

// Every frame classified (MouthMapping::classify), a lone speech frame between two frames of one
// shape taking theirs, and runs of one shape joined into cues from the first frame's start to
// the last frame's end. Before the first frame: X.
MouthCueTrack mouthCues(const MouthTrack &track, const MouthMapping &mapping);

enum class CueFormat { Tsv, Json, Xml, Dat };
// By the file's extension (.tsv, .json, .xml, .dat); throws lipsync::Error naming the path.
CueFormat cueFormatOfPath(const std::string &path);

struct DatOptions
{
    double frameRate = 24.0;   // Rhubarb's --datFrameRate: 24..100
    bool prestonBlair = true;  // Rhubarb's --datUsePrestonBlair: MBP, etc, E, AI, O, U, FV, L, rest
};

std::string formatMouthCues(const MouthCueTrack &track, CueFormat format, const DatOptions &dat = {});
// Atomically; the format by the extension.
void writeMouthCues(const MouthCueTrack &track, const std::string &path, const DatOptions &dat = {});
// Reads any of the four back (a .dat: frames at `dat.frameRate`, letters or Preston Blair names).
// Throws lipsync::Error naming the file and the line or field at fault.
MouthCueTrack readMouthCues(const std::string &path, const DatOptions &dat = {});

} // namespace lipsync
