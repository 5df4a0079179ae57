#pragma once
// Atomic whole-file writes for core/ (QSaveFile: temporary file + fsync + rename), so a crash
// mid-save leaves either the old or the new file, never a broken one.
#include <string>

namespace lipsync {

// Throws lipsync::Error naming the file if it cannot be written.
void writeFileAtomically(const std::string &path, const std::string &contents);
// Throws lipsync::Error naming the file if it cannot be read.
std::string readWholeFile(const std::string &path);

} // namespace lipsync
