#pragma once
// The one way to find the files LipSync Studio ships (resources/: the demo project, the GRID
// aligner model, the YuNet face detector), for the CLI, the studio, the benchmarks and the
// tests alike. Folders searched, in order:
//   $LIPSYNC_RESOURCE_DIR            a copy of resources/ (a packager's or a user's override)
//   <executable dir>/../share/lipsync
// The second is the install layout (<prefix>/bin/lipsync, <prefix>/share/lipsync) and also the
// build tree's, where CMake links <build>/share/lipsync to the source tree's resources/ — so no
// source path is compiled into a binary. Files that Debian packages install (the CMU dictionary,
// CMU Sphinx's model, dlib's predictor, OpenCV's cascades) are not resources: they keep their
// Debian paths.
#include <string>
#include <vector>

namespace lipsync {

class ResourceLocator
{
public:
    // The absolute path of `relative` (e.g. "aligner/grid-s1.aligner") in the first folder that
    // holds it, or "" if none does.
    static std::string find(const std::string &relative);
    // The folders searched, in order (for messages that say where a file was looked for).
    static std::vector<std::string> folders();
    // The folder of the running executable.
    static std::string executableFolder();
};

} // namespace lipsync
