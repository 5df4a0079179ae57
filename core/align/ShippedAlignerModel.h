#pragma once
// Where the aligner model shipped with the studio (resources/aligner/grid-s1.aligner, trained on
// GRID s1) is, for the CLI and the studio alike: $LIPSYNC_ALIGNER_MODEL (another model), else
// aligner/grid-s1.aligner among the shipped resources (util/ResourceLocator).
#include <string>

namespace lipsync {

// The absolute path, or "" when no model is found.
std::string shippedAlignerModelPath();
// The phone bigram shipped beside it for live recognition (aligner/grid-s1.bigram: counted from
// the shipped model's alignments of the 400 GRID s1 clips), or "" when there is none.
std::string shippedPhoneBigramPath();

} // namespace lipsync
