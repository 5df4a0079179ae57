#pragma once
// Where the aligner model shipped with the studio (resources/aligner/grid-s1.aligner, trained on
// GRID s1) is, for the CLI and the studio alike. Search order: $LIPSYNC_ALIGNER_MODEL; the
// resources folder up to five folders above the executable (a build tree inside the checkout);
// `sourceDir`/resources/aligner; <prefix>/share/lipsync/aligner beside an installed executable.
#include <string>

namespace lipsync {

// The absolute path, or "" when no model is found. Needs a QCoreApplication.
std::string shippedAlignerModelPath(const std::string &sourceDir = {});

} // namespace lipsync
