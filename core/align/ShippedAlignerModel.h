#pragma once
// Where the aligner model shipped with the studio (resources/aligner/grid-s1.aligner, trained on
// GRID s1) is, for the CLI and the studio alike: $LIPSYNC_ALIGNER_MODEL (another model), else
// aligner/grid-s1.aligner among the shipped resources (util/ResourceLocator).
#include <string>

namespace lipsync {

// The absolute path, or "" when no model is found.
std::string shippedAlignerModelPath();

} // namespace lipsync
