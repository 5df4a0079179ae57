#pragma once
// The environment variables the studio and the CLI read, in this one place (tests/layout keeps it
// so). Each replaces a default file or folder, or turns on a diagnostic:
//   LIPSYNC_RESOURCE_DIR   a folder searched first for resources (ResourceLocator)
//   LIPSYNC_ALIGNER_MODEL  the aligner model used by default (shippedAlignerModelPath)
//   LIPSYNC_SPHINX_MODEL   CMU Sphinx's acoustic model folder (SphinxAligner)
//   LIPSYNC_CMUDICT        the CMU pronouncing dictionary (PronunciationDictionary::cmu)
//   LIPSYNC_YUNET_MODEL    the YuNet face detector (FaceDetector)
//   LIPSYNC_FFMPEG_LOG     set: FFmpeg's own log messages are shown
#include <string>

namespace lipsync::environment {

// The variable's value (UTF-8), empty when it is unset or empty.
std::string value(const char *name);
// Whether the variable is set at all (even to nothing).
bool isSet(const char *name);

} // namespace lipsync::environment
